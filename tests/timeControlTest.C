// Time stepping and write control (system/controlDict), OpenFOAM's Time semantics.
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "support/CaseRunner.H"
#include "time/TimeControl.H"

#include <gtest/gtest.h>

using namespace gpic;

namespace {
Dictionary control(const std::string& text)
{
    return Dictionary::parse("endTime 1; deltaT 1e-3; writeInterval 0.1; " + text, "system/controlDict");
}
} // namespace

TEST(TimeControl, aFixedStepIsKeptAndShortenedOnlyToLandOnTheEndTime)
{
    const Dictionary d = control("");
    const TimeControl tc(d);
    EXPECT_DOUBLE_EQ(tc.deltaT(0.5, 1.0), 1e-3);
    EXPECT_NEAR(tc.deltaT(1.0 - 4e-4, 1.0), 4e-4, 1e-15);
    EXPECT_TRUE(tc.finished(1.0));
    EXPECT_FALSE(tc.finished(1.0 - 1e-6));
}

TEST(TimeControl, anAdjustedStepIsTheCourantNumberTimesTheLimitCappedByMaxDeltaT)
{
    const Dictionary d = control("adjustTimeStep yes; maxCourant 0.4; maxDeltaT 2e-3;");
    const TimeControl tc(d);
    EXPECT_DOUBLE_EQ(tc.deltaT(0.0, 1e-3), 0.4e-3);  // 0.4 x the limit
    EXPECT_DOUBLE_EQ(tc.deltaT(0.0, 1.0), 2e-3);     // capped
}

TEST(TimeControl, adjustableRunTimeLandsExactlyOnWriteTimes)
{
    const Dictionary d = control("adjustTimeStep yes; maxDeltaT 0.03; writeControl adjustableRunTime;");
    const TimeControl tc(d);
    double t = 0;
    int writes = 0;
    while (!tc.finished(t)) {
        const double previous = t;
        t += tc.deltaT(t, 1.0);
        if (tc.isWriteTime(previous, t, 0)) {
            ++writes;
            EXPECT_NEAR(t, 0.1 * writes, 1e-12);
        }
    }
    EXPECT_EQ(writes, 10);
}

TEST(TimeControl, timeStepWriteControlCountsSteps)
{
    const Dictionary d = Dictionary::parse("endTime 1; deltaT 1e-3; writeControl timeStep; writeInterval 50;",
                                           "system/controlDict");
    const TimeControl tc(d);
    EXPECT_FALSE(tc.isWriteTime(0.0, 1e-3, 49));
    EXPECT_TRUE(tc.isWriteTime(0.0, 1e-3, 100));
}

TEST(TimeControl, aFixedStepAboveTheLimitStopsWithTheLimitInTheMessage)
{
    const Dictionary d = control("");
    const TimeControl tc(d);
    try {
        tc.checkStable(5e-4, "cell size 0.04 m / (wave speed 80 m/s + particle speed 0 m/s)");
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("system/controlDict:1:"), std::string::npos) << what;
        EXPECT_NE(what.find("0.0005"), std::string::npos) << what;
        EXPECT_NE(what.find("deltaT"), std::string::npos) << what;
    }
    EXPECT_THROW(tc.deltaT(0.0, 5e-4), RunError);  // particles sped up during a run
    EXPECT_NO_THROW(tc.checkStable(2e-3, ""));
}

// A material listed in constant/materials that no body uses sets no time step: the silo
// case lists corn and sand, polar and nonpolar, and runs one of them.
TEST(TimeControl, anUnusedMaterialDoesNotShortenTheStableStep)
{
    namespace t = gpic::test;
    t::ScratchDir scratch("unusedMaterial");
    const auto base = scratch.path() / "base", extra = scratch.path() / "extra";
    t::copyCase(t::tutorialPath("verification/elasticBar"), base);
    t::copyCase(t::tutorialPath("verification/elasticBar"), extra);
    {
        std::ofstream m(extra / "constant" / "materials", std::ios::app);
        m << "steel { type linearElastic; rho 7850; E 200e9; nu 0.3; }\n";
    }
    const double dtBase = t::initialisedSimulation(base)->solver().criticalTimeStep();
    const double dtExtra = t::initialisedSimulation(extra)->solver().criticalTimeStep();
    EXPECT_GT(dtBase, 0.0);
    EXPECT_EQ(dtExtra, dtBase);  // steel's wave speed, 5000 times the bar's, would cut it 5000-fold
}
