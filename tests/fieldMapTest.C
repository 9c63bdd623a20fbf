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
    r = runApplication("picFieldMap", dir, "-field stress:xx -slice x3 0.01");  // a plane case is mapped whole
    EXPECT_EQ(r.exitCode, 1);
    ASSERT_EQ(r.errorLines.size(), 1u) << r.err;
    EXPECT_NE(r.errorLines[0].find("-slice is for a 3D case"), std::string::npos) << r.err;
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

TEST(DisplacementRatio, aFreelyFallingBlockBesideAMovingToolHasTheRatioOfTheirPaths)
{
    // A block falls freely from rest while a rigid tool, far from it, moves sideways at
    // 0.1 m/s. Over the first 0.02 s (200 steps of 1e-4 s) the block drops g dt^2 n (n + 1)/2
    // (symplectic Euler, exact in MPM) = 1.9718 mm and the tool moves 2 mm: PDR = 0.98589 for
    // every particle of the block.
    ScratchDir scratch("displacementRatio");
    const fs::path dir = scratch.path() / "case";
    writeDictionary(dir / "system/controlDict", "endTime 0.02; deltaT 1e-4; writeControl timeStep; writeInterval 200;\n");
    writeDictionary(dir / "constant/grid", "origin (0 0); cellSize 0.01; nCells (20 10);\n"
                                 "boundaries { left { type slip; } right { type slip; } bottom { type fixed; } top { type free; } }\n");
    writeDictionary(dir / "constant/materials", "soil { type linearElastic; rho 2000; E 1e7; nu 0.25; }\n"
                                       "steel { type linearElastic; rho 7850; E 2e11; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies", "block { material soil; shape { type rectangle; min (0.02 0.05); max (0.06 0.08); } particlesPerCell 2; }\n"
                                   "tool { material steel; shape { type rectangle; min (0.14 0.02); max (0.16 0.08); } particlesPerCell 2; }\n");
    writeDictionary(dir / "constant/rigidBodies", "tool { type prescribedVelocity; velocity (0.1 0); }\n");
    // MUSL: USL lets a soft block in free fall grow round-off at the cell crossing (doc/stability.md).
    writeDictionary(dir / "system/mpmSchemes", "updateScheme MUSL;\n");
    writeDictionary(dir / "constant/g", "value (0 -9.81);\n");
    ASSERT_EQ(runApplication("picInit", dir).exitCode, 0);
    const AppResult run = runApplication("picSolver", dir);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const AppResult r = runApplication("picDisplacementRatio", dir, "-from 0 -to 0.02 -tool tool");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = readNumbersCsv(dir / "postProcessing/picDisplacementRatio/0-0.02/pdr.csv");
    ASSERT_EQ(rows.size(), 48u) << "the block's 4 x 3 cells of 2 x 2 particles";
    const double drop = 9.81 * 1e-8 * 200 * 201 / 2;
    for (const auto& row : rows) EXPECT_NEAR(row[2], drop / 0.002, 1e-9) << "at (" << row[0] << " " << row[1] << ")";
    EXPECT_GT(fs::file_size(dir / "postProcessing/picDisplacementRatio/0-0.02/pdr.png"), 1000u);

    const AppResult bad = runApplication("picDisplacementRatio", dir, "-from 0 -to 0.02 -tool blade");
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("valid choices: block, tool"), std::string::npos) << bad.err;
}
