// The thread tuner (libpic/core/ThreadTuner.H) against step times that depend on the count it
// sets: it must settle on the faster count, follow a change of the machine within its
// keeping time, and spend only its trials on the slower count.
#include "core/ThreadTuner.H"

#include <gtest/gtest.h>

#include <functional>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace {

//- Run `steps` steps whose time is stepTime(threads); returns the steps taken at 1 thread.
long drive(gpic::ThreadTuner& tuner, long steps, const std::function<double(int)>& stepTime)
{
    long single = 0;
    for (long s = 0; s < steps; ++s) {
        const int n = tuner.threads();
        if (n == 1) ++single;
        tuner.stepTook(stepTime(n));
    }
    return single;
}

class ThreadTuner : public testing::Test {
protected:
#ifdef _OPENMP
    void TearDown() override { omp_set_num_threads(saved_); }
    int saved_ = omp_get_max_threads();
#endif
};

} // namespace

TEST_F(ThreadTuner, keepsTwoThreadsWhereTheyAreFaster)
{
    gpic::ThreadTuner tuner(2);
    EXPECT_EQ(tuner.threads(), 2);
    // 1 ms a step on 2 threads, 1.6 ms on 1: 20 s of steps.
    const long single = drive(tuner, 15000, [](int n) { return n == 2 ? 1e-3 : 1.6e-3; });
    EXPECT_EQ(tuner.threads(), 2);
    EXPECT_EQ(tuner.mostUsed(), 2);
    // Trials of 1 thread: at least 0.05 s each, one per keeping time (>= 30 trials' worth).
    EXPECT_LT(single, 0.05 * 15000);
    EXPECT_GT(single, 0);
#ifdef _OPENMP
    EXPECT_EQ(omp_get_max_threads(), 2);
#endif
}

TEST_F(ThreadTuner, dropsToOneThreadOnABusyMachineAndComesBack)
{
    gpic::ThreadTuner tuner(2);
    // A competing process: 2 threads wait at every barrier, 10 times slower than 1.
    drive(tuner, 2000, [](int n) { return n == 2 ? 10e-3 : 1e-3; });
    EXPECT_EQ(tuner.threads(), 1);
#ifdef _OPENMP
    EXPECT_EQ(omp_get_max_threads(), 1);
#endif
    // The machine is quiet again: within the keeping time (>= 3 s) and a trial, back to 2.
    drive(tuner, 6000, [](int n) { return n == 2 ? 0.6e-3 : 1e-3; });
    EXPECT_EQ(tuner.threads(), 2);
    EXPECT_NE(tuner.summary().find("thread for"), std::string::npos) << tuner.summary();  // mostly 1
}

TEST_F(ThreadTuner, aTieKeepsTheCountInUse)
{
    gpic::ThreadTuner tuner(2);
    // Within 3 %: no switch for noise.
    drive(tuner, 200, [](int n) { return n == 2 ? 1.00e-3 : 0.98e-3; });
    EXPECT_EQ(tuner.threads(), 2);
}

TEST_F(ThreadTuner, oneCoreHasNothingToTune)
{
    gpic::ThreadTuner tuner(1);
    drive(tuner, 100, [](int) { return 1e-3; });
    EXPECT_EQ(tuner.threads(), 1);
    EXPECT_EQ(tuner.summary(), "1 thread for 100 % of the steps");
}
