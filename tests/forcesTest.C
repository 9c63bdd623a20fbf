// The forces function object (force and moment of the material on rigid bodies) and the
// picForces utility (CSV, PNG, window means, stress along a tool face, errors).
// Physics: an elastic block resting on a fixed plate in a smooth box, damped to rest, loads
// the plate with exactly its weight W = rho g A, and the resultant acts through the block's
// centre line: about CofR its moment is (x_c - CofR_x) F_y.
#include "grid/Grid.H"
#include "io/GridVtk.H"
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <cmath>
#include <cstdio>

using namespace gpic;
using namespace gpic::test;

namespace {

const double g = 9.81;

//- A steel plate (fixed) under an elastic block of density rho: plate x in [0, 1], y in
//  [0, 0.2]; block x in [x0, x1], y in [0.2, 0.2 + H]. Damped to rest by t = endTime.
fs::path writeBlockOnPlate(const ScratchDir& scratch, double x0, double x1, double H, const std::string& forcesEntry,
                           double endTime = 2.0)
{
    const fs::path dir = scratch.path() / "blockOnPlate";
    fs::create_directories(dir / "system");
    fs::create_directories(dir / "constant");
    std::ofstream(dir / "system/controlDict")
        << "endTime " << endTime << ";\ndeltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\n"
        << "writeControl adjustableRunTime;\nwriteInterval " << endTime << ";\ndamping 0.7;\nwriteGrid yes;\n"
        << "functions { " << forcesEntry << " }\n";
    std::ofstream(dir / "constant/grid")
        << "origin (0 0);\ncellSize 0.1;\nnCells (10 8);\n"
        << "boundaries { left { type slip; } right { type slip; } bottom { type fixed; } top { type free; } }\n";
    std::ofstream(dir / "constant/materials")
        << "heavy { type linearElastic; rho 2000; E 2e6; nu 0.3; }\n"
        << "steel { type linearElastic; rho 7850; E 2e11; nu 0.3; }\n";
    std::ofstream(dir / "constant/bodies")
        << "plate { material steel; particlesPerCell 2; shape { type rectangle; min (0 0); max (1 0.2); } }\n"
        << "block { material heavy; particlesPerCell 2; shape { type rectangle; min (" << x0 << " 0.2); max (" << x1
        << ' ' << 0.2 + H << "); } }\n";
    std::ofstream(dir / "constant/g") << "value (0 " << -g << ");\n";
    std::ofstream(dir / "constant/rigidBodies") << "plate { type fixed; }\n";
    return dir;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

//- Rows of a CSV file (header first), split at commas.
std::vector<std::vector<std::string>> readCsv(const fs::path& file)
{
    std::ifstream in(file);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::stringstream s(line);
        for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
        rows.push_back(cells);
    }
    return rows;
}

} // namespace

TEST(Forces, aFixedPlateUnderAnElasticBlockCarriesItsWeight)
{
    ScratchDir scratch("forcesWeight");
    const double H = 0.5, rho = 2000, W = rho * g * 1.0 * H;  // 9810 N/m
    const fs::path dir = writeBlockOnPlate(scratch, 0.0, 1.0, H, "forces { type forces; writeInterval 10; }");
    runCase(dir);
    auto c = readColumns(dir / "postProcessing/forces/0/forces.dat");
    ASSERT_GT(c["time"].size(), 10u);
    // The material presses the plate down with W; smooth walls carry none of it.
    EXPECT_NEAR(c["plate:Fy"].back(), -W, 0.01 * W);
    EXPECT_NEAR(c["plate:Fx"].back(), 0.0, 1e-6 * W);
    EXPECT_EQ(c["plate:dx"].back(), 0.0);  // fixed
    EXPECT_EQ(c["plate:dy"].back(), 0.0);
    EXPECT_EQ(c.count("block:Fy"), 0u);    // only rigid bodies by default
}

TEST(Forces, theMomentOfAnOffCentreLoadIsTakenAboutCofR)
{
    // A 0.4 m wide block centred at x = 0.7 m: F_y = -W, and about CofR = (0.2, 0.2) the
    // moment is (0.7 - 0.2) F_y = -0.5 W (clockwise); about its own centre line, none.
    ScratchDir scratch("forcesMoment");
    const double H = 0.4, rho = 2000, W = rho * g * 0.4 * H;
    const fs::path dir = writeBlockOnPlate(scratch, 0.5, 0.9, H,
                                           "offCentre { type forces; bodies (plate); CofR (0.2 0.2); writeInterval 10; }\n"
                                           "centred { type forces; CofR (0.7 0); writeInterval 10; }");
    runCase(dir);
    auto a = readColumns(dir / "postProcessing/offCentre/0/forces.dat");
    auto b = readColumns(dir / "postProcessing/centred/0/forces.dat");
    EXPECT_NEAR(a["plate:Fy"].back(), -W, 0.01 * W);
    EXPECT_NEAR(a["plate:Mz"].back(), -0.5 * W, 0.01 * 0.5 * W);
    // About (0.7, 0): the vertical load has no arm; 1 % of W times the 0.5 m arm above.
    EXPECT_NEAR(b["plate:Mz"].back(), 0.0, 0.01 * 0.5 * W);
    EXPECT_EQ(a["plate:Fy"].back(), b["plate:Fy"].back());
}

TEST(Forces, aFaceCarriesTheLoadOfTheMaterialAlongItOnly)
{
    // The 0.4 m block on x in [0.5, 0.9]: the plate's top face under it carries the block's
    // weight W, the same face over [0, 0.4] (bare plate, a cell from the block) carries none,
    // and the face cut at the block's middle carries about half (the node on the cut counts
    // for both halves: a sixth of W between them, the block's edge nodes an eighth of W each).
    ScratchDir scratch("forcesFaces");
    const double H = 0.4, rho = 2000, W = rho * g * 0.4 * H;
    const fs::path dir = writeBlockOnPlate(
        scratch, 0.5, 0.9, H,
        "forces { type forces; bodies (plate); writeInterval 10; faces {"
        " under { body plate; from (1 0.2); to (0 0.2); }"
        " bare  { body plate; from (0.4 0.2); to (0 0.2); }"
        " right { body plate; from (1 0.2); to (0.7 0.2); }"
        " left  { body plate; from (0.7 0.2); to (0 0.2); } } }");
    runCase(dir);
    auto c = readColumns(dir / "postProcessing/forces/0/forces.dat");
    EXPECT_NEAR(c["under:Fy"].back(), -W, 0.01 * W);
    EXPECT_NEAR(c["under:Fy"].back(), c["plate:Fy"].back(), 1e-9 * W);  // every contact node lies along it
    EXPECT_NEAR(c["bare:Fy"].back(), 0.0, 1e-9 * W);
    EXPECT_NEAR(c["bare:Fx"].back(), 0.0, 1e-9 * W);
    EXPECT_NEAR(c["left:Fy"].back(), c["right:Fy"].back(), 0.05 * W);  // symmetric about x = 0.7
    EXPECT_LT(c["left:Fy"].back() + c["right:Fy"].back(), -1.05 * W);  // the cut node in both
}

TEST(Forces, badBodiesAreNamedWithTheValidChoices)
{
    ScratchDir scratch("forcesBad");
    // The forces entry of a short run must stop it with an error holding every part.
    const auto expectError = [&](const std::string& entry, const std::vector<std::string>& parts) {
        try {
            runCase(writeBlockOnPlate(scratch, 0.0, 1.0, 0.5, entry, 0.01));
            ADD_FAILURE() << "no error for " << entry;
        } catch (const InputError& e) {
            for (const auto& part : parts) EXPECT_TRUE(contains(e.what(), part)) << e.what();
        }
    };
    expectError("forces { type forces; bodies (plat); }",
                {"system/controlDict:", "'plat' is not a body; valid choices: plate, block"});
    expectError("forces { type forces; bodies (block); }", {"'block' is not a rigid body", "valid choices: plate"});
    expectError("forces { type forces; faces { top { body block; from (1 0.2); to (0 0.2); } } }",
                {"face 'top': 'block' is not a rigid body; valid choices: plate"});
    expectError("forces { type forces; faces { top { body plate; from (1 0.2); to (1 0.2); } } }",
                {"system/controlDict:", "face 'top' has no length"});
}

// ---------------------------------------------------------------- picForces

namespace {

//- A hand-made forces.dat: Fx = 2 t, Fy = -3, Mz = t^2, d = (0, -t), t = 0, 0.1, ..., 1.
void writeForcesDat(const fs::path& file)
{
    fs::create_directories(file.parent_path());
    std::ofstream out(file);
    out << "# force of the material on each body\n# time blade:Fx blade:Fy blade:Mz blade:dx blade:dy\n";
    for (int k = 0; k <= 10; ++k) {
        const double t = 0.1 * k;
        out << t << ' ' << 2 * t << " -3 " << t * t << " 0 " << -t << '\n';
    }
}

} // namespace

TEST(PicForces, writesTheCsvThePlotAndTheMeanOverAWindow)
{
    ScratchDir scratch("picForces");
    const fs::path dir = scratch.path() / "case";
    writeForcesDat(dir / "postProcessing/forces/0/forces.dat");
    // A later start (a restart) is the one read by default.
    writeForcesDat(dir / "postProcessing/forces/0.5/forces.dat");
    std::ofstream(dir / "postProcessing/forces/0.5/forces.dat", std::ios::app) << "1.1 2.2 -3 1.21 0 -1.1\n";

    const AppResult r = runApplication("picForces", dir, "-window 0.2 0.6");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "Read 12 samples from")) << r.out;
    EXPECT_TRUE(contains(r.out, "postProcessing/forces/0.5/forces.dat")) << r.out;
    const auto csv = readCsv(dir / "postProcessing/picForces/forces.csv");
    ASSERT_EQ(csv.size(), 13u);
    EXPECT_EQ(csv[0], (std::vector<std::string>{"time", "blade:Fx", "blade:Fy", "blade:Mz", "blade:dx", "blade:dy"}));
    EXPECT_DOUBLE_EQ(std::stod(csv[4][1]), 0.6);
    EXPECT_GT(fs::file_size(dir / "postProcessing/picForces/forces.png"), 1000u);
    // Time averages over [0.2, 0.6] by the trapezoidal rule: 2t -> 0.8 and -3 exactly.
    double Fx = 0, Fy = 0, Mz = 0;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
        std::sscanf(line.c_str(), " blade:Fx %lf", &Fx);
        std::sscanf(line.c_str(), " blade:Fy %lf", &Fy);
        std::sscanf(line.c_str(), " blade:Mz %lf", &Mz);
    }
    EXPECT_TRUE(contains(r.out, "Mean over 0.2 <= t <= 0.6 s (5 samples, trapezoidal)")) << r.out;
    EXPECT_NEAR(Fx, 0.8, 1e-9);
    EXPECT_NEAR(Fy, -3.0, 1e-12);
    // t^2: the trapezoids over the five samples, divided by the 0.4 s window.
    const double trapezoid = 0.1 * (0.5 * 0.04 + 0.09 + 0.16 + 0.25 + 0.5 * 0.36) / 0.4;
    EXPECT_NEAR(Mz, trapezoid, 1e-9);

    // Against displacement.
    const AppResult d = runApplication("picForces", dir, "-x displacement -file " +
                                                            (dir / "postProcessing/forces/0/forces.dat").string());
    ASSERT_EQ(d.exitCode, 0) << d.err;
    EXPECT_TRUE(contains(d.out, "Read 11 samples")) << d.out;
    EXPECT_GT(fs::file_size(dir / "postProcessing/picForces/forces.png"), 1000u);
}

TEST(PicForces, badInputGivesOneLineAndExitCodeOne)
{
    ScratchDir scratch("picForcesBad");
    const fs::path dir = scratch.path() / "case";
    fs::create_directories(dir);
    const auto oneLineError = [&](const std::string& args, const std::string& expected) {
        const AppResult r = runApplication("picForces", dir, args);
        EXPECT_FALSE(r.signalled) << args;
        EXPECT_EQ(r.exitCode, 1) << args << ": " << r.err;
        ASSERT_EQ(r.errorLines.size(), 1u) << args << ": " << r.err;
        EXPECT_TRUE(contains(r.errorLines[0], expected)) << args << ": " << r.errorLines[0];
    };
    oneLineError("", "add a forces function object to system/controlDict");
    writeForcesDat(dir / "postProcessing/forces/0/forces.dat");
    oneLineError("-x distance", "-x: 'distance' is not valid; valid choices: time, displacement");
    oneLineError("-source probes", "valid choices: forces, grid");
    oneLineError("-window 0.6 0.2", "-window: expected two times t0 < t1");
    oneLineError("-window 5 6", "no sample in the window");
    oneLineError("-surface \"(0 0) (1 1)\"", "-surface needs -time");
    oneLineError("-surface \"(0 0) 1 1\" -time 0", "-surface: expected \"(x0 y0) (x1 y1)\"");
    oneLineError("-time 0", "-time selects the time directory for -surface");
    oneLineError("-source grid", "no time directory has a grid.vti");
    oneLineError("-file nowhere.dat", "nowhere.dat: cannot open file");
    std::ofstream(dir / "broken.dat") << "# time a:Fx\n0 1\n0.1 x\n";
    oneLineError("-file " + (dir / "broken.dat").string(), "broken.dat:3: 'x' is not a number");
    std::ofstream(dir / "short.dat") << "# time a:Fx a:Fy\n0 1\n";
    oneLineError("-file " + (dir / "short.dat").string(), "short.dat:2: row has 2 values, the header names 3 columns");
}

TEST(PicForces, theStressAlongAFaceIsTheNodalForceOverItsTributaryLength)
{
    // A hand-made grid.vti: a blade face x = 0.3, y in [0, 0.4] (h = 0.1, five nodes), the
    // material to its right (+x) pressing with p = 2 kPa and dragging it up with tau = 500 Pa:
    // nodal forces -p h (end nodes half), tau h. A node inside the blade (x = 0.2) and one
    // deep in the material (x = 0.5) must be left out.
    ScratchDir scratch("surfaceSynthetic");
    const fs::path dir = scratch.path() / "case";
    fs::create_directories(dir / "0.5");
    Grid<2> grid(Vector2::Zero(), Vector2(0.1, 0.1), 8, 6);
    grid.fContact.assign(static_cast<std::size_t>(grid.nNodes()), Vector2::Zero());
    const double h = 0.1, p = 2000, tau = 500;
    for (int j = 0; j <= 4; ++j) {
        const double share = (j == 0 || j == 4) ? 0.5 : 1.0;
        grid.fContact[grid.node(3, j)] = share * h * Vector2(-p, tau);
        grid.fContact[grid.node(2, j)] = Vector2(50, 30);
        grid.fContact[grid.node(5, j)] = Vector2(50, 30);
    }
    writeGrid((dir / "0.5/grid.vti").string(), grid, 0.5);
    const AppResult r = runApplication("picForces", dir, "-surface \"(0.3 0) (0.3 0.4)\" -time 0.5");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto csv = readCsv(dir / "postProcessing/picForces/surface_0.5.csv");
    ASSERT_EQ(csv.size(), 6u);
    EXPECT_EQ(csv[0], (std::vector<std::string>{"s", "x", "y", "length", "Fn", "Ft", "normalStress", "shearStress"}));
    for (std::size_t k = 1; k < csv.size(); ++k) {
        EXPECT_NEAR(std::stod(csv[k][0]), 0.1 * double(k - 1), 1e-12);
        EXPECT_NEAR(std::stod(csv[k][6]), p, 1e-9 * p) << "station " << k;
        EXPECT_NEAR(std::stod(csv[k][7]), tau, 1e-9 * p) << "station " << k;
    }
    EXPECT_GT(fs::file_size(dir / "postProcessing/picForces/surface_0.5.png"), 1000u);
    EXPECT_TRUE(contains(r.out, "mean normal stress 2000 Pa, shear stress 500 Pa")) << r.out;
    // The same face listed the other way round puts the material on its left: a warning.
    const AppResult w = runApplication("picForces", dir, "-surface \"(0.3 0.4) (0.3 0)\" -time 0.5");
    EXPECT_EQ(w.exitCode, 0);
    ASSERT_EQ(w.warningLines.size(), 1u) << w.err;
    EXPECT_TRUE(contains(w.warningLines[0], "List the ends counter-clockwise around the body")) << w.err;
    // No contact force along a face: an error.
    const AppResult e = runApplication("picForces", dir, "-surface \"(0.7 0) (0.7 0.4)\" -time 0.5");
    EXPECT_EQ(e.exitCode, 1);
    EXPECT_TRUE(contains(e.err, "no node with a contact force along (0.7 0) -> (0.7 0.4)")) << e.err;
}

TEST(PicForces, theStressUnderABlockIsItsWeightPerAreaAndGridSumsMatchTheFunctionObject)
{
    // The block's weight spread over the plate's top face (y = 0.2; the material above, so
    // the face runs from x = 1 to x = 0): sigma_n = rho g H on average. From grid.vti the
    // summed contact force of the last step equals the function object's.
    ScratchDir scratch("surfaceRun");
    const double H = 0.5, rho = 2000;
    const fs::path dir = writeBlockOnPlate(scratch, 0.0, 1.0, H, "forces { type forces; writeInterval 1; }");
    runCase(dir);
    const AppResult r = runApplication("picForces", dir, "-surface \"(1 0.2) (0 0.2)\" -time 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    double meanNormal = 0;
    const auto at = r.out.find("mean normal stress ");
    ASSERT_NE(at, std::string::npos) << r.out;
    meanNormal = std::stod(r.out.substr(at + 19));
    EXPECT_NEAR(meanNormal, rho * g * H, 0.01 * rho * g * H);

    const AppResult s = runApplication("picForces", dir, "-source grid -CofR \"(0.5 0)\"");
    ASSERT_EQ(s.exitCode, 0) << s.err;
    auto c = readColumns(dir / "postProcessing/forces/0/forces.dat");
    const auto csv = readCsv(dir / "postProcessing/picForces/forces.csv");
    ASSERT_GE(csv.size(), 2u);
    EXPECT_EQ(csv[0], (std::vector<std::string>{"time", "all:Fx", "all:Fy", "all:Mz"}));
    EXPECT_EQ(csv.back()[0], "2");
    EXPECT_NEAR(std::stod(csv.back()[2]), c["plate:Fy"].back(), 1e-9 * rho * g * H);
    // About (0.5, 0), the plate's centre line: a symmetric load has no moment.
    EXPECT_NEAR(std::stod(csv.back()[3]), 0.0, 1e-6 * rho * g * H);
}
