// picFieldMap: the map of a particle field holds each particle's value at its position. Checked
// on a geostatic start, where every particle's stress is known in closed form (eqs. 3.3.1-3.3.4).
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <cmath>

using namespace gpic;
using namespace gpic::test;

namespace {

std::vector<std::vector<double>> readNumbersCsv(const fs::path& file)
{
    std::ifstream in(file);
    EXPECT_TRUE(in.good()) << "cannot read " << file;
    std::vector<std::vector<double>> rows;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
        rows.push_back(row);
    }
    return rows;
}

fs::path geostaticCase(const fs::path& dir)
{
    writeDictionary(dir / "system/controlDict", "endTime 1; deltaT 1e-4; writeControl timeStep; writeInterval 100;\n");
    writeDictionary(dir / "constant/grid", "origin (0 0); cellSize 0.01; nCells (10 6);\n"
                                 "boundaries { left { type slip; } right { type slip; } bottom { type fixed; } top { type free; } }\n");
    writeDictionary(dir / "constant/materials", "soil { type linearElastic; rho 2000; E 1e7; nu 0.25; }\n");
    writeDictionary(dir / "constant/bodies", "soil { material soil; shape { type rectangle; min (0 0); max (0.1 0.05); }\n"
                                   "       particlesPerCell 2; initialStress { type geostatic; K0 0.5; } }\n");
    writeDictionary(dir / "constant/g", "value (0 -9.81);\n");
    return dir;
}

} // namespace

TEST(FieldMap, aStressComponentIsMappedAtEachParticle)
{
    ScratchDir scratch("fieldMap");
    const fs::path dir = geostaticCase(scratch.path() / "case");
    ASSERT_EQ(runApplication("picInit", dir).exitCode, 0);
    for (const auto& [field, factor] : {std::pair<std::string, double>{"stress:yy", 1.0}, {"stress:xx", 0.5}}) {
        const AppResult r = runApplication("picFieldMap", dir, "-field " + field + " -time 0");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::string stem = field;
        stem[stem.find(':')] = '_';
        const auto rows = readNumbersCsv(dir / "postProcessing/picFieldMap/0" / (stem + ".csv"));
        ASSERT_EQ(rows.size(), 200u) << "10 x 5 cells of 2 x 2 particles";
        for (const auto& row : rows) {
            // sigma22 = -rho g (surface - y), sigma11 = K0 sigma22 with K0 = 0.5.
            const double expected = -factor * 2000 * 9.81 * (0.05 - row[1]);
            EXPECT_NEAR(row[2], expected, 1e-9 * 2000 * 9.81 * 0.05) << field << " at (" << row[0] << " " << row[1] << ")";
        }
        EXPECT_GT(fs::file_size(dir / "postProcessing/picFieldMap/0" / (stem + ".png")), 1000u);
    }
}

TEST(FieldMap, anUnknownArrayOrComponentListsTheValidChoices)
{
    ScratchDir scratch("fieldMapBad");
    const fs::path dir = geostaticCase(scratch.path() / "case");
    ASSERT_EQ(runApplication("picInit", dir).exitCode, 0);
    AppResult r = runApplication("picFieldMap", dir, "-field stres");
    EXPECT_EQ(r.exitCode, 1);
    ASSERT_EQ(r.errorLines.size(), 1u) << r.err;
    EXPECT_NE(r.errorLines[0].find("particles.vtp"), std::string::npos) << r.err;
    EXPECT_NE(r.errorLines[0].find("valid choices"), std::string::npos) << r.err;
    EXPECT_NE(r.errorLines[0].find("stress"), std::string::npos) << r.err;
    r = runApplication("picFieldMap", dir, "-field stress:qq");
    EXPECT_EQ(r.exitCode, 1);
    ASSERT_EQ(r.errorLines.size(), 1u) << r.err;
    EXPECT_NE(r.errorLines[0].find("xy"), std::string::npos) << r.err;
    r = runApplication("picFieldMap", dir, "-field stress:xx -range 1 0");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("-range"), std::string::npos) << r.err;
}

TEST(FreeSurface, theSurfaceOfASlopedFillFollowsItsTopWithinAParticle)
{
    // A fill whose top falls linearly from 50 mm at x1 = 0 to 20 mm at x1 = 0.1 m, filled
    // with particles whose centres lie inside it: each column's surface (the top of its
    // highest particle) lies within half a particle (2.5 mm, plus the slope over half a
    // column) of the line.
    ScratchDir scratch("freeSurface");
    const fs::path dir = geostaticCase(scratch.path() / "case");
    writeDictionary(dir / "constant/bodies", "soil { material soil; shape { type polygon; points ((0 0) (0.1 0) (0.1 0.02) (0 0.05)); }\n"
                                   "       particlesPerCell 2; }\n");
    ASSERT_EQ(runApplication("picInit", dir).exitCode, 0);
    const AppResult r = runApplication("picFreeSurface", dir, "-time 0");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = readNumbersCsv(dir / "postProcessing/picFreeSurface/surface.csv");
    ASSERT_EQ(rows.size(), 20u) << "20 columns of one particle width (5 mm)";
    for (const auto& row : rows) {
        const double line = 0.05 - 0.3 * row[1];  // the top at the column centre
        EXPECT_NEAR(row[2], line, 0.0025 + 0.3 * 0.0025 + 1e-12) << "x1 = " << row[1];
    }
    EXPECT_GT(fs::file_size(dir / "postProcessing/picFreeSurface/surface.png"), 1000u);
}
