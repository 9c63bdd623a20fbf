// A restart continues exactly as an uninterrupted run (doc/userGuide/caseLayout.md,
// "Restarts"): the twoDisks case run straight to t = 2 and the same case stopped at t = 1 and
// restarted must end with bitwise identical particles, and the restarted run's
// function-object output must carry on with the same values. The real picInit and picSolver
// run as processes, as a user runs them.
#include "io/ParticlesVtk.H"
#include "particles/Particles.H"
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <algorithm>
#include <cstring>
#include <fstream>

using namespace gpic::test;

namespace {

class Restart : public ::testing::Test {
protected:
    ScratchDir scratch{"restart"};

    //- A copy of twoDisks: dt 1e-3 s, endTime 2 s, written every 0.5 s on the dot; the disks
    //  collide at t = 1.3 s, so the second half of a split run starts from a stressed state.
    fs::path prepare(const std::string& name, bool adjustTimeStep = false)
    {
        const fs::path dir = scratch.path() / name;
        copyCase(tutorialPath("verification/twoDisks"), dir);
        const fs::path control = dir / "system/controlDict";
        setEntry(control, "startFrom", "latestTime");
        setEntry(control, "endTime", "2");
        setEntry(control, "deltaT", "1e-3");
        setEntry(control, "writeControl", "adjustableRunTime");
        setEntry(control, "writeInterval", "0.5");
        if (adjustTimeStep) {
            // deltaT becomes only an upper bound: the Courant number sets every step, so the
            // steps depend on the particle speeds the restart reads back.
            setEntry(control, "deltaT", "1");
            setEntry(control, "adjustTimeStep", "yes");
            setEntry(control, "maxCourant", "0.5");
            // About 130 steps in all: every one of them in bodyMotion.dat.
            replaceText(control, "bodyMotion; writeInterval 10;", "bodyMotion; writeInterval 1;");
        }
        return dir;
    }

    static AppResult run(const std::string& app, const fs::path& dir, const std::string& args = "")
    {
        AppResult r = runApplication(app, dir, args);
        EXPECT_FALSE(r.signalled) << r.command;
        EXPECT_EQ(r.exitCode, 0) << app << " " << args << ": " << r.err;
        return r;
    }

    //- picInit, then picSolver to t = 1 and again (startFrom latestTime) to t = 2.
    void runSplit(const fs::path& dir)
    {
        run("picInit", dir);
        setEntry(dir / "system/controlDict", "endTime", "1");
        run("picSolver", dir);
        ASSERT_TRUE(fs::exists(dir / "1/particles.vtp"));
        ASSERT_FALSE(fs::exists(dir / "1.5"));
        setEntry(dir / "system/controlDict", "endTime", "2");
        const AppResult r = run("picSolver", dir);
        EXPECT_NE(r.out.find("starting at t = 1 (1)"), std::string::npos) << r.out;
    }

    void runStraight(const fs::path& dir)
    {
        run("picInit", dir);
        run("picSolver", dir);
    }
};

gpic::Particles<2> read(const fs::path& file, double& time)
{
    gpic::Particles<2> p;
    gpic::readParticles(file.string(), p, time);
    return p;
}

//- Element by element, comparing the bits (so -0 differs from 0 and NaN equals itself).
template <class T>
void expectBitwiseEqual(const std::vector<T>& a, const std::vector<T>& b, const std::string& name)
{
    ASSERT_EQ(a.size(), b.size()) << name;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::memcmp(&a[i], &b[i], sizeof(T)) != 0) {
            ADD_FAILURE() << name << " differs first at particle " << i << " (of " << a.size() << ")";
            return;
        }
}

void expectSameParticles(const fs::path& fileA, const fs::path& fileB)
{
    SCOPED_TRACE(fileA.string() + " vs " + fileB.string());
    double tA = 0, tB = 0;
    const gpic::Particles<2> a = read(fileA, tA), b = read(fileB, tB);
    EXPECT_EQ(std::memcmp(&tA, &tB, sizeof tA), 0) << tA << " vs " << tB;
    ASSERT_EQ(a.size(), b.size());
    ASSERT_GT(a.size(), 0u);
    expectBitwiseEqual(a.id, b.id, "id");
    expectBitwiseEqual(a.body, b.body, "body");
    expectBitwiseEqual(a.material, b.material, "material");
    expectBitwiseEqual(a.x, b.x, "x");
    expectBitwiseEqual(a.x0, b.x0, "x0");
    expectBitwiseEqual(a.v, b.v, "v");
    expectBitwiseEqual(a.m, b.m, "m");
    expectBitwiseEqual(a.V, b.V, "V");
    expectBitwiseEqual(a.halfSize, b.halfSize, "halfSize");
    expectBitwiseEqual(a.sigma, b.sigma, "sigma");
    expectBitwiseEqual(a.eps, b.eps, "eps");
    expectBitwiseEqual(a.epsP, b.epsP, "epsP");
    expectBitwiseEqual(a.work, b.work, "work");
    ASSERT_EQ(a.historyNames(), b.historyNames());
    for (const auto& h : a.historyNames()) expectBitwiseEqual(a.history(h), b.history(h), h);
}

//- The rows of `restarted` (a run from tRestart to tEnd) are those of `straight` for
//  tRestart < t <= tEnd, column by column: no extra row at the restart (the straight run's
//  row there, if it has one, is in the first part's file).
void expectSameMotion(const fs::path& straightFile, const fs::path& restartedFile, double tRestart,
                      double tEnd)
{
    const auto straight = readColumns(straightFile);
    const auto restarted = readColumns(restartedFile);
    ASSERT_FALSE(restarted.empty()) << restartedFile;
    const auto& tS = straight.at("time");
    const auto& tR = restarted.at("time");
    ASSERT_FALSE(tR.empty());
    EXPECT_GT(tR.front(), tRestart) << "a restart writes no row of its own at its start";
    // Pairs (row of restarted, row of straight) to compare.
    std::vector<std::pair<std::size_t, std::size_t>> rows;
    std::size_t k = 0;
    for (std::size_t s = 0; s < tS.size(); ++s)
        if (tS[s] > tRestart && tS[s] <= tEnd * (1 + 1e-12)) rows.emplace_back(k++, s);
    ASSERT_EQ(k, tR.size()) << "rows after t = " << tRestart << " in " << restartedFile;
    ASSERT_GT(rows.size(), 10u);
    for (const auto& [name, values] : restarted) {
        const auto& reference = straight.at(name);
        for (const auto& [r, s] : rows)
            if (values[r] != reference[s]) {
                ADD_FAILURE() << name << " at t = " << tR[r] << ": restarted " << values[r]
                              << ", straight " << reference[s];
                break;
            }
    }
}

//- The data lines (not '#') of a function object's file.
std::vector<std::string> dataLines(const fs::path& file)
{
    std::vector<std::string> rows;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#') rows.push_back(line);
    return rows;
}

//- The '#' lines of a function object's file.
std::vector<std::string> headerLines(const fs::path& file)
{
    std::vector<std::string> rows;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] == '#') rows.push_back(line);
    return rows;
}

//- A 20 x 20 mm elastic block falling through the outflow bottom of a 40 x 40 mm grid along
//  the side of a fixed post (frictional contact; its first row leaves at 0.021 s), to
//  t = 0.06 s in 600 steps, written every 300 steps; massFlow, bodyMotion, forces, toolWear
//  and toolFill every 70 steps (a restart at step 300 falls between their rows).
void fallingBlockWithEveryFunction(const fs::path& dir)
{
    writeDictionary(dir / "system/controlDict",
                    "startFrom latestTime; endTime 0.06; deltaT 1e-4; writeControl timeStep; writeInterval 300;\n"
                    "functions {\n"
                    "  silo { type massFlow; writeInterval 70; factor 2; region { min (0 0); max (0.04 0.02); } }\n"
                    "  motion { type bodyMotion; writeInterval 70; }\n"
                    "  post { type forces; bodies (post); writeInterval 70; }\n"
                    "  wear { type toolWear; body post; wearCoefficient 1e-3; hardness 1e6; writeInterval 70;\n"
                    "         faces { side { from (0.032 0.006); to (0.032 0.002); } } }\n"
                    "  fill { type toolFill; body post; region { type rectangle; min (0.01 0); max (0.03 0.012); }\n"
                    "         writeInterval 70; }\n}\n");
    writeDictionary(dir / "system/mpmSchemes", "updateScheme MUSL;\n");
    writeDictionary(dir / "constant/grid", "origin (0 0); cellSize 0.002; nCells (20 20);\n"
                                           "boundaries { left { type slip; } right { type slip; } bottom { type outflow; } "
                                           "top { type free; } }\n");
    writeDictionary(dir / "constant/materials", "block { type linearElastic; rho 1000; E 1e5; nu 0.3; }\n"
                                                "steel { type linearElastic; rho 7800; E 2e8; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies",
                    "block { material block; shape { type rectangle; min (0.012 0.0021); max (0.032 0.0221); } "
                    "particlesPerCell 2; }\n"
                    "post { material steel; shape { type rectangle; min (0.032 0.002); max (0.038 0.006); } "
                    "particlesPerCell 2; }\n");
    writeDictionary(dir / "constant/rigidBodies", "post { type fixed; }\n");
    writeDictionary(dir / "constant/g", "value (0 -9.81);\n");
    // Frictional contact with the post: the block slides down its side and wears it.
    writeDictionary(dir / "constant/contactProperties", "law coulombFriction; mu 0.3; normals rigidSurface;\n");
}

} // namespace

TEST_F(Restart, aRunStoppedAndRestartedEndsBitwiseAsTheStraightRun)
{
    const fs::path straight = prepare("straight"), split = prepare("split");
    runStraight(straight);
    runSplit(split);
    for (const char* t : {"0.5", "1", "1.5", "2"})
        expectSameParticles(straight / t / "particles.vtp", split / t / "particles.vtp");
    EXPECT_EQ(readText(straight / "2/uniform/time"), readText(split / "2/uniform/time"));

    // The test means something only if the disks have collided by t = 2 (at t = 1.3 s).
    double t0 = 0, t2 = 0;
    const auto start = read(straight / "0/particles.vtp", t0), end = read(straight / "2/particles.vtp", t2);
    EXPECT_NE(start.v[0], end.v[0]);
    EXPECT_NE(end.sigma[0][0], 0.0);
}

TEST_F(Restart, theRestartedFunctionObjectCarriesOnWithTheSameValues)
{
    const fs::path straight = prepare("straight"), split = prepare("split");
    runStraight(straight);
    runSplit(split);
    expectSameMotion(straight / "postProcessing/motion/0/bodyMotion.dat",
                     split / "postProcessing/motion/1/bodyMotion.dat", 1.0, 2.0);
}

TEST_F(Restart, everyFunctionObjectWritesTheRowsOfTheStraightRun)
{
    // Straight to 0.06 s, and stopped at 0.03 s (step 300, between the rows of steps 280 and
    // 350) and restarted: the two parts' rows together are the straight run's, character for
    // character, for every function object type; massFlow's running totals and rates carry
    // on across the restart.
    const fs::path straight = scratch.path() / "straight", split = scratch.path() / "split";
    fallingBlockWithEveryFunction(straight);
    fallingBlockWithEveryFunction(split);
    runStraight(straight);
    run("picInit", split);
    setEntry(split / "system/controlDict", "endTime", "0.03");
    run("picSolver", split);
    ASSERT_TRUE(fs::exists(split / "0.03/uniform/functionObjects"));
    setEntry(split / "system/controlDict", "endTime", "0.06");
    run("picSolver", split);
    for (const auto& [fn, file] : std::vector<std::pair<std::string, std::string>>{
             {"silo", "massFlow.dat"}, {"motion", "bodyMotion.dat"}, {"post", "forces.dat"}, {"wear", "wear.dat"},
             {"wear", "wearProfile.dat"}, {"fill", "fill.dat"}}) {
        SCOPED_TRACE(fn);
        const auto whole = dataLines(straight / "postProcessing" / fn / "0" / file);
        auto parts = dataLines(split / "postProcessing" / fn / "0" / file);
        const auto second = dataLines(split / "postProcessing" / fn / "0.03" / file);
        ASSERT_FALSE(second.empty());
        parts.insert(parts.end(), second.begin(), second.end());
        ASSERT_EQ(parts.size(), whole.size());
        for (std::size_t k = 0; k < whole.size(); ++k) EXPECT_EQ(parts[k], whole[k]) << "row " << k;
    }
    // The test means something only if mass has gone out before and after the restart.
    const auto flow = readColumns(straight / "postProcessing/silo/0/massFlow.dat");
    const auto& t = flow.at("time");
    const auto& out = flow.at("out");
    ASSERT_GT(t.size(), 5u);
    double outBefore = 0;
    for (std::size_t k = 0; k < t.size(); ++k)
        if (t[k] <= 0.03) outBefore = out[k];
    EXPECT_GT(outBefore, 0.0);
    EXPECT_GT(out.back(), outBefore);
    // ... and only if the post has worn and done work, and the fill has changed, across the restart.
    const auto wear = readColumns(straight / "postProcessing/wear/0/wear.dat");
    const auto fill = readColumns(straight / "postProcessing/fill/0/fill.dat");
    double wornBefore = 0;
    for (std::size_t k = 0; k < wear.at("time").size(); ++k)
        if (wear.at("time")[k] <= 0.03) wornBefore = wear.at("side:volume")[k];
    EXPECT_GT(wornBefore, 0.0);
    EXPECT_GT(wear.at("side:volume").back(), wornBefore);
    EXPECT_NE(fill.at("mass").back(), fill.at("mass").front());
}

TEST_F(Restart, aRestartWithAnAdjustedTimeStepEndsBitwiseAsTheStraightRun)
{
    const fs::path straight = prepare("straight", true), split = prepare("split", true);
    runStraight(straight);
    runSplit(split);
    for (const char* t : {"1.5", "2"})
        expectSameParticles(straight / t / "particles.vtp", split / t / "particles.vtp");
    // Same step count and last step: the restart took the very same steps.
    EXPECT_EQ(readText(straight / "2/uniform/time"), readText(split / "2/uniform/time"));
    expectSameMotion(straight / "postProcessing/motion/0/bodyMotion.dat",
                     split / "postProcessing/motion/1/bodyMotion.dat", 1.0, 2.0);
}

TEST_F(Restart, dashTimeRestartsFromThatTimeDirectory)
{
    // Run to 2, keep a copy of 1/, then rerun from 0.5 to 1 with -time 0.5: latestTime (2)
    // would have nothing to do, so a rewritten 1/ equal to the copy shows the run came from 0.5.
    const fs::path dir = prepare("case");
    runStraight(dir);
    const fs::path kept = scratch.path() / "kept1.vtp";
    fs::copy_file(dir / "1/particles.vtp", kept);
    const std::string at05 = readText(dir / "0.5/particles.vtp");
    const auto mtime05 = fs::last_write_time(dir / "0.5/particles.vtp");
    // The rerun cuts the first run's rows back to 0.5: the straight rows are kept aside.
    const fs::path straightMotion = scratch.path() / "straightMotion.dat";
    fs::copy_file(dir / "postProcessing/motion/0/bodyMotion.dat", straightMotion);

    setEntry(dir / "system/controlDict", "endTime", "1");
    const AppResult r = run("picSolver", dir, "-time 0.5");
    EXPECT_NE(r.out.find("starting at t = 0.5 (0.5)"), std::string::npos) << r.out;
    expectSameParticles(kept, dir / "1/particles.vtp");
    EXPECT_EQ(readText(dir / "0.5/particles.vtp"), at05) << "the start directory is only read";
    EXPECT_TRUE(fs::last_write_time(dir / "0.5/particles.vtp") == mtime05);
    expectSameMotion(straightMotion, dir / "postProcessing/motion/0.5/bodyMotion.dat", 0.5, 1.0);
    EXPECT_LE(readColumns(dir / "postProcessing/motion/0/bodyMotion.dat").at("time").back(), 0.5);
}

TEST_F(Restart, aRestartAfterAKillDropsTheRowsPastItsStartAndATornRow)
{
    // What a run killed (SIGKILL, a power cut) after writing 0.03 leaves: the time directories
    // up to 0.03, and rows past 0.03 in every file, the last one cut mid-line. Made here without
    // a race: the first run goes on to 0.06, then 0.06/ goes and every file gets a torn row
    // ("0.02 1", no newline: it reads as a time before the restart). The restart from 0.03
    // must drop all of that, so that the two parts' rows are the straight run's, character for
    // character, with each file's header lines once.
    const fs::path straight = scratch.path() / "straight", split = scratch.path() / "split";
    fallingBlockWithEveryFunction(straight);
    fallingBlockWithEveryFunction(split);
    runStraight(straight);
    runStraight(split);
    fs::remove_all(split / "0.06");
    const std::vector<std::pair<std::string, std::string>> files{
        {"silo", "massFlow.dat"}, {"motion", "bodyMotion.dat"}, {"post", "forces.dat"},
        {"wear", "wear.dat"},     {"wear", "wearProfile.dat"},  {"fill", "fill.dat"}};
    for (const auto& [fn, file] : files) {
        const fs::path f = split / "postProcessing" / fn / "0" / file;
        ASSERT_GT(dataLines(f).size(), dataLines(straight / "postProcessing" / fn / "0" / file).size() / 2 + 1)
            << "rows past 0.03 to drop in " << f;
        std::ofstream(f, std::ios::app) << "0.02 1";
    }
    const AppResult r = run("picSolver", split);
    EXPECT_NE(r.out.find("starting at t = 0.03 (0.03)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("rows after t = 0.03 s of an earlier run dropped"), std::string::npos) << r.out;
    for (const auto& [fn, file] : files) {
        SCOPED_TRACE(fn + "/" + file);
        const fs::path first = split / "postProcessing" / fn / "0" / file;
        const fs::path second = split / "postProcessing" / fn / "0.03" / file;
        const fs::path whole = straight / "postProcessing" / fn / "0" / file;
        EXPECT_EQ(headerLines(first), headerLines(whole));
        EXPECT_EQ(headerLines(second), headerLines(whole));
        auto parts = dataLines(first);
        const auto later = dataLines(second);
        ASSERT_FALSE(later.empty());
        parts.insert(parts.end(), later.begin(), later.end());
        EXPECT_EQ(parts, dataLines(whole));
    }
}

TEST_F(Restart, aRerunFromAnEarlierTimeLeavesNoRowOfALaterStart)
{
    // Split at 1 and run to 2, then rerun from 0.5 with -time: the rows the first restart
    // wrote (postProcessing/motion/1/) are all after 0.5 and go, header kept, as do those of
    // the first part past 0.5; the rerun's rows carry on from 0.5 as the straight run's.
    const fs::path straight = prepare("straight"), split = prepare("split");
    runStraight(straight);
    runSplit(split);
    run("picSolver", split, "-time 0.5");
    const fs::path later = split / "postProcessing/motion/1/bodyMotion.dat";
    EXPECT_TRUE(dataLines(later).empty()) << "rows left after 0.5 in " << later;
    EXPECT_EQ(headerLines(later), headerLines(straight / "postProcessing/motion/0/bodyMotion.dat"));
    const auto first = readColumns(split / "postProcessing/motion/0/bodyMotion.dat");
    ASSERT_FALSE(first.at("time").empty());
    EXPECT_LE(first.at("time").back(), 0.5);
    expectSameMotion(straight / "postProcessing/motion/0/bodyMotion.dat",
                     split / "postProcessing/motion/0.5/bodyMotion.dat", 0.5, 2.0);
}
