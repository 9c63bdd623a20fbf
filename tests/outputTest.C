// What a run leaves in the case: time directories at the write times, the ParaView index
// with one part per kind of file, the optional grid, purgeWrite, and the function-object
// file under postProcessing/<name>/<startTime>.
#include "io/GridVtk.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "support/CaseRunner.H"

using namespace gpic::test;

namespace {

fs::path twoDisks(const ScratchDir& scratch)
{
    const fs::path dir = scratch.path() / "twoDisks";
    copyCase(tutorialPath("verification/twoDisks"), dir);
    setEntry(dir / "system/controlDict", "endTime", "0.4");
    return dir;
}

//- The case holds exactly these time directories, each with the state of the time its name
//  says, and the index lists each once, in order.
void expectTimeDirectories(const fs::path& dir, const std::vector<std::string>& expected)
{
    std::vector<std::string> names;
    for (const auto& [t, name] : gpic::listTimeDirectories(dir.string())) {
        names.push_back(name);
        gpic::Particles p;
        double time = -1;
        gpic::readParticles((dir / name / "particles.vtp").string(), p, time);
        EXPECT_NEAR(time, t, 1e-9) << name;
    }
    EXPECT_EQ(names, expected);
    const gpic::PvdCollection pvd((dir / "twoDisks.pvd").string());
    ASSERT_EQ(pvd.entries().size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_EQ(pvd.entries()[k].file, expected[k] + "/particles.vtp");
}

} // namespace

TEST(Output, writeGridAddsTheGridAsASecondParaViewPart)
{
    ScratchDir scratch("grid");
    const fs::path dir = twoDisks(scratch);
    setEntry(dir / "system/controlDict", "writeGrid", "yes");
    runCase(dir);
    const gpic::GridVtkInfo info = gpic::readGridInfo((dir / "0.2/grid.vti").string());
    EXPECT_EQ(info.dimensions[0], 26);  // 25 x 25 cells
    EXPECT_EQ(info.dimensions[1], 26);
    EXPECT_DOUBLE_EQ(info.spacing[0], 0.04);
    EXPECT_DOUBLE_EQ(info.time, 0.2);
    for (const char* field : {"mass", "velocity"})
        EXPECT_NE(std::find(info.pointArrays.begin(), info.pointArrays.end(), field), info.pointArrays.end())
            << field;
    const gpic::PvdCollection pvd((dir / "twoDisks.pvd").string());
    int particles = 0, grids = 0;
    for (const auto& e : pvd.entries()) (e.part == 0 ? particles : grids)++;
    EXPECT_EQ(particles, 5);  // 0, 0.1, ..., 0.4
    EXPECT_EQ(grids, 4);      // the initial state has no grid
}

TEST(Output, noGridIsWrittenUnlessAskedFor)
{
    ScratchDir scratch("nogrid");
    const fs::path dir = twoDisks(scratch);
    runCase(dir);
    EXPECT_TRUE(fs::exists(dir / "0.4/particles.vtp"));
    EXPECT_FALSE(fs::exists(dir / "0.4/grid.vti"));
    EXPECT_TRUE(fs::exists(dir / "postProcessing/motion/0/bodyMotion.dat"));
}

TEST(Output, purgeWriteKeepsTheStartAndTheLastN)
{
    ScratchDir scratch("purge");
    const fs::path dir = twoDisks(scratch);
    setEntry(dir / "system/controlDict", "purgeWrite", "2");
    runCase(dir);
    std::vector<std::string> names;
    for (const auto& [t, name] : gpic::listTimeDirectories(dir.string())) names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"0", "0.3", "0.4"}));
    const gpic::PvdCollection pvd((dir / "twoDisks.pvd").string());
    ASSERT_EQ(pvd.entries().size(), 3u);
    EXPECT_EQ(pvd.entries()[1].file, "0.3/particles.vtp");
}

TEST(Output, picListTimesRemovesAllButTheStartAndTrimsTheIndex)
{
    ScratchDir scratch("listtimes");
    const fs::path dir = twoDisks(scratch);
    runCase(dir);
    const std::string app = std::string(GPIC_BINARY_DIR) + "/bin/picListTimes -case " + dir.string();
    ASSERT_EQ(std::system((app + " > " + (scratch.path() / "list.txt").string()).c_str()), 0);
    std::ifstream list(scratch.path() / "list.txt");
    std::string names((std::istreambuf_iterator<char>(list)), std::istreambuf_iterator<char>());
    EXPECT_EQ(names, "0\n0.1\n0.2\n0.3\n0.4\n");
    ASSERT_EQ(std::system((app + " -rm > /dev/null").c_str()), 0);
    EXPECT_EQ(gpic::listTimeDirectories(dir.string()).size(), 1u);
    EXPECT_EQ(gpic::PvdCollection((dir / "twoDisks.pvd").string()).entries().size(), 1u);
}

TEST(Output, aTimePrecisionTooShortForTheWritesGetsMoreDigitsAndNoDirectoryIsReplaced)
{
    // timePrecision 1 with writes every 0.05 s: 0.15 would be named "0.2" (then replaced by
    // the state of 0.2). Each time keeps its own directory, named within half a write
    // interval of its time, and the index lists each once.
    ScratchDir scratch("precision");
    const fs::path dir = twoDisks(scratch);
    setEntry(dir / "system/controlDict", "endTime", "0.2");
    setEntry(dir / "system/controlDict", "writeInterval", "0.05");
    setEntry(dir / "system/controlDict", "timePrecision", "1");
    runCase(dir);
    expectTimeDirectories(dir, {"0", "0.05", "0.1", "0.15", "0.2"});
}

TEST(Output, aLastWriteJustAfterAnIntervalWriteMovesThatOneToItsOwnName)
{
    // Writes every 0.0999998 s to endTime 0.2: 0.1999996 is named "0.2" at 6 digits, then the
    // end, 0.2, needs that name: the earlier directory moves to "0.1999996" (index too).
    ScratchDir scratch("lastWrite");
    const fs::path dir = twoDisks(scratch);
    setEntry(dir / "system/controlDict", "endTime", "0.2");
    setEntry(dir / "system/controlDict", "writeInterval", "0.0999998");
    runCase(dir);
    expectTimeDirectories(dir, {"0", "0.0999998", "0.1999996", "0.2"});
}
