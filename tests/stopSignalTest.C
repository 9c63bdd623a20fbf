// A run stopped by SIGTERM (a batch system's kill), SIGINT (Ctrl-C) or SIGHUP (its terminal
// closed) ends cleanly: it
// finishes the step, writes that state as a time directory (listed in the ParaView index),
// leaves no temporary directory, prints one line and exits with 128 + the signal's number;
// a restart goes on from the written state.
#include "io/TimeDirectories.H"
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <regex>
#include <sstream>
#include <thread>

using namespace gpic::test;

namespace {

//- picSolver started in the background on caseDir, its output in files beside the case.
pid_t startSolver(const fs::path& caseDir)
{
    const std::string bin = (fs::path(GPIC_BINARY_DIR) / "bin" / "picSolver").string();
    const std::string out = (caseDir.parent_path() / "picSolver.stdout").string();
    const std::string err = (caseDir.parent_path() / "picSolver.stderr").string();
    const pid_t pid = fork();
    if (pid == 0) {
        const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(o, 1);
        dup2(e, 2);
        execl(bin.c_str(), bin.c_str(), "-case", caseDir.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    return pid;
}

//- Wait for `pid` at most `seconds`; its wait status, or -1 on time-out (then it is killed).
int waitFor(pid_t pid, double seconds)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    int status = 0;
    while (std::chrono::steady_clock::now() < end) {
        if (waitpid(pid, &status, WNOHANG) == pid) return status;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    return -1;
}

//- twoDisks in `dir` (bodyMotion every `motionInterval` steps) with 1e-5 s steps to 3 s
//  (before the disks leave the grid), far longer than a test waits, so that only a signal ends
//  it; picSolver started on it and into the run: its first time directory after 0 written.
//  Returns picSolver's process id, or 0 (with a test failure).
pid_t runningTwoDisks(const fs::path& dir, int motionInterval = 10)
{
    copyCase(tutorialPath("verification/twoDisks"), dir);
    if (motionInterval != 10)
        replaceText(dir / "system/controlDict", "writeInterval 10;", "writeInterval " + std::to_string(motionInterval) + ";");
    setEntry(dir / "system/controlDict", "deltaT", "1e-5");
    setEntry(dir / "system/controlDict", "endTime", "3");
    if (runApplication("picInit", dir).exitCode != 0) {
        ADD_FAILURE() << "picInit failed on " << dir;
        return 0;
    }
    const pid_t pid = startSolver(dir);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!fs::exists(dir / "0.1/uniform/time") && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (!fs::exists(dir / "0.1/uniform/time")) {
        ADD_FAILURE() << "the run never wrote 0.1";
        waitFor(pid, 0);
        return 0;
    }
    return pid;
}

void stopsCleanlyOn(int signal, const std::string& name)
{
    ScratchDir scratch{"stopSignal"};
    const fs::path dir = scratch.path() / "twoDisks";
    const pid_t pid = runningTwoDisks(dir);
    ASSERT_GT(pid, 0);
    ASSERT_EQ(kill(pid, signal), 0);
    const int status = waitFor(pid, 120);
    ASSERT_NE(status, -1) << "picSolver did not stop within 120 s of " << name;
    ASSERT_TRUE(WIFEXITED(status)) << "picSolver died of the signal instead of stopping";
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);

    const std::string err = readText(dir.parent_path() / "picSolver.stderr");
    std::vector<std::string> errors;
    std::istringstream lines(err);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("Warning:", 0) != 0) errors.push_back(line);
    ASSERT_EQ(errors.size(), 1u) << err;
    EXPECT_EQ(errors[0].rfind("Error: run stopped by " + name + " at t = ", 0), 0u) << errors[0];
    // The wall time of the segment, which a run made in segments adds up.
    EXPECT_TRUE(std::regex_search(errors[0], std::regex(R"(\(step [0-9]+, wall [0-9]+\.[0-9] s\))"))) << errors[0];

    // The state written is the latest time directory, named in the message, in the index.
    // On a loaded machine the signal may land while 0.1 is still being finished: then 0.1
    // is the current state and nothing more is written.
    const auto times = gpic::listTimeDirectories(dir.string());
    ASSERT_GE(times.size(), 2u);
    const std::string last = times.back().second;
    EXPECT_NE(errors[0].find("written to " + (dir / last).string()), std::string::npos) << errors[0];
    EXPECT_TRUE(fs::exists(dir / last / "particles.vtp"));
    EXPECT_NE(readText(dir / "twoDisks.pvd").find("\"" + last + "/particles.vtp\""), std::string::npos);
    expectNoTemporaries(dir);

    // A restart carries on from it to a new end.
    const double stopped = times.back().first;
    setEntry(dir / "system/controlDict", "endTime", std::to_string(stopped + 0.05));
    const AppResult restart = runApplication("picSolver", dir);
    EXPECT_EQ(restart.exitCode, 0) << restart.err;
    EXPECT_NE(restart.out.find("starting at t = "), std::string::npos);
    EXPECT_GT(gpic::listTimeDirectories(dir.string()).back().first, stopped);
}

} // namespace

TEST(StopSignal, sigtermWritesTheCurrentStateAndExits143) { stopsCleanlyOn(SIGTERM, "SIGTERM"); }

TEST(StopSignal, sigintWritesTheCurrentStateAndExits130) { stopsCleanlyOn(SIGINT, "SIGINT"); }

TEST(StopSignal, sighupWritesTheCurrentStateAndExits129) { stopsCleanlyOn(SIGHUP, "SIGHUP"); }

TEST(StopSignal, aKilledRunKeepsTheFunctionObjectRowsOfItsLastWrittenState)
{
    // SIGKILL cannot be caught: what survives is what is on disk. The function objects' rows
    // are pushed to their files at every time directory, so those of the newest state written
    // are all there, whole (bodyMotion every 1000 steps of 1e-5 s: a row per 0.01 s, fewer
    // than a file buffer holds).
    ScratchDir scratch{"killed"};
    const fs::path dir = scratch.path() / "twoDisks";
    const pid_t pid = runningTwoDisks(dir, 1000);
    ASSERT_GT(pid, 0);
    ASSERT_EQ(kill(pid, SIGKILL), 0);
    waitFor(pid, 60);

    const double newest = gpic::listTimeDirectories(dir.string()).back().first;
    ASSERT_GE(newest, 0.1);
    const auto rows = readColumns(dir / "postProcessing/motion/0/bodyMotion.dat");
    ASSERT_TRUE(rows.count("time")) << "no rows at all";
    std::size_t upToNewest = 0;
    for (double t : rows.at("time"))
        if (t <= newest + 1e-9) ++upToNewest;
    EXPECT_EQ(upToNewest, static_cast<std::size_t>(std::llround(newest / 0.01)) + 1)
        << "rows up to t = " << newest << " s, the newest state written";
    // Every row up to there is whole: all its columns.
    for (const auto& [name, values] : rows) EXPECT_GE(values.size(), upToNewest) << name;
}

TEST(StopSignal, aKilledRunRestartedWritesTheRowsOfTheStraightRun)
{
    // bodyMotion every 10 steps: a row per 1e-4 s, so that the killed run has pushed rows past
    // its newest time directory out of its file buffer, the last most likely cut mid-line. The
    // restart from the newest state drops them: the first run's rows up to there and the
    // restart's rows are the straight run's, character for character.
    ScratchDir scratch{"killedRestarted"};
    const fs::path dir = scratch.path() / "twoDisks";
    const pid_t pid = runningTwoDisks(dir);
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // well into the next 0.1 s
    ASSERT_EQ(kill(pid, SIGKILL), 0);
    waitFor(pid, 60);

    const auto times = gpic::listTimeDirectories(dir.string());
    const std::string newest = times.back().second;
    const std::string endTime = std::to_string(times.back().first + 0.02);
    setEntry(dir / "system/controlDict", "endTime", endTime);
    const AppResult restart = runApplication("picSolver", dir);
    ASSERT_EQ(restart.exitCode, 0) << restart.err;

    const fs::path straight = scratch.path() / "straight";
    copyCase(tutorialPath("verification/twoDisks"), straight);
    setEntry(straight / "system/controlDict", "deltaT", "1e-5");
    setEntry(straight / "system/controlDict", "endTime", endTime);
    ASSERT_EQ(runApplication("picInit", straight).exitCode, 0);
    ASSERT_EQ(runApplication("picSolver", straight).exitCode, 0);

    const auto lines = [](const fs::path& file) {
        std::vector<std::string> all;
        std::ifstream in(file);
        for (std::string line; std::getline(in, line);) all.push_back(line);
        return all;
    };
    const auto whole = lines(straight / "postProcessing/motion/0/bodyMotion.dat");
    auto parts = lines(dir / "postProcessing/motion/0/bodyMotion.dat");
    ASSERT_GT(parts.size(), 1000u);
    const auto second = lines(dir / "postProcessing/motion" / newest / "bodyMotion.dat");
    ASSERT_GT(second.size(), 100u);
    ASSERT_EQ(second[0][0], '#');
    std::size_t header = 0;
    while (header < second.size() && second[header][0] == '#') ++header;
    parts.insert(parts.end(), second.begin() + static_cast<long>(header), second.end());
    ASSERT_EQ(parts.size(), whole.size());
    for (std::size_t k = 0; k < whole.size(); ++k) ASSERT_EQ(parts[k], whole[k]) << "line " << k;
}
