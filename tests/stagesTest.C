// A run in stages (system/controlDict `stages`): the layer-by-layer fill of seed 3.3.3, the
// excavation of 5.3.4, a silo's gate (4.6), a tool moved after the fill (4.7, 6.2.5), their
// end conditions, a restart inside a stage, and the errors of bad stage input.
//
// The elastic column: plane strain, between smooth (slip) walls on a fixed base, so at rest
//     sigma22 = -rho g (H - x2),   sigma11 = K0 sigma22,   K0 = nu / (1 - nu)   (eqs. 3.3.1-3.3.2)
// whatever the history of loading, as long as it stays elastic and laterally confined.
#include "core/error.H"
#include "stages/EndCondition.H"
#include "io/ParticlesVtk.H"
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace gpic::test;

namespace {

const double rho = 2000, g = 9.81, nu = 0.3, K0 = nu / (1 - nu);

//- A column 0.4 m wide of height H in a grid 0.4 x 1.2 m (cells of 0.1 m), `initialStress`
//  in the body (may be empty), the given stages, and `extra` controlDict lines.
void writeColumn(const fs::path& dir, double H, const std::string& stages, const std::string& initialStress = "",
                 const std::string& extra = "")
{
    writeDictionary(dir / "system/controlDict",
                    "deltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\nwriteControl adjustableRunTime;\n"
                    "writeInterval 0.0625;\n" + extra + "stages\n{\n" + stages + "}\n");
    writeDictionary(dir / "constant/grid", "origin (0 0);\ncellSize 0.1;\nnCells (4 12);\n"
                                           "boundaries { left { type slip; } right { type slip; } "
                                           "bottom { type fixed; } top { type free; } }\n");
    writeDictionary(dir / "constant/materials",
                    "soil { type linearElastic; rho " + std::to_string(rho) + "; E 5e7; nu " + std::to_string(nu) + "; }\n");
    writeDictionary(dir / "constant/g", "value (0 -9.81);\n");
    writeDictionary(dir / "constant/bodies", "soil { material soil; particlesPerCell 2; shape { type rectangle; "
                                             "min (0 0); max (0.4 " + std::to_string(H) + "); } " +
                                                 initialStress + " }\n");
}

gpic::Particles<2> readState(const fs::path& dir, const std::string& name)
{
    gpic::Particles<2> p;
    double t = 0;
    gpic::readParticles((dir / name / "particles.vtp").string(), p, t);
    return p;
}

//- Largest |sigma22 + rho g (H - x2)| and |sigma11 - K0 sigma22| over the particles below
//  `depthFrom` from the top, as fractions of rho g H.
std::pair<double, double> stressErrors(const gpic::Particles<2>& p, double H, double depthFrom = 0)
{
    double e22 = 0, e11 = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const double s22 = -rho * g * (H - p.x0[q].y());
        e22 = std::max(e22, std::abs(p.sigma[q][gpic::YY] - s22));
        if (H - p.x0[q].y() >= depthFrom) e11 = std::max(e11, std::abs(p.sigma[q][gpic::XX] - K0 * p.sigma[q][gpic::YY]));
    }
    return {e22 / (rho * g * H), e11 / (rho * g * H)};
}

const std::string fillStage =
    "    fill { type geostaticFill; bodies (soil); phi 30; until { equilibrium 1e-5; maxTime 1; } }\n";

} // namespace

TEST(Stages, geostaticFillLayerByLayerGivesTheConfinedElasticState)
{
    // Ten layers of one cell row each enter with Jaky's K0 = 0.5 (eq. 3.3.3) and settle with
    // alpha = 0.8 to |v|max <= 1e-5 m/s. The weight of the layers above reaches every layer
    // through the elastic response, so at the end sigma22 = -rho g (H - x2) within 2 % of
    // rho g H at the base, and sigma11 / sigma22 is the elastic nu / (1 - nu) = 0.43, not
    // Jaky's 0.5 (below the top layer, whose own weight still carries K0 = 0.5: 0.7 % of rho g H).
    ScratchDir scratch("stagesFill");
    const fs::path dir = scratch.path() / "column";
    const double H = 1.0;
    writeColumn(dir, H, fillStage);
    const AppResult init = runApplication("picInit", dir);
    ASSERT_EQ(init.exitCode, 0) << init.err;
    const AppResult r = runApplication("picSolver", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(r.warningLines.empty()) << r.err;
    EXPECT_NE(r.out.find("Stage fill (geostaticFill) begins at t = 0 s, step 0"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Stage fill: layer 10, 16 particles up to x2 = 1 m"), std::string::npos) << r.out;
    const auto end = r.out.find("Stage fill ended: equilibrium |v|max ");
    ASSERT_NE(end, std::string::npos) << r.out;
    EXPECT_NE(r.out.find("<= 1e-05 m/s after 10 layers, t = ", end), std::string::npos) << r.out;

    const auto rows = readColumns(dir / "postProcessing/stages.dat");
    ASSERT_EQ(rows.at("endTime").size(), 1u);
    const std::string last = gpic::latestTime(dir.string());
    EXPECT_NEAR(rows.at("endTime")[0], std::stod(last), 1e-5 * std::stod(last)) << "the end is written";
    EXPECT_FALSE(fs::exists(dir / last / "dormant.vtp")) << "every particle is in after the fill";
    EXPECT_NE(readText(dir / last / "uniform/stage").find("stage     none;"), std::string::npos);

    const gpic::Particles<2> p = readState(dir, last);
    ASSERT_EQ(p.size(), 160u);
    double vmax = 0;
    for (const auto& v : p.v) vmax = std::max(vmax, v.norm());
    EXPECT_LE(vmax, 1e-5) << "the stage ended at equilibrium";
    const auto [e22, e11] = stressErrors(p, H, 0.1);
    EXPECT_LT(e22, 0.02);
    EXPECT_LT(e11, 0.02);
}

//- The column of writeColumn (H = 1 m) turned by 30 degrees on the grid, gravity turned with
//  it, its smooth walls a fixed rigid U-shaped body with frictionless contact; `fill` holds the
//  geostaticFill's layer and end keywords, `timeStep` the controlDict's time-step keywords.
struct TurnedColumn {
    const double H = 1.0, theta = M_PI / 6, c = std::cos(theta), sn = std::sin(theta);
    const gpic::Vector2 across{c, sn}, up{-sn, c};
    gpic::Vector2 turned(double s, double n) const { return {c * s - sn * n + 0.8, sn * s + c * n + 0.3}; }
    //- The stress component a . sigma . b.
    static double component(const gpic::SymTensor& t, const gpic::Vector2& a, const gpic::Vector2& b)
    {
        return a.x() * b.x() * t[gpic::XX] + a.y() * b.y() * t[gpic::YY] + (a.x() * b.y() + a.y() * b.x()) * t[gpic::XY];
    }
    void write(const fs::path& dir, const std::string& fill,
               const std::string& timeStep = "deltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\n") const
    {
        const auto polygon = [&](const std::vector<std::pair<double, double>>& corners) {
            std::string text = "points (";
            for (const auto& [s, n] : corners) {
                const gpic::Vector2 x = turned(s, n);
                text += " (" + std::to_string(x.x()) + " " + std::to_string(x.y()) + ")";
            }
            return text + " );";
        };
        writeDictionary(dir / "system/controlDict",
                        timeStep + "writeControl adjustableRunTime;\nwriteInterval 1;\nstages\n{\n    fill { type geostaticFill; fill (soil); phi 30; " + fill + " }\n}\n");
        writeDictionary(dir / "constant/grid", "origin (0 0);\ncellSize 0.1;\nnCells (15 19);\n"
                                               "boundaries { left { type free; } right { type free; } "
                                               "bottom { type free; } top { type free; } }\n");
        writeDictionary(dir / "constant/materials",
                        "soil { type linearElastic; rho " + std::to_string(rho) + "; E 5e7; nu " + std::to_string(nu) + "; }\n"
                        "steel { type linearElastic; rho 7850; E 2e11; nu 0.3; }\n");
        writeDictionary(dir / "constant/g", "value (" + std::to_string(g * sn) + " " + std::to_string(-g * c) + ");\n");
        writeDictionary(dir / "constant/bodies",
                        "soil { material soil; particlesPerCell 2; shape { type polygon; " +
                            polygon({{0, 0}, {0.4, 0}, {0.4, H}, {0, H}}) + " } }\n"
                        "box { material steel; particlesPerCell 2; shape { type polygon; " +
                            polygon({{-0.2, -0.2}, {0.6, -0.2}, {0.6, 1.2}, {0.4, 1.2}, {0.4, 0}, {0, 0}, {0, 1.2}, {-0.2, 1.2}}) +
                            " } }\n");
        writeDictionary(dir / "constant/rigidBodies", "box { type fixed; }\n");
        writeDictionary(dir / "constant/contactProperties", "law coulombFriction;\nnormals rigidSurface;\nmu 0;\n");
    }
};

TEST(Stages, aFillTurnedOnTheGridEntersWithTheStressOfTheTurnedGravity)
{
    // One layer (the whole column) enters with eq. 3.3.4 along gravity: sigma_nn = -rho g d,
    // d measured down the column's n axis from the top of its particles, sigma_ss = sigma33 =
    // K0 sigma_nn (Jaky, phi 30: K0 = 0.5) and sigma_sn = 0 in the column's axes. One step of
    // 1e-7 s later (the stage ends at once) every particle still holds it within 1 % of rho g H.
    ScratchDir scratch("stagesTurnedEntry");
    const fs::path dir = scratch.path() / "column";
    const TurnedColumn column;
    column.write(dir, "layerThickness 2; until { equilibrium 1e9; minSteps 1; }", "deltaT 1e-7;\n");
    ASSERT_EQ(runApplication("picInit", dir).exitCode, 0);
    const AppResult r = runApplication("picSolver", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("Stage fill: layer 1, 159 particles up to height = "), std::string::npos) << r.out;

    const gpic::Particles<2> p = readState(dir, gpic::latestTime(dir.string()));
    double top = -1e9;
    for (std::size_t q = 0; q < p.size(); ++q)
        if (p.body[q] == 0)
            top = std::max(top, p.x0[q].dot(column.up) + p.halfSize[q].cwiseProduct(column.up).cwiseAbs().sum());
    const double jaky = 1 - std::sin(M_PI / 6);
    std::size_t checked = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        if (p.body[q] != 0) continue;
        const double sV = -rho * g * (top - p.x0[q].dot(column.up));
        const gpic::SymTensor& t = p.sigma[q];
        EXPECT_NEAR(TurnedColumn::component(t, column.up, column.up), sV, 0.01 * rho * g * column.H) << q;
        EXPECT_NEAR(TurnedColumn::component(t, column.across, column.across), jaky * sV, 0.01 * rho * g * column.H) << q;
        EXPECT_NEAR(TurnedColumn::component(t, column.across, column.up), 0, 0.01 * rho * g * column.H) << q;
        EXPECT_NEAR(t[gpic::ZZ], jaky * sV, 0.01 * rho * g * column.H) << q;
        ++checked;
    }
    EXPECT_EQ(checked, 159u);
}

TEST(Stages, aFillTurnedOnTheGridSettlesToTheConfinedStateInItsOwnAxes)
{
    // Layers of 0.1 m normal to gravity settle to the confined state of the upright column in
    // the column's own axes (s across, n up): sigma_nn = -rho g (H - n), sigma_ss = K0 sigma_nn
    // with K0 = nu / (1 - nu), sigma_sn = 0. The particles fill the turned outline by whole
    // sub-cells and sit on the grid at all angles, so single particles scatter by about 5 % of
    // rho g H; the test compares the means of bands 0.1 m high, within 3 % of rho g H, above
    // the lowest 0.2 m (where the floor's contact acts inside the cells).
    ScratchDir scratch("stagesTurnedFill");
    const fs::path dir = scratch.path() / "column";
    const TurnedColumn column;
    column.write(dir, "layerThickness 0.1; until { equilibrium 1e-5; maxTime 1; }");
    ASSERT_EQ(runApplication("picInit", dir).exitCode, 0);
    const AppResult r = runApplication("picSolver", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_NE(r.out.find("Stage fill ended: equilibrium"), std::string::npos) << r.out;

    const gpic::Particles<2> p = readState(dir, gpic::latestTime(dir.string()));
    const int nBands = 10;
    std::vector<double> eNN(nBands), eSS(nBands), eSN(nBands);
    std::vector<int> count(nBands);
    for (std::size_t q = 0; q < p.size(); ++q) {
        if (p.body[q] != 0) continue;
        const gpic::SymTensor& t = p.sigma[q];
        const double n = (p.x0[q] - column.turned(0, 0)).dot(column.up);
        const int band = std::clamp(static_cast<int>(n / 0.1), 0, nBands - 1);
        const double sNN = TurnedColumn::component(t, column.up, column.up);
        eNN[band] += sNN + rho * g * (column.H - n);
        eSS[band] += TurnedColumn::component(t, column.across, column.across) - K0 * sNN;
        eSN[band] += TurnedColumn::component(t, column.across, column.up);
        ++count[band];
    }
    for (int band = 2; band < nBands; ++band) {
        ASSERT_GT(count[band], 10) << "band " << band;
        EXPECT_LT(std::abs(eNN[band] / count[band]) / (rho * g * column.H), 0.03) << "band " << band;
        EXPECT_LT(std::abs(eSS[band] / count[band]) / (rho * g * column.H), 0.03) << "band " << band;
        EXPECT_LT(std::abs(eSN[band] / count[band]) / (rho * g * column.H), 0.03) << "band " << band;
    }
}

TEST(Stages, aFillStageStartsFromAnEarlierLayerAndAnUpToHeight)
{
    // upTo 0.5 fills five layers; a second geostaticFill carries on with the other five. Both
    // fill bands of the same rows, so the state equals a single fill's up to the damping's
    // path: the same 2 % bounds.
    ScratchDir scratch("stagesUpTo");
    const fs::path dir = scratch.path() / "column";
    const double H = 1.0;
    writeColumn(dir, H,
                "    lower { type geostaticFill; upTo 0.5; phi 30; until { equilibrium 1e-5; maxTime 1; } }\n"
                "    upper { type geostaticFill; phi 30; until { equilibrium 1e-5; maxTime 1; } }\n");
    const auto simulation = runAndKeep(dir);
    const auto& records = simulation->stages()->records();
    ASSERT_EQ(records.size(), 2u);
    EXPECT_NE(records[0].reason.find("after 5 layers"), std::string::npos) << records[0].reason;
    EXPECT_NE(records[1].reason.find("after 5 layers"), std::string::npos) << records[1].reason;
    EXPECT_EQ(records[1].startTime, records[0].endTime) << "time runs on from stage to stage";
    const auto [e22, e11] = stressErrors(simulation->solver().particles(), H, 0.1);
    EXPECT_LT(e22, 0.02);
    EXPECT_LT(e11, 0.02);
}

TEST(Stages, excavationLeavesTheStressOfTheNewHeight)
{
    // A column of 1 m at rest in its K0 state (picInit); the top 0.3 m are dug away in three
    // layers, each followed by equilibrium. Elastic unloading under confinement takes
    // rho g 0.3 off sigma22 everywhere: sigma22 = -rho g (0.7 - x2) within 2 % of rho g H'.
    ScratchDir scratch("stagesDig");
    const fs::path dir = scratch.path() / "column";
    writeColumn(dir, 1.0,
                "    dig { type excavate; body soil; region { type rectangle; min (-1 0.7); max (1 2); }\n"
                "          until { equilibrium 1e-5; maxTime 1; } }\n",
                "initialStress { type geostatic; K0 " + std::to_string(K0) + "; }");
    const auto simulation = runAndKeep(dir);
    const auto& records = simulation->stages()->records();
    ASSERT_EQ(records.size(), 1u);
    EXPECT_NE(records[0].reason.find("equilibrium"), std::string::npos) << records[0].reason;
    EXPECT_NE(records[0].reason.find("after 3 layers (240 kg/m dug)"), std::string::npos) << records[0].reason;
    const gpic::Particles<2>& p = simulation->solver().particles();
    ASSERT_EQ(p.size(), 112u);
    for (const auto& x : p.x0) ASSERT_LT(x.y(), 0.7);
    const double H = 0.7;
    const auto [e22, e11] = stressErrors(p, H, 0.1);
    EXPECT_LT(e22, 0.02);
    EXPECT_LT(e11, 0.02);
    EXPECT_LE(gpic::EndCondition<2>::maxSpeed(simulation->solver()), 1e-5);
}

namespace {

//- A block of 0.4 x 0.3 m resting on the bottom over its `opening (0.2 0.8)` (whole width).
void writeSilo(const fs::path& dir, const std::string& stages, const std::string& extra = "")
{
    writeDictionary(dir / "system/controlDict", "deltaT 1e-3;\nwriteControl adjustableRunTime;\nwriteInterval 0.05;\n" +
                                                    extra + "stages\n{\n" + stages + "}\n");
    writeDictionary(dir / "constant/grid", "origin (0 0);\ncellSize 0.1;\nnCells (10 6);\n"
                                           "boundaries { left { type fixed; } right { type fixed; } "
                                           "bottom { type slip; opening (0.2 0.8); } top { type free; } }\n");
    writeDictionary(dir / "constant/materials", "sand { type linearElastic; rho 1600; E 1e6; nu 0.3; }\n");
    writeDictionary(dir / "constant/g", "value (0 -9.81);\n");
    writeDictionary(dir / "constant/bodies",
                    "sand { material sand; particlesPerCell 2; shape { type rectangle; min (0.3 0); max (0.7 0.3); } }\n");
}

const std::string siloStages = "    closed { type run; openings { bottom closed; } damping 0.8; until { duration 0.2; } }\n"
                               "    open   { type openGate; side bottom; until { duration 0.3; } }\n";

} // namespace

TEST(Stages, aClosedGateHoldsTheBlockAndTheOpenedGateLetsItOut)
{
    // The run stops at endTime 0.2, the end of the closed stage: nothing has left and the
    // block sits where it was. The restart (written at the stage's end) opens the gate: the
    // block falls through (g t^2 / 2 = 0.44 m in 0.3 s) and its mass is removed.
    ScratchDir scratch("stagesGate");
    const fs::path dir = scratch.path() / "silo";
    writeSilo(dir, siloStages, "endTime 0.2;\n");
    {
        const auto closed = runAndKeep(dir);
        EXPECT_EQ(closed->solver().removedMass(), 0.0);
        const gpic::Particles<2>& p = closed->solver().particles();
        ASSERT_EQ(p.size(), 48u);
        double drop = 0;
        for (std::size_t q = 0; q < p.size(); ++q) drop = std::max(drop, p.x0[q].y() - p.x[q].y());
        EXPECT_LT(drop, 0.01) << "the closed gate holds the block";
        ASSERT_EQ(closed->stages()->records().size(), 1u);
        EXPECT_EQ(closed->stages()->records()[0].endTime, 0.2);
    }
    replaceText(dir / "system/controlDict", "endTime 0.2;", "");
    gpic::RunOptions options;
    options.caseDir = dir.string();
    options.quiet = true;
    gpic::Simulation<2> open(options);
    open.run();
    EXPECT_NEAR(open.time(), 0.5, 1e-12);
    EXPECT_GT(open.solver().removedMass(), 0.5 * 1600 * 0.12) << "most of the block fell out";
    EXPECT_NEAR(open.solver().removedMass() + [&] {
        double m = 0;
        for (double mq : open.solver().particles().m) m += mq;
        return m;
    }(), 1600 * 0.12, 1e-9) << "what left plus what is left is the block";
    const auto rows = readColumns(dir / "postProcessing/stages.dat");
    ASSERT_EQ(rows.at("startTime").size(), 2u);
    EXPECT_DOUBLE_EQ(rows.at("startTime")[1], 0.2);
}

TEST(Stages, endConditionsByTimeAndByTheToolsDisplacement)
{
    // A blade held `fixed` for 0.05 s (duration), then driven by its constant/rigidBodies
    // velocity table, which the driver reads from the stage's start: a ramp to 0.5 m/s over
    // 0.1 s, then constant. It has moved D = 0.2 m at 0.025 + 0.175 / 0.5 = 0.45 s after the
    // stage began; the stage stops at the first step that reaches D, within one step (1 ms).
    ScratchDir scratch("stagesTool");
    const fs::path dir = scratch.path() / "tool";
    writeSilo(dir,
              "    hold { type run; drivers { blade { type fixed; } } until { duration 0.05; } }\n"
              "    push { type moveTool; body blade; until { displacement 0.2; } }\n");
    replaceText(dir / "constant/grid", "nCells (10 6);", "nCells (20 6);");
    replaceText(dir / "constant/grid", "opening (0.2 0.8); ", "");
    writeDictionary(dir / "constant/bodies",
                    "sand { material sand; particlesPerCell 2; shape { type rectangle; min (0 0); max (0.4 0.3); } }\n"
                    "blade { material sand; particlesPerCell 2; shape { type rectangle; min (1 0.3); max (1.1 0.5); } }\n");
    writeDictionary(dir / "constant/rigidBodies",
                    "blade { type prescribedVelocity; velocity table ((0 0 0) (0.1 0.5 0) (10 0.5 0)); }\n");
    const auto simulation = runAndKeep(dir);
    const auto& records = simulation->stages()->records();
    ASSERT_EQ(records.size(), 2u);
    EXPECT_EQ(records[0].endTime, 0.05) << "a time end is landed on";
    EXPECT_NE(records[0].reason.find("duration 0.05 s reached"), std::string::npos) << records[0].reason;
    const double moving = records[1].endTime - records[1].startTime;
    EXPECT_GE(moving, 0.45 - 1e-9);
    EXPECT_LT(moving, 0.45 + 1e-3 + 1e-9);
    EXPECT_NE(records[1].reason.find("displacement 0.2"), std::string::npos) << records[1].reason;
    // The blade did not move while it was held.
    EXPECT_EQ(records[1].startStep, 50);
    // The guard's summary covers the whole run, not only the last stage (a copy of the state
    // at its start, then one every snapshotInterval steps).
    const long interval = simulation->guard().snapshotInterval();
    EXPECT_GT(simulation->guard().snapshots(), 1 + (records[1].endStep - records[1].startStep) / interval);
    const gpic::Particles<2>& p = simulation->solver().particles();
    for (std::size_t q = 0; q < p.size(); ++q)
        if (p.body[q] == 1) {
            EXPECT_NEAR(p.x[q].x() - p.x0[q].x(), 0.2, 0.5e-3 + 1e-9);
        }
}

TEST(Stages, aRestartInsideAFillEndsBitwiseAsTheStraightRun)
{
    // The fill stopped at t = 0.125 s (endTime, a write time; both exact in binary, so that
    // the straight run lands on the same time), inside one of its layers,
    // and restarted, against the fill run straight through: every later time directory the
    // same bit for bit (particles, sleeping particles, stage progress).
    ScratchDir scratch("stagesRestart");
    const fs::path straight = scratch.path() / "straight", split = scratch.path() / "split";
    writeColumn(straight, 1.0, fillStage);
    writeColumn(split, 1.0, fillStage, "", "endTime 0.125;\n");
    runAndKeep(straight);
    runAndKeep(split);
    ASSERT_TRUE(fs::exists(split / "0.125/dormant.vtp")) << "stopped inside the fill";
    const std::string progress = readText(split / "0.125/uniform/stage");
    EXPECT_NE(progress.find("begun     yes;"), std::string::npos) << progress;
    EXPECT_EQ(progress, readText(straight / "0.125/uniform/stage"));
    replaceText(split / "system/controlDict", "endTime 0.125;", "");
    gpic::RunOptions options;
    options.caseDir = split.string();
    options.quiet = true;
    gpic::Simulation<2> restarted(options);
    restarted.run();

    const auto times = gpic::listTimeDirectories(straight.string());
    ASSERT_GT(times.size(), 5u);
    int compared = 0;
    for (const auto& [t, name] : times) {
        if (t <= 0.125) continue;
        ASSERT_TRUE(fs::exists(split / name)) << name;
        for (const char* file : {"particles.vtp", "dormant.vtp", "uniform/stage", "uniform/time"}) {
            ASSERT_EQ(fs::exists(straight / name / file), fs::exists(split / name / file)) << name << "/" << file;
            if (fs::exists(straight / name / file)) {
                EXPECT_TRUE(readText(straight / name / file) == readText(split / name / file)) << name << "/" << file;
            }
        }
        ++compared;
    }
    EXPECT_GT(compared, 3);
    EXPECT_EQ(gpic::listTimeDirectories(split.string()).back().second, times.back().second);
}

namespace {

//- The InputError a Simulation of `dir` (after picInit) throws, or "" when none.
gpic::InputError inputErrorOf(const fs::path& dir)
{
    gpic::initialiseCase(dir.string());
    gpic::RunOptions options;
    options.caseDir = dir.string();
    options.quiet = true;
    try {
        gpic::Simulation<2> s(options);
    } catch (const gpic::InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError for " << dir;
    return gpic::InputError("", 0, "");
}

} // namespace

TEST(Stages, badStageInputIsOneLineNamingFileLineKeywordAndChoices)
{
    ScratchDir scratch("stagesBad");
    const auto check = [&](const std::string& tag, const std::string& stages, const std::vector<std::string>& words,
                           const std::string& extra = "") {
        SCOPED_TRACE(tag);
        const fs::path dir = scratch.path() / tag;
        writeColumn(dir, 1.0, stages, "", extra);
        const gpic::InputError e = inputErrorOf(dir);
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(e.file(), "system/controlDict") << what;
        EXPECT_GT(e.line(), 0) << what;
        for (const auto& w : words) EXPECT_NE(what.find(w), std::string::npos) << "'" << w << "' not in: " << what;
    };
    check("type", "    fill { type fillUp; until { duration 1; } }\n",
          {"unknown stage type 'fillUp'", "valid choices: excavate, geostaticFill, moveTool, openGate, run"});
    check("noType", "    fill { until { duration 1; } }\n", {"needs a type", "geostaticFill"});
    check("until", "    settle { type run; damping 0.8; }\n", {"needs an end condition", "until", "equilibrium"});
    check("twoEnds", "    settle { type run; until { duration 1; equilibrium 1e-6; } }\n",
          {"exactly one of endTime, duration, displacement and equilibrium"});
    check("body", "    settle { type run; bodies (soil rock); until { duration 1; } }\n",
          {"'rock' is not a body of the particles; valid choices: soil"});
    check("tool", "    push { type moveTool; body soil; until { displacement 0.1; } }\n", {"'soil' has no driver"});
    check("gate", "    open { type openGate; side bottom; until { duration 1; } }\n",
          {"side 'bottom' has no `opening`", "valid choices: (none)"});
    check("fillUntil", "    fill { type geostaticFill; phi 30; until { duration 1; } }\n",
          {"each layer to equilibrium", "until { equilibrium"});
    check("K0", "    fill { type geostaticFill; until { equilibrium 1e-6; } }\n", {"exactly one of K0 and phi"});
    check("damping", "    settle { type run; until { duration 1; } }\n", {"damping per stage"}, "damping 0.5;\n");
    check("dampingRange", "    settle { type run; damping 1.5; until { duration 1; } }\n", {"0 <= damping < 1"});
}
