// A small polar scene (a Cosserat Drucker-Prager column collapsing on a rough floor, rotation
// fixed there and on the symmetry side) runs bitwise the same at 1 and 2 threads
// (doc/threading.md), and a run stopped half-way and restarted from its time directory ends
// bitwise as the straight run: the micro-rotation, its rate, sigma21, the couple stresses and
// the curvatures are written to the VTK file and read back.
#include "core/Threads.H"
#include "io/ParticlesVtk.H"
#include "io/TimeDirectories.H"
#include "planar/CosseratRotation.H"
#include "support/CaseRunner.H"
#include "support/ThreadRuns.H"

#include <omp.h>

#include <cmath>
#include <cstring>

using namespace gpic;
using namespace gpic::test;

namespace {

void columnCase(const fs::path& dir, const std::string& scheme, double endTime)
{
    writeDictionary(dir / "system/controlDict", "startFrom latestTime; endTime " + std::to_string(endTime) +
                                                    "; deltaT 1e-5;\n"
                                                    "writeControl adjustableRunTime; writeInterval 1e-3;\n");
    writeDictionary(dir / "system/mpmSchemes", "updateScheme " + scheme + "; shapeFunction uGIMP; sortInterval 20;\n");
    writeDictionary(dir / "constant/grid", "origin (0 0); cellSize 0.002; nCells (40 16);\n"
                                           "boundaries { left { type symmetry; } right { type slip; }\n"
                                           "  bottom { type fixed; rotation fixed; } top { type free; } }\n");
    writeDictionary(dir / "constant/materials",
                    "sand { type cosseratDruckerPrager; rho 2650; G 0.3e6; nu 0.3; l 0.002; phi 30; psi 2; c 0; }\n");
    writeDictionary(dir / "constant/bodies", "column { material sand; shape { type rectangle; min (0 0); max (0.03 0.02); } particlesPerCell 2; }\n");
    writeDictionary(dir / "constant/g", "value (0 -9.81);\n");
}

void expectSame(const Particles<2>& a, const Particles<2>& b)
{
    ASSERT_TRUE(a.carries(FieldGroup::polar));
    ASSERT_TRUE(b.carries(FieldGroup::polar));
    expectBitwise(a.id, b.id, "id");
    expectBitwise(a.x, b.x, "x");
    expectBitwise(a.v, b.v, "v");
    expectBitwise(a.sigma, b.sigma, "sigma");
    expectBitwise(a.epsP, b.epsP, "epsP");
    expectBitwise(a.polar.w, b.polar.w, "microRotation");
    expectBitwise(a.polar.omega, b.polar.omega, "microRotationRate");
    expectBitwise(a.polar.sigma21, b.polar.sigma21, "sigma21");
    expectBitwise(a.polar.mu, b.polar.mu, "coupleStress");
    expectBitwise(a.polar.kappa, b.polar.kappa, "curvature");
    expectBitwise(a.history("epsPs"), b.history("epsPs"), "epsPs");
}

double largest(const std::vector<double>& a)
{
    double m = 0;
    for (double v : a) m = std::max(m, std::abs(v));
    return m;
}

} // namespace

TEST(CosseratRun, aPolarSceneIsTheSameAtOneAndTwoThreads)
{
    for (const char* scheme : {"USL", "MUSL"}) {
        ScratchDir scratch("cosseratThreads");
        columnCase(scratch.path() / "one", scheme, 1e-3);
        columnCase(scratch.path() / "two", scheme, 1e-3);
        const Particles<2> one = runAtThreads(scratch.path() / "one", 1), two = runAtThreads(scratch.path() / "two", 2);
        EXPECT_GT(largest(one.polar.w), 0.0) << "the column turns its grains";
        EXPECT_GT(largest(one.history("yieldState")), 0.0) << "and yields";
        expectSame(one, two);
    }
}

TEST(CosseratRun, aRestartContinuesBitwiseAsTheStraightRun)
{
    ScratchDir scratch("cosseratRestart");
    const fs::path straight = scratch.path() / "straight", split = scratch.path() / "split";
    columnCase(straight, "USL", 2e-3);
    columnCase(split, "USL", 1e-3);
    const Particles<2> whole = runAndKeep(straight)->solver().particles();
    runAndKeep(split);
    setEntry(split / "system/controlDict", "endTime", "2e-3");
    RunOptions options;
    options.caseDir = split.string();
    options.quiet = true;
    Simulation<2> restarted(options);
    EXPECT_GT(largest(restarted.solver().particles().polar.w), 0.0) << "the restart read the micro-rotation";
    restarted.run();
    expectSame(whole, restarted.solver().particles());

    // The written file holds the polar fields; a nonpolar reader sees no history in them.
    double t = 0;
    Particles<2> read;
    const auto times = listTimeDirectories(split.string());
    readParticles((split / times.back().second / "particles.vtp").string(), read, t);
    EXPECT_TRUE(read.carries(FieldGroup::polar));
    EXPECT_FALSE(read.hasHistory("microRotation"));
    expectBitwise(read.polar.w, restarted.solver().particles().polar.w, "microRotation read back");
}

// The rotation field exists only where a body is made of a polar material: a Cosserat material
// that constant/materials lists but no body uses (cases list both and pick one) leaves the
// scene nonpolar, with no rotation arrays and no rotational time-step limit.
TEST(CosseratRun, aPolarMaterialNoBodyUsesAddsNoRotationField)
{
    ScratchDir scratch("cosseratUnused");
    const fs::path polar = scratch.path() / "polar", listedOnly = scratch.path() / "listedOnly";
    columnCase(polar, "USL", 1e-3);
    columnCase(listedOnly, "USL", 1e-3);
    {
        std::ofstream m(listedOnly / "constant" / "materials", std::ios::app);
        m << "soil { type linearElastic; rho 2650; E 0.78e6; nu 0.3; }\n";
    }
    replaceText(listedOnly / "constant/bodies", "material sand;", "material soil;");
    const auto used = initialisedSimulation(polar);
    const auto unused = initialisedSimulation(listedOnly);
    EXPECT_TRUE(used->solver().find<CosseratRotation>() != nullptr);
    EXPECT_TRUE(used->solver().particles().carries(FieldGroup::polar));
    EXPECT_FALSE(unused->solver().find<CosseratRotation>() != nullptr);
    EXPECT_FALSE(unused->solver().particles().carries(FieldGroup::polar));
    // Without the rotation the step is the translational one (E = 2 G (1 + nu) as sand's G).
    EXPECT_GT(unused->solver().criticalTimeStep(), used->solver().criticalTimeStep());
}

// A rigid body holds the micro-rotation at its nodes unless its driver says `rotation free`
// (seed 6.2.5: fixed at smooth tools, free at rough ones). A stage that gives the body a
// driver of its own may change that; where the stage's driver is silent, the body keeps the
// condition of constant/rigidBodies.
TEST(CosseratRun, aStagesDriverSetsTheRotationConditionAtItsRigidBody)
{
    const auto plateFixedAfter = [](const std::string& constantRotation, const std::string& stageRotation) {
        ScratchDir scratch("polarStages");
        const fs::path dir = scratch.path() / "column";
        columnCase(dir, "MUSL", 2e-4);
        std::ofstream(dir / "constant/materials", std::ios::app) << "steel { type linearElastic; rho 7850; E 200e9; nu 0.3; }\n";
        std::ofstream(dir / "constant/bodies", std::ios::app)
            << "plate { material steel; shape { type rectangle; min (0 0.024); max (0.03 0.028); } particlesPerCell 2; }\n";
        writeDictionary(dir / "constant/rigidBodies", "plate { type fixed; " + constantRotation + " }\n");
        std::ofstream(dir / "system/controlDict", std::ios::app)
            << "stages {\n  settle { type run; until { duration 1e-4; } }\n"
            << "  hold { type run; drivers { plate { type fixed; " + stageRotation + " } } until { duration 1e-4; } }\n}\n";
        const auto simulation = runAndKeep(dir);
        EXPECT_EQ(simulation->stages()->records().size(), 2u);
        const auto& fixed = simulation->solver().find<CosseratRotation>()->field().rigidFixed;
        EXPECT_EQ(fixed.size(), 2u);
        return fixed.size() == 2 && fixed[1] != 0;
    };
    EXPECT_FALSE(plateFixedAfter("", "rotation free;")) << "the stage's driver frees the rotation";
    EXPECT_TRUE(plateFixedAfter("rotation free;", "rotation fixed;")) << "the stage's driver fixes it";
    EXPECT_FALSE(plateFixedAfter("rotation free;", "")) << "a silent stage driver keeps constant/rigidBodies'";
    EXPECT_TRUE(plateFixedAfter("", "")) << "fixed by default";
}
