// Mass scaling (libpic/time/MassScaling.H): a density scaled by s slows the waves by sqrt(s),
// so the stable step h / c grows by sqrt(s); gravity keeps acting on the true mass. Checked
// on the damped elastic column of geostaticTest.C, whose settled state is the geostatic
// field sigma22 = -rho g (H - x2), sigma11 = K0 sigma22, K0 = nu / (1 - nu): a weight taken
// from the scaled mass would give 100 times that stress.
#include "support/CaseRunner.H"
#include "support/GeostaticColumn.H"

using namespace gpic::test;

namespace {

const double E = 5e7;

//- The column, damped (alpha 0.8) from zero stress, with `massScaling` as given ("" none).
void writeColumn(const fs::path& dir, const std::string& massScaling, double endTime, double damping = 0.8)
{
    column::write(dir, E, damping, endTime, false, "bilinear", massScaling);
}

struct Settled {
    double stressError;  //- max |sigma - geostatic| / (rho g H)
    long steps;
    double massScale;    //- of the soil (1 without scaling)
};

Settled settle(const std::string& massScaling, double endTime)
{
    ScratchDir scratch("massScaling");
    const fs::path dir = scratch.path() / "column";
    writeColumn(dir, massScaling, endTime);
    gpic::initialiseCase(dir.string());
    gpic::RunOptions options;
    options.caseDir = dir.string();
    options.quiet = true;
    gpic::Simulation<2> simulation(options);
    Settled r{0, simulation.run(), 1};
    const auto& scales = simulation.solver().massScales();
    if (!scales.empty()) r.massScale = scales[0];
    r.stressError = column::stressError(simulation.solver().particles());
    return r;
}

//- v with all its digits, for a dictionary entry.
std::string exact(double v)
{
    std::ostringstream os;
    os.precision(17);
    os << v;
    return os.str();
}

//- The engine of the column case, built but not run.
std::unique_ptr<gpic::Simulation<2>> columnEngine(const fs::path& dir, const std::string& massScaling)
{
    writeColumn(dir, massScaling, 0.01);
    return initialisedSimulation(dir);
}

} // namespace

TEST(MassScaling, theColumnSettlesUnderItsTrueWeightInTenTimesFewerSteps)
{
    // The same 3 % of rho g H as the unscaled column (geostaticTest.C). Scaled 100 times,
    // the column's period grows tenfold: it gets 10 times as long to settle in the same
    // number of steps, which are 10 times longer.
    const Settled plain = settle("", 1.5);
    const Settled scaled = settle("massScaling { factor 100; }", 15);
    EXPECT_LT(plain.stressError, 0.03);
    EXPECT_LT(scaled.stressError, 0.03);
    EXPECT_DOUBLE_EQ(scaled.massScale, 100);
    // 15 s at 10 times the step: the plain run's count, within the steps that land on writes.
    EXPECT_NEAR(double(scaled.steps) / double(plain.steps), 1.0, 0.01);
}

TEST(MassScaling, theStableStepGrowsBySqrtOfTheScale)
{
    ScratchDir scratch("massScalingStep");
    const auto plain = columnEngine(scratch.path() / "plain", "");
    const auto byFactor = columnEngine(scratch.path() / "factor", "massScaling { factor 100; }");
    const double dt = plain->solver().criticalTimeStep();
    EXPECT_NEAR(byFactor->solver().criticalTimeStep() / dt, 10.0, 1e-12);
    EXPECT_NEAR(byFactor->solver().maxWaveSpeed() * 10.0, plain->solver().maxWaveSpeed(), 1e-9);
    // timeStep: the scale that makes maxCourant h / c' the target, (T / (C h / c))^2.
    const double target = 5 * 0.5 * dt;
    const auto byStep = columnEngine(scratch.path() / "step", "massScaling { timeStep " + exact(target) + "; }");
    EXPECT_NEAR(byStep->solver().massScales()[0], 25.0, 1e-9);
    EXPECT_NEAR(0.5 * byStep->solver().criticalTimeStep(), target, 1e-12 * target);
    // A target the material already reaches leaves it unscaled.
    const auto reached = columnEngine(scratch.path() / "reached", "massScaling { timeStep " + exact(0.1 * dt) + "; }");
    EXPECT_DOUBLE_EQ(reached->solver().massScales()[0], 1.0);
}

TEST(MassScaling, tooMuchInertiaIsWarned)
{
    // Undamped and scaled 1e4 times, the column falls under its weight as a slow, heavy
    // spring: its kinetic energy is a large share of gravity's work, and the run says so.
    ScratchDir scratch("massScalingWarn");
    const fs::path dir = scratch.path() / "column";
    writeColumn(dir, "massScaling { factor 1e4; kineticRatio 0.05; }", 6.0, 0.0);
    testing::internal::CaptureStderr();
    runAndKeep(dir);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("of the work done on the material in the stage (kineticRatio 0.05)"), std::string::npos) << err;
    // The damped column at factor 100 stays quiet.
    const fs::path quiet = scratch.path() / "quiet";
    writeColumn(quiet, "massScaling { factor 100; }", 15);
    testing::internal::CaptureStderr();
    runAndKeep(quiet);
    EXPECT_EQ(testing::internal::GetCapturedStderr().find("kineticRatio"), std::string::npos);
}

TEST(MassScaling, badEntriesNameTheKeyword)
{
    ScratchDir scratch("massScalingBad");
    const auto fails = [&](const std::string& name, const std::string& entry, const std::string& expected) {
        const fs::path dir = scratch.path() / name;
        writeColumn(dir, entry, 0.01);
        try {
            initialisedSimulation(dir);
            ADD_FAILURE() << entry << " was accepted";
        } catch (const gpic::InputError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    fails("both", "massScaling { factor 10; timeStep 1e-3; }", "one of factor");
    fails("neither", "massScaling { kineticRatio 0.1; }", "one of factor");
    fails("light", "massScaling { factor 0.5; }", "factor >= 1");
    fails("word", "massScaling 100;", "needs a sub-dictionary");
    // Applied loads: their work is told from the weight's by the nodal mass.
    const fs::path loaded = scratch.path() / "loaded";
    writeColumn(loaded, "massScaling { factor 10; }", 0.01);
    writeDictionary(loaded / "constant/loads",
                    "top { type surfacePressure; body column; from (0 2); to (1 2); pressure 1000; }\n");
    try {
        initialisedSimulation(loaded);
        ADD_FAILURE() << "mass scaling with loads was accepted";
    } catch (const gpic::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("applied loads"), std::string::npos) << e.what();
    }
}

TEST(MassScaling, aStageMayScaleAndTheNextNot)
{
    // The column settles scaled 100 times, then goes on unscaled: the settled stress holds,
    // and each stage takes the steps of its own stable step.
    ScratchDir scratch("massScalingStages");
    const auto plain = columnEngine(scratch.path() / "plain", "");
    const double dt = 0.5 * plain->solver().criticalTimeStep();  // maxCourant 0.5, unscaled
    const fs::path dir = scratch.path() / "column";
    writeColumn(dir, "", 1);
    std::ofstream(dir / "system/controlDict")
        << "deltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\nwriteControl adjustableRunTime;\nwriteInterval 100;\n"
        << "stages {\n  settle { type run; damping 0.8; massScaling { factor 100; } until { duration 15; } }\n"
        << "  go { type run; damping 0.8; until { duration 0.1; } }\n}\n";
    const auto simulation = initialisedSimulation(dir);
    const long steps = simulation->run();
    EXPECT_TRUE(simulation->solver().massScales().empty());  // the last stage is unscaled
    EXPECT_LT(column::stressError(simulation->solver().particles()), 0.03);
    const double expected = 15 / (10 * dt) + 0.1 / dt;
    EXPECT_NEAR(double(steps) / expected, 1.0, 0.05) << steps << " steps, " << expected << " expected";
}
