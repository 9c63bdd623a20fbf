// What a run leaves in the case: time directories at the write times, the ParaView index
// with one part per kind of file, the optional grid, purgeWrite, and the function-object
// file under postProcessing/<name>/<startTime>.
#include "io/GridVtk.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "io/GridVtkRead.H"
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <numeric>

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
        gpic::Particles<2> p;
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
    // ParaView takes the parts from the first time and drops any part it lacks: the start
    // has its grid too, projected from the particles before the first step.
    EXPECT_EQ(grids, 5);
    for (const auto& e : pvd.entries()) EXPECT_TRUE(fs::exists(dir / e.file)) << e.file;
    const auto start = gpic::readGridImage((dir / "0/grid.vti").string());
    vtkDataArray* mass = start->GetPointData()->GetArray("mass");
    ASSERT_NE(mass, nullptr);
    double gridMass = 0;
    for (vtkIdType n = 0; n < mass->GetNumberOfTuples(); ++n) gridMass += mass->GetTuple1(n);
    gpic::Particles<2> p;
    double t = -1;
    gpic::readParticles((dir / "0/particles.vtp").string(), p, t);
    const double particleMass = std::accumulate(p.m.begin(), p.m.end(), 0.0);
    EXPECT_NEAR(gridMass, particleMass, 1e-12 * particleMass);  // lumped mass: partition of unity
}

TEST(Output, aRunWithTheGridStoppedByTheGuardListsItsLastGoodStateWithBothParts)
{
    ScratchDir scratch("gridStop");
    const fs::path dir = twoDisks(scratch);
    setEntry(dir / "system/controlDict", "writeGrid", "yes");
    setEntry(dir / "system/controlDict", "writeInterval", "1");  // nothing written but the start
    // The impact's energy error (0.2 %, seed table 4.3) is far above this bound: it trips.
    std::ofstream(dir / "system/controlDict", std::ios::app) << "stabilityGuard { maxEnergyGain 1e-6; }\n";
    setEntry(dir / "system/controlDict", "endTime", "2");
    EXPECT_THROW(runCase(dir), gpic::RunError);
    const gpic::PvdCollection pvd((dir / "twoDisks.pvd").string());
    ASSERT_GE(pvd.entries().size(), 4u);  // the start and the last good state, two parts each
    for (std::size_t k = 0; k + 1 < pvd.entries().size(); k += 2) {
        EXPECT_EQ(pvd.entries()[k].part, 0);
        EXPECT_EQ(pvd.entries()[k + 1].part, 1);
        EXPECT_EQ(pvd.entries()[k].time, pvd.entries()[k + 1].time);
        EXPECT_TRUE(fs::exists(dir / pvd.entries()[k + 1].file)) << pvd.entries()[k + 1].file;
    }
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

TEST(Output, purgeWriteHoldsAcrossARestart)
{
    // To 0.4 (0, 0.3, 0.4 kept), then restarted to 0.8: the directories of the first run count
    // as the restart's own, so that the case ends as a straight run's, with the start and the
    // last two (0.4, the restart's start, goes too).
    ScratchDir scratch("purgeRestart");
    const fs::path dir = twoDisks(scratch);
    setEntry(dir / "system/controlDict", "purgeWrite", "2");
    runCase(dir);
    setEntry(dir / "system/controlDict", "endTime", "0.8");
    const AppResult r = runApplication("picSolver", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::string> names;
    for (const auto& [t, name] : gpic::listTimeDirectories(dir.string())) names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"0", "0.7", "0.8"}));
    const gpic::PvdCollection pvd((dir / "twoDisks.pvd").string());
    ASSERT_EQ(pvd.entries().size(), 3u);
    EXPECT_EQ(pvd.entries()[1].file, "0.7/particles.vtp");
}

TEST(Output, aWriteIntervalShorterThanTheStepAndThousandsOfDirectoriesAreWarned)
{
    // writeInterval 1e-4 s with steps of 1e-3 s to 1.2 s: every one of 1200 steps written
    // (purgeWrite 1 keeps the disk use small), both said before the first step.
    ScratchDir scratch("writeBudget");
    const fs::path dir = twoDisks(scratch);
    const fs::path control = dir / "system/controlDict";
    setEntry(control, "endTime", "1.2");
    setEntry(control, "writeControl", "runTime");
    setEntry(control, "writeInterval", "1e-4");
    setEntry(control, "purgeWrite", "1");
    ASSERT_EQ(runApplication("picInit", dir).exitCode, 0);
    const AppResult r = runApplication("picSolver", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_EQ(r.warningLines.size(), 2u) << r.err;
    EXPECT_NE(r.warningLines[0].find("writeInterval 0.0001 s is shorter than the time step 0.001 s: every step is "
                                     "written"), std::string::npos) << r.warningLines[0];
    EXPECT_NE(r.warningLines[1].find("the run would write about 1200 time directories"), std::string::npos)
        << r.warningLines[1];
    EXPECT_NE(r.warningLines[1].find("of which purgeWrite keeps 1"), std::string::npos) << r.warningLines[1];
    for (const auto& w : r.warningLines) EXPECT_NE(w.find("system/controlDict:"), std::string::npos) << w;
    EXPECT_EQ(gpic::listTimeDirectories(dir.string()).size(), 2u);
}

TEST(Output, aRunWhoseDirectoriesWouldNotFitOnTheDiskIsRefused)
{
    // adjustableRunTime with writeInterval 1e-12 s: every step cut to 1e-12 s and written,
    // 4e11 directories of some 100 KiB each, far more than any disk: refused before the first step.
    ScratchDir scratch("writeBudgetFull");
    const fs::path dir = twoDisks(scratch);
    const fs::path control = dir / "system/controlDict";
    setEntry(control, "writeControl", "adjustableRunTime");
    setEntry(control, "writeInterval", "1e-12");
    ASSERT_EQ(runApplication("picInit", dir).exitCode, 0);
    const AppResult r = runApplication("picSolver", dir);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    ASSERT_EQ(r.errorLines.size(), 1u) << r.err;
    for (const char* m : {"system/controlDict:", "would write about 400000000000 time directories", "free on",
                          "raise writeInterval or set purgeWrite"})
        EXPECT_NE(r.errorLines[0].find(m), std::string::npos) << m << " not in " << r.errorLines[0];
    EXPECT_EQ(gpic::listTimeDirectories(dir.string()).size(), 1u);
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

namespace {

std::vector<std::string> indexFiles(const fs::path& pvdFile)
{
    std::vector<std::string> files;
    const gpic::PvdCollection pvd(pvdFile.string());
    for (const auto& e : pvd.entries()) files.push_back(e.file);
    return files;
}

int runApp(const std::string& app, const fs::path& dir, const std::string& args, const fs::path& log)
{
    const std::string cmd = std::string(GPIC_BINARY_DIR) + "/bin/" + app + " -case " + dir.string() + " " + args +
                            " > " + log.string() + " 2>&1";
    return std::system(cmd.c_str());
}

} // namespace

// Users copy a case and go on with it: the index the copy brought along is the one ParaView
// opens, so the solver, picListTimes and a restart keep that one instead of starting a
// second index named after the new folder.
TEST(Output, aCopiedAndRenamedCaseGoesOnWithTheIndexItCameWith)
{
    ScratchDir scratch("renamed");
    const fs::path dir = twoDisks(scratch);
    setEntry(dir / "system/controlDict", "endTime", "0.2");
    setEntry(dir / "system/controlDict", "writeGrid", "yes");
    runCase(dir);
    const fs::path copy = scratch.path() / "siloRenamed";
    fs::copy(dir, copy, fs::copy_options::recursive);
    setEntry(copy / "system/controlDict", "endTime", "0.4");
    {
        gpic::RunOptions options;
        options.caseDir = copy.string();
        options.quiet = true;
        gpic::Simulation<2> restarted(options);  // from 0.2, the latest time
        restarted.run();
    }
    EXPECT_FALSE(fs::exists(copy / "siloRenamed.pvd"));
    // Every time once, each with both parts: the restart's start kept its grid.
    std::vector<std::string> expected;
    for (const char* t : {"0", "0.1", "0.2", "0.3", "0.4"})
        for (const char* part : {"/particles.vtp", "/grid.vti"}) expected.push_back(std::string(t) + part);
    EXPECT_EQ(indexFiles(copy / "twoDisks.pvd"), expected);
    ASSERT_EQ(runApp("picListTimes", copy, "-rm", scratch.path() / "rm.log"), 0);
    EXPECT_EQ(indexFiles(copy / "twoDisks.pvd"), (std::vector<std::string>{"0/particles.vtp", "0/grid.vti"}));

    // Two indexes, none named after the folder: which one is meant cannot be guessed.
    fs::copy_file(copy / "twoDisks.pvd", copy / "old.pvd");
    const fs::path log = scratch.path() / "two.log";
    EXPECT_NE(runApp("picSolver", copy, "", log), 0);
    std::ifstream in(log);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("several ParaView indexes (old.pvd, twoDisks.pvd)"), std::string::npos) << text;
}

TEST(Output, picListTimesRebuildWritesTheIndexOfEveryTimeDirectoryOnce)
{
    ScratchDir scratch("rebuild");
    const fs::path dir = twoDisks(scratch);
    setEntry(dir / "system/controlDict", "writeGrid", "yes");
    runCase(dir);
    const gpic::PvdCollection written((dir / "twoDisks.pvd").string());
    fs::remove(dir / "twoDisks.pvd");
    ASSERT_EQ(runApp("picListTimes", dir, "-rebuild", scratch.path() / "rebuild.log"), 0);
    const gpic::PvdCollection rebuilt((dir / "twoDisks.pvd").string());
    ASSERT_EQ(rebuilt.entries().size(), written.entries().size());
    ASSERT_EQ(rebuilt.entries().size(), 10u);  // 5 times, particles and grid
    for (std::size_t k = 0; k < written.entries().size(); ++k) {
        EXPECT_EQ(rebuilt.entries()[k].file, written.entries()[k].file);
        EXPECT_EQ(rebuilt.entries()[k].part, written.entries()[k].part);
        EXPECT_EQ(rebuilt.entries()[k].time, written.entries()[k].time);  // uniform/time's exact value
    }
    // A time without its grid: the rebuilt index lists no grid at all, not a grid at some times.
    fs::remove(dir / "0.3/grid.vti");
    ASSERT_EQ(runApp("picListTimes", dir, "-rebuild", scratch.path() / "rebuild2.log"), 0);
    const gpic::PvdCollection withoutGrid((dir / "twoDisks.pvd").string());
    EXPECT_EQ(withoutGrid.entries().size(), 5u);
    for (const auto& e : withoutGrid.entries()) EXPECT_EQ(e.part, 0);
}

// ParaView's colour bar names a tensor's component by the array's component names, and a
// glyph's scale by a one-component array: the radius of the particle's current area.
TEST(Output, tensorComponentsAreNamedAndTheRadiusFollowsTheVolume)
{
    ScratchDir scratch("names");
    const fs::path dir = twoDisks(scratch);
    setEntry(dir / "system/controlDict", "endTime", "1.6");  // into the impact: the disks compress
    setEntry(dir / "system/controlDict", "writeInterval", "1.6");
    runCase(dir);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((dir / "1.6/particles.vtp").string().c_str());
    reader->Update();
    vtkPointData* pd = reader->GetOutput()->GetPointData();
    for (const char* tensor : {"stress", "strain"}) {
        vtkDataArray* a = pd->GetArray(tensor);
        ASSERT_NE(a, nullptr) << tensor;
        ASSERT_EQ(a->GetNumberOfComponents(), 9);
        const char* expected[9] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
        for (int c = 0; c < 9; ++c) {
            ASSERT_NE(a->GetComponentName(c), nullptr) << tensor << " " << c;
            EXPECT_STREQ(a->GetComponentName(c), expected[c]) << tensor;
        }
    }
    ASSERT_NE(pd->GetArray("velocity")->GetComponentName(1), nullptr);
    EXPECT_STREQ(pd->GetArray("velocity")->GetComponentName(1), "Y");
    vtkDataArray* radius = pd->GetArray("radius");
    vtkDataArray* volume = pd->GetArray("volume");
    ASSERT_NE(radius, nullptr);
    ASSERT_EQ(radius->GetNumberOfComponents(), 1);
    gpic::Particles<2> p0;
    double t = -1;
    gpic::readParticles((dir / "0/particles.vtp").string(), p0, t);
    double largestChange = 0;
    for (vtkIdType q = 0; q < volume->GetNumberOfTuples(); ++q) {
        const double V = volume->GetTuple1(q), r = radius->GetTuple1(q);
        EXPECT_NEAR(3.14159265358979323846 * r * r, V, 1e-12 * V) << q;
        largestChange = std::max(largestChange, std::abs(V / p0.V[static_cast<std::size_t>(q)] - 1.0));
    }
    EXPECT_GT(largestChange, 1e-3);  // the check saw volumes that changed
}
