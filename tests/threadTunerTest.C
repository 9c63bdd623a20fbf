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

//- A quiet machine, and one where another process keeps a core busy.
int quiet() { return 0; }
int oneBusy() { return 1; }

TEST_F(ThreadTuner, keepsTwoThreadsWhereTheyAreFaster)
{
    gpic::ThreadTuner tuner(2, quiet);
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
    gpic::ThreadTuner tuner(2, quiet);
    // Slower on 2 threads (a small scene): 2 threads wait at every barrier, 10 times slower than 1.
    drive(tuner, 2000, [](int n) { return n == 2 ? 10e-3 : 1e-3; });
    EXPECT_EQ(tuner.threads(), 1);
#ifdef _OPENMP
    EXPECT_EQ(omp_get_max_threads(), 1);
#endif
    // Faster on 2 again (the scene grew): within the keeping time (>= 3 s) and a trial, back to 2.
    drive(tuner, 15000, [](int n) { return n == 2 ? 0.6e-3 : 1e-3; });
    EXPECT_EQ(tuner.threads(), 2);
    EXPECT_NE(tuner.summary().find("thread for"), std::string::npos) << tuner.summary();  // mostly 1
}

TEST_F(ThreadTuner, aBusyCoreIsLeftToItsProcessWhateverTheBlocksSay)
{
    // Short blocks on 2 threads can look fast on a busy machine (the scheduler favours a
    // newly busy process at first); the count beyond the free cores is not taken.
    gpic::ThreadTuner tuner(2, oneBusy);
    drive(tuner, 2000, [](int n) { return n == 2 ? 0.5e-3 : 1e-3; });
    EXPECT_EQ(tuner.threads(), 1);
}

TEST_F(ThreadTuner, aTieKeepsTheCountInUse)
{
    gpic::ThreadTuner tuner(2, quiet);
    // Within 3 %: no switch for noise.
    drive(tuner, 1000, [](int n) { return n == 2 ? 1.00e-3 : 0.98e-3; });
    EXPECT_EQ(tuner.threads(), 2);
}

TEST_F(ThreadTuner, otherTasksAreCountedWithoutOurOwn)
{
    // This process runs (at least) this thread: what /proc reports beyond it is the others'.
    const int others = gpic::otherRunnableTasks();
#ifdef __linux__
    EXPECT_GE(others, 0);
#endif
    EXPECT_LT(others, 1000);
}

TEST_F(ThreadTuner, oneCoreHasNothingToTune)
{
    gpic::ThreadTuner tuner(1, quiet);
    drive(tuner, 100, [](int) { return 1e-3; });
    EXPECT_EQ(tuner.threads(), 1);
    EXPECT_EQ(tuner.summary(), "1 thread for 100 % of the steps");
}
