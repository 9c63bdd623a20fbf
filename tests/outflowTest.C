// Outlets: particles that leave the grid through an `outflow` side or an `opening` of a
// wall are removed and their mass counted; elsewhere the wall holds them.
#include "support/CaseRunner.H"

#include <cmath>
#include <numeric>

using namespace gpic;
using namespace gpic::test;

namespace {

double sum(const std::vector<double>& a) { return std::accumulate(a.begin(), a.end(), 0.0); }

//- A 20 x 20 mm elastic block falling for 0.06 s (600 steps) through the outflow bottom of a
//  40 x 40 mm grid; `functions` is added to the controlDict.
void fallingBlockCase(const fs::path& dir, const std::string& functions)
{
    writeDictionary(dir / "system/controlDict",
                    "endTime 0.06; deltaT 1e-4; writeControl timeStep; writeInterval 100000;\n" + functions);
    // MUSL: the nodal velocity comes from the particles' momenta, so the node a particle has
    // just reached (tiny mass) cannot turn round-off into strain (USL's small-mass instability).
    writeDictionary(dir / "system/mpmSchemes", "updateScheme MUSL;\n");
    writeDictionary(dir / "constant/grid", "origin (0 0); cellSize 0.002; nCells (20 20);\n"
                                 "boundaries { left { type slip; } right { type slip; } bottom { type outflow; } top { type free; } }\n");
    writeDictionary(dir / "constant/materials", "block { type linearElastic; rho 1000; E 1e5; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies", "block { material block; shape { type rectangle; min (0.01 0.0101); max (0.03 0.0301); } particlesPerCell 2; }\n");
    writeDictionary(dir / "constant/g", "value (0 -9.81);\n");
}

} // namespace

TEST(Outflow, aFallingBlockLeavesRowByRowAsFreeFallPredicts)
{
    // Free fall is exact in MPM: every node gets a = g, so after n steps of dt a particle
    // has dropped g dt^2 n (n + 1) / 2 (symplectic Euler). It is removed at the end of the
    // first step that takes it below the outflow side.
    ScratchDir scratch("outflow");
    const fs::path dir = scratch.path() / "case";
    const double dt = 1e-4, g = 9.81;
    const long steps = 600;
    fallingBlockCase(dir, "");
    auto simulation = initialisedSimulation(dir);
    const Particles<2> initial = simulation->solver().particles();
    simulation->run();
    const double drop = g * dt * dt * steps * (steps + 1) / 2;
    double expected = 0, rowMass = 0;
    for (std::size_t q = 0; q < initial.size(); ++q) {
        if (initial.x[q].y() < drop) expected += initial.m[q];
        rowMass = initial.m[q] * 20;  // 20 particles per row
    }
    const MpmSolver<2>& solver = simulation->solver();
    EXPECT_GT(expected, 0.3 * sum(initial.m));
    EXPECT_LT(expected, 0.7 * sum(initial.m));
    EXPECT_NEAR(solver.removedMass(), expected, 0.5 * rowMass) << "rows removed too early or too late";
    EXPECT_NEAR(solver.removedMass() + sum(solver.particles().m), sum(initial.m), 1e-12 * sum(initial.m));
    for (const auto& x : solver.particles().x) EXPECT_TRUE(solver.grid().contains(x));
}

TEST(Outflow, anOpeningInAWallLetsOutOnlyWhatIsAboveIt)
{
    // Cohesionless material on a rough floor with an opening at the left (the symmetry side):
    // material drains through the opening; the floor beside it holds the rest.
    ScratchDir scratch("outflow");
    const fs::path dir = scratch.path() / "case";
    writeDictionary(dir / "system/controlDict", "endTime 0.15; deltaT 5e-5; writeControl timeStep; writeInterval 100000;\n");
    writeDictionary(dir / "constant/grid", "origin (0 0); cellSize 0.005; nCells (24 12);\n"
                                 "boundaries { left { type symmetry; } right { type fixed; }\n"
                                 "             bottom { type fixed; opening (0 0.02); } top { type free; } }\n");
    writeDictionary(dir / "constant/materials", "sand { type mohrCoulomb; rho 1500; E 2e6; nu 0.3; phi 30; psi 0; c 0; }\n");
    writeDictionary(dir / "constant/bodies", "sand { material sand; shape { type rectangle; min (0 0); max (0.12 0.03); } particlesPerCell 2; }\n");
    writeDictionary(dir / "constant/g", "value (0 -9.81);\n");
    auto simulation = initialisedSimulation(dir);
    const Particles<2> initial = simulation->solver().particles();
    simulation->run();
    const MpmSolver<2>& solver = simulation->solver();
    EXPECT_GT(solver.removedMass(), 0.05 * sum(initial.m)) << "the opening lets material out";
    EXPECT_NEAR(solver.removedMass() + sum(solver.particles().m), sum(initial.m), 1e-12 * sum(initial.m));
    // Far from the opening the floor holds: the bottom layer there has not dropped.
    for (std::size_t q = 0; q < solver.particles().size(); ++q) {
        const Vector2& x = solver.particles().x[q];
        EXPECT_TRUE(solver.grid().contains(x));
        if (solver.particles().x0[q].x() > 0.08) {
            EXPECT_GT(x.y(), 0.0);
        }
    }
}

TEST(Outflow, aReversedOpeningIsAnInputError)
{
    ScratchDir scratch("outflow");
    const fs::path dir = scratch.path() / "case";
    writeDictionary(dir / "system/controlDict", "endTime 0.01; deltaT 1e-4; writeControl timeStep; writeInterval 100000;\n");
    writeDictionary(dir / "constant/grid", "origin (0 0); cellSize 0.005; nCells (4 4);\n"
                                 "boundaries { left { type slip; } right { type slip; }\n"
                                 "             bottom { type fixed; opening (0.02 0.01); } top { type free; } }\n");
    writeDictionary(dir / "constant/materials", "m { type linearElastic; rho 1000; E 1e6; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies", "b { material m; shape { type rectangle; min (0 0); max (0.01 0.01); } particlesPerCell 2; }\n");
    try {
        initialisedSimulation(dir);
        FAIL() << "a reversed opening was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("constant/grid"), std::string::npos) << what;
        EXPECT_NE(what.find("opening"), std::string::npos) << what;
        EXPECT_NE(what.find("a < b"), std::string::npos) << what;
    }
}

TEST(Outflow, massFlowLogsWhatHasFallenOutAtEachTime)
{
    // The falling block of the first test with a massFlow function object over the lower
    // half of the grid, factor 2 (a half model): at every line the mass gone equals the rows
    // free fall has taken below the outflow side by then, the region holds what lies in it,
    // and the rate column integrates to the mass gone.
    ScratchDir scratch("outflow");
    const fs::path dir = scratch.path() / "case";
    const double dt = 1e-4, g = 9.81, factor = 2;
    fallingBlockCase(dir, "functions { silo { type massFlow; writeInterval 50; factor 2; "
                          "region { min (0 0); max (0.04 0.02); } } }\n");
    auto simulation = initialisedSimulation(dir);
    const Particles<2> initial = simulation->solver().particles();
    simulation->run();
    const double removed = simulation->solver().removedMass();
    simulation.reset();  // closes postProcessing files

    const auto dat = readColumns(dir / "postProcessing/silo/0/massFlow.dat");
    ASSERT_EQ(dat.at("time").size(), 13u) << "the start and every 50 steps";
    const double rowMass = factor * initial.m[0] * 20;  // 20 particles per row
    double integrated = 0;
    for (std::size_t k = 0; k < dat.at("time").size(); ++k) {
        const double t = dat.at("time")[k];
        const long n = std::lround(t / dt);
        const double drop = g * dt * dt * n * (n + 1) / 2;  // symplectic Euler free fall
        double gone = 0, inRegion = 0;
        for (std::size_t q = 0; q < initial.size(); ++q) {
            const double y = initial.x[q].y() - drop;
            if (y < 0) gone += factor * initial.m[q];
            else if (y <= 0.02) inRegion += factor * initial.m[q];
        }
        EXPECT_NEAR(dat.at("out")[k], gone, 0.5 * rowMass) << "t = " << t;
        EXPECT_NEAR(dat.at("mass")[k], inRegion, 0.5 * rowMass) << "t = " << t;
        if (k > 0) integrated += dat.at("outflowRate")[k] * (t - dat.at("time")[k - 1]);
    }
    EXPECT_NEAR(dat.at("out").back(), factor * removed, 1e-9 * factor * removed);
    EXPECT_NEAR(integrated, factor * removed, 1e-9 * factor * removed);
    EXPECT_GT(removed, 0.3 * factor * initial.m[0] * initial.size() / factor);
}
