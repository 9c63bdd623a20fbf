// Bad input, as a user meets it: the real picInit and picSolver run as processes on a copy of
// the twoDisks tutorial with one defect each. Every defect must give exactly one stderr line
// "Error: ..." (warnings aside) that names the file and line, the keyword and, where there is
// a choice, the valid choices; exit status 1 for bad input and 2 for a failed run, never a
// crash; and the time directories written before stay byte for byte as they were, with no
// temporary directory left behind.
#include "io/ParticlesVtk.H"
#include "particles/Particles.H"
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <unistd.h>

#include <algorithm>

using namespace gpic::test;

namespace {

constexpr int badInput = 1;
constexpr int runFailed = 2;

class BadInput : public ::testing::Test {
protected:
    ScratchDir scratch{"badInput"};
    fs::path dir = scratch.path() / "twoDisks";

    fs::path controlDict() const { return dir / "system/controlDict"; }
    fs::path materials() const { return dir / "constant/materials"; }
    fs::path grid() const { return dir / "constant/grid"; }
    fs::path bodies() const { return dir / "constant/bodies"; }
    fs::path schemes() const { return dir / "system/mpmSchemes"; }

    void SetUp() override
    {
        copyCase(tutorialPath("verification/twoDisks"), dir);
        // Writes 0.1 and 0.2 in 200 steps: a fraction of a second.
        setEntry(controlDict(), "endTime", "0.2");
    }

    //- The case runs as it is: picInit and picSolver succeed, leaving 0, 0.1 and 0.2.
    void startGood()
    {
        for (const char* app : {"picInit", "picSolver"}) {
            const AppResult r = runApplication(app, dir);
            ASSERT_EQ(r.exitCode, 0) << app << ": " << r.err;
        }
        ASSERT_TRUE(fs::exists(dir / "0.2/particles.vtp"));
    }

    //- `app` must refuse the case with exit status `code` and one error line holding each
    //  of `mentions`, and leave the existing time directories as they were.
    AppResult expectRejected(const std::string& app, int code, const std::vector<std::string>& mentions,
                             const std::string& args = "")
    {
        SCOPED_TRACE(app + " " + args);
        const TimeSnapshot before = snapshotTimes(dir);
        const AppResult r = runApplication(app, dir, args);
        EXPECT_FALSE(r.signalled) << "crashed: " << r.command;
        EXPECT_EQ(r.exitCode, code) << r.err;
        EXPECT_EQ(r.errorLines.size(), 1u) << "stderr should be one error line:\n" << r.err;
        if (!r.errorLines.empty()) {
            const std::string& line = r.errorLines.front();
            EXPECT_EQ(line.rfind("Error: ", 0), 0u) << line;
            for (const auto& m : mentions)
                EXPECT_NE(line.find(m), std::string::npos) << "'" << m << "' is not in\n" << line;
        }
        expectTimesUntouched(dir, before);
        expectNoTemporaries(dir);
        return r;
    }

    //- Both applications read this file: both must refuse it with the same message.
    void expectBothReject(const std::vector<std::string>& mentions)
    {
        const AppResult init = expectRejected("picInit", badInput, mentions);
        const AppResult solver = expectRejected("picSolver", badInput, mentions);
        EXPECT_EQ(init.errorLines, solver.errorLines);
    }
};

//- Append `text` as a new last line of `file`; returns its line number.
int appendLine(const fs::path& file, const std::string& text)
{
    std::string s = readText(file);
    if (!s.empty() && s.back() != '\n') s += '\n';
    s += text + '\n';
    std::ofstream(file) << s;
    return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

} // namespace

// --- Syntax ---------------------------------------------------------------------------------

TEST_F(BadInput, aMissingSemicolonIsASyntaxErrorAtItsLine)
{
    startGood();
    replaceText(materials(), "E       1000;", "E       1000");
    expectBothReject({"constant/materials:7:", "'E'", "missing ';'"});
}

TEST_F(BadInput, anUnclosedBraceNamesTheDictionaryLeftOpen)
{
    startGood();
    replaceText(materials(), "nu      0.3;\n}", "nu      0.3;\n");
    expectBothReject({"constant/materials:4:", "'{'", "constant/materials/rubber", "'}'"});
}

TEST_F(BadInput, aStrayClosingBraceIsReportedAtItsLine)
{
    startGood();
    const int line = appendLine(materials(), "}");
    expectBothReject({"constant/materials:" + std::to_string(line) + ":", "'}'"});
}

TEST_F(BadInput, anUnterminatedCommentIsReportedWhereItOpens)
{
    startGood();
    replaceText(materials(), "nu      0.3;", "nu      0.3;  /* Poisson's ratio");
    expectBothReject({"constant/materials:8:", "unterminated comment", "*/"});
}

// --- Files ----------------------------------------------------------------------------------

TEST_F(BadInput, aMissingFileIsNamed)
{
    startGood();
    fs::remove(materials());
    expectBothReject({"constant/materials", "cannot open"});
}

TEST_F(BadInput, aMissingIncludeFileIsNamedAtTheIncludingLine)
{
    startGood();
    replaceText(materials(), "rubber\n{", "#include \"rubberDefaults\"\nrubber\n{");
    expectBothReject({"constant/materials:3:", "#include", "rubberDefaults"});
}

TEST_F(BadInput, aMissingLibraryInLibsIsNamedWithItsLine)
{
    startGood();
    const int line = appendLine(controlDict(), "libs (\"libnotThere.so\");");
    expectBothReject({"system/controlDict:" + std::to_string(line) + ":", "libnotThere.so", "cannot load"});
}

// --- Run-time selection: an unknown type lists the valid ones -------------------------------

TEST_F(BadInput, anUnknownMaterialTypeListsTheValidTypes)
{
    startGood();
    replaceText(materials(), "linearElastic", "linearElastik");
    expectBothReject({"constant/materials:5:", "'linearElastik'", "valid choices:", "linearElastic"});
}

TEST_F(BadInput, anUnknownBoundaryTypeListsTheValidTypes)
{
    // picInit checks the sides too, so the mistake shows before the particles are made.
    startGood();
    replaceText(grid(), "left    { type free; }", "left    { type fre; }");
    expectBothReject({"constant/grid:10:", "'fre'", "boundaries/left", "fixed, free, frictionalWall, guided, outflow, slip, symmetry"});
}

TEST_F(BadInput, anUnknownUpdateSchemeListsTheValidSchemes)
{
    startGood();
    setEntry(schemes(), "updateScheme", "USX");
    expectRejected("picSolver", badInput,
                   {"system/mpmSchemes:3:", "updateScheme", "'USX'", "MUSL, USF, USL"});
}

TEST_F(BadInput, anUnknownShapeFunctionListsTheValidOnes)
{
    startGood();
    setEntry(schemes(), "shapeFunction", "trilinear");
    expectRejected("picSolver", badInput,
                   {"system/mpmSchemes:4:", "shapeFunction", "'trilinear'", "bilinear, quadraticBSpline, uGIMP"});
}

TEST_F(BadInput, aFlipFractionOutsideZeroToOneNamesTheRange)
{
    startGood();
    setEntry(schemes(), "flipFraction", "1.5");
    expectRejected("picSolver", badInput, {"system/mpmSchemes:", "flipFraction", "0 <= flipFraction <= 1"});
}

// The stability guard's settings are read once, with the case: a bad one stops picSolver
// before any step, at its line.
TEST_F(BadInput, aStabilityGuardSettingOutOfRangeNamesTheRequirement)
{
    startGood();
    std::ofstream(controlDict(), std::ios::app) << "stabilityGuard { snapshotInterval 0; }\n";
    expectRejected("picSolver", badInput, {"system/controlDict:", "snapshotInterval", "snapshotInterval >= 1"});
    replaceText(controlDict(), "snapshotInterval 0;", "maxEnergyGain -1;");
    expectRejected("picSolver", badInput, {"system/controlDict:", "maxEnergyGain", "maxEnergyGain > 0"});
}

// Not bad input: a cell size written to ten digits (1/75 m as 0.0133333333) makes the grid
// 2.5e-9 m short of the disk that touches its side; that rounding is accepted.
TEST_F(BadInput, aGridShortOfABodyByRoundingIsAccepted)
{
    setEntry(grid(), "cellSize", "0.0133333333");
    setEntry(grid(), "nCells", "(75 75)");
    const AppResult r = runApplication("picInit", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST_F(BadInput, anUnknownVolumetricStrainWordListsTheValidWords)
{
    startGood();
    setEntry(schemes(), "volumetricStrain", "bBar");
    expectRejected("picSolver", badInput, {"system/mpmSchemes:", "volumetricStrain", "'bBar'", "particle, cellMean"});
}

TEST_F(BadInput, anUnknownBodyShapeListsTheValidShapes)
{
    startGood();
    replaceText(bodies(), "type circle", "type square");
    expectRejected("picInit", badInput,
                   {"constant/bodies:7:", "'square'", "upperLeft/shape", "circle, polygon, rectangle"});
}

TEST_F(BadInput, aSelfIntersectingPolygonNamesTheEdgesThatCross)
{
    startGood();
    // A bow-tie: edges 1 ((0.1 0.6)-(0.3 1)) and 3 ((0.3 0.6)-(0.1 1)) cross at (0.2 0.8).
    replaceText(bodies(), "type circle; centre (0.2 0.8); radius 0.2;",
                "type polygon; points ((0.1 0.6) (0.3 1) (0.3 0.6) (0.1 1));");
    expectRejected("picInit", badInput, {"constant/bodies:7:", "'points'", "upperLeft/shape", "edges 1 and 3 cross"});
}

TEST_F(BadInput, anUnknownStartFromWordListsTheValidWords)
{
    startGood();
    setEntry(controlDict(), "startFrom", "lastTime");
    expectRejected("picSolver", badInput,
                   {"system/controlDict:5:", "startFrom", "'lastTime'", "startTime, firstTime, latestTime"});
}

TEST_F(BadInput, aBodyMaterialNotInConstantMaterialsListsTheMaterials)
{
    startGood();
    replaceText(bodies(), "material         rubber;", "material         rubbr;");
    expectRejected("picInit", badInput,
                   {"constant/bodies:6:", "material", "'rubbr'", "valid choices: rubber"});
}

TEST_F(BadInput, aRenamedMaterialNoLongerMatchingTheParticlesListsTheMaterials)
{
    // The particles of 0.2 carry the material name "rubber": a restart must not guess.
    startGood();
    replaceText(materials(), "rubber\n{", "gum\n{");
    expectRejected("picSolver", badInput,
                   {"0.2/particles.vtp", "'rubber'", "constant/materials", "valid choices: gum"});
}

// --- Values ---------------------------------------------------------------------------------

TEST_F(BadInput, aMissingRequiredKeywordIsNamed)
{
    startGood();
    replaceText(materials(), "    E       1000;       // Pa\n", "");
    expectBothReject({"constant/materials:3:", "'E'", "undefined", "constant/materials/rubber"});
}

TEST_F(BadInput, aNonPositiveYoungsModulusIsRefused)
{
    startGood();
    for (const char* E : {"0", "-1000"}) {
        setEntry(materials(), "E", E);
        expectBothReject({"constant/materials:7:", "'E'", "E > 0"});
    }
}

TEST_F(BadInput, aPoissonRatioOutsideMinusOneToOneHalfIsRefused)
{
    // 0.5 makes the bulk modulus infinite, -1 the shear modulus.
    startGood();
    for (const char* nu : {"0.5", "0.7", "-1", "-1.5"}) {
        setEntry(materials(), "nu", nu);
        expectBothReject({"constant/materials:8:", "'nu'", "-1 < nu < 0.5"});
    }
}

TEST_F(BadInput, aNonPositiveDensityIsRefused)
{
    startGood();
    for (const char* rho : {"0", "-1000"}) {
        setEntry(materials(), "rho", rho);
        expectBothReject({"constant/materials:6:", "'rho'", "rho > 0"});
    }
}

TEST_F(BadInput, aWordWhereANumberBelongsIsRefused)
{
    startGood();
    setEntry(controlDict(), "endTime", "four");
    expectRejected("picSolver", badInput, {"system/controlDict:8:", "endTime", "'four'", "number"});
}

TEST_F(BadInput, aVectorOfTheWrongSizeIsRefused)
{
    startGood();
    for (const char* size : {"(1 2 3)", "(1 2 3 4)", "(1)"}) {
        setEntry(grid(), "cellSize", size);
        expectBothReject({"constant/grid:4:", "cellSize", size});
    }
}

TEST_F(BadInput, aNonPositiveWriteIntervalIsRefused)
{
    startGood();
    for (const char* interval : {"0", "-0.1"}) {
        setEntry(controlDict(), "writeInterval", interval);
        expectRejected("picSolver", badInput,
                       {"system/controlDict:11:", "writeInterval", "writeInterval > 0"});
    }
}

TEST_F(BadInput, aBodyReachingOutsideTheGridIsRefused)
{
    startGood();
    replaceText(bodies(), "centre (0.8 0.2)", "centre (0.9 0.2)");
    expectRejected("picInit", badInput,
                   {"constant/bodies:15:", "shape", "'lowerRight'", "outside the grid", "(1.1 0.4)"});
}

TEST_F(BadInput, twoBodiesThatOverlapAreRefusedNamingBoth)
{
    // The lower disk moved to (0.45 0.55): 0.354 m from the upper one's centre, less than the
    // sum of the radii (0.4 m).
    replaceText(bodies(), "centre (0.8 0.2)", "centre (0.45 0.55)");
    expectRejected("picInit", badInput,
                   {"constant/bodies:15:", "shape", "body 'lowerRight' overlaps body 'upperLeft'", "particles lie inside"});
}

TEST_F(BadInput, twoBodiesThatOnlyTouchAreAccepted)
{
    // Centres 0.4 m apart on a line through sub-cell corners: the disks touch at (0.5 0.8).
    replaceText(bodies(), "centre (0.8 0.2)", "centre (0.6 0.8)");
    const AppResult r = runApplication("picInit", dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST_F(BadInput, aGridTooLargeToNumberIsRefusedNamingNCells)
{
    // 200 000 x 200 000 cells have 4e10 nodes: beyond an int's numbering, whatever the memory.
    startGood();
    setEntry(grid(), "nCells", "(200000 200000)");
    expectBothReject({"constant/grid:5:", "nCells", "200000 x 200000 cells", "40000400001 nodes"});
}

TEST_F(BadInput, aGridBeyondTheMachinesMemoryIsRefusedBeforeAllocating)
{
    // 46 000 x 46 000 cells: 2.1e9 nodes (an int can number them) need about 197 GB.
    const double have = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    if (have > 190e9) GTEST_SKIP() << "this machine could hold the grid";
    startGood();
    setEntry(grid(), "nCells", "(46000 46000)");
    expectBothReject({"constant/grid:5:", "nCells", "46000 x 46000 cells", "need at least 197 GB", "this machine has"});
}

TEST_F(BadInput, aFixedTimeStepAboveTheStabilityLimitGivesTheLimit)
{
    // h / (c + |v|) = 0.04 / (1.16024 + 0.141421) = 0.03073 s, with the P-wave speed
    // c = sqrt((K + 4G/3) / rho) of E = 1000 Pa, nu = 0.3, rho = 1000 and |v| = 0.1 sqrt(2).
    startGood();
    setEntry(controlDict(), "deltaT", "0.1");
    expectRejected("picSolver", badInput,
                   {"system/controlDict:9:", "deltaT", "stability limit 0.03073 s", "adjustTimeStep"});
    EXPECT_FALSE(fs::exists(dir / "0.3")) << "no step may be taken";
}

// --- Time directories -----------------------------------------------------------------------

TEST_F(BadInput, anUnreadableLatestTimeDirectoryIsNamed)
{
    startGood();
    std::ofstream(dir / "0.2/particles.vtp") << "garbage\n";
    expectRejected("picSolver", badInput, {"0.2/particles.vtp", "cannot read particles"});
}

TEST_F(BadInput, aFullDiskIsSaidWithThePathAndLeavesTheEarlierTimes)
{
    // The case on a 400 kB file system: room for the case and 0/ (about 190 kB), not for 0.1/.
    const fs::path mount = scratch.path() / "small";
    fs::create_directories(mount);
    if (std::system(("mount -t tmpfs -o size=400k tmpfs '" + mount.string() + "' 2> /dev/null").c_str()) != 0)
        GTEST_SKIP() << "cannot mount a small tmpfs here (needs root)";
    struct Unmount {
        fs::path at;
        ~Unmount() { (void)std::system(("umount '" + at.string() + "'").c_str()); }
    } unmount{mount};
    const fs::path small = mount / "twoDisks";
    fs::copy(dir, small, fs::copy_options::recursive);
    dir = small;
    ASSERT_EQ(runApplication("picInit", dir).exitCode, 0);
    // Fill what is left but a little: the next time directory cannot fit.
    const auto left = fs::space(mount).available;
    if (left > 64 * 1024) std::ofstream(mount / "filler") << std::string(left - 64 * 1024, 'x');
    const AppResult r = expectRejected("picSolver", runFailed, {"no space left on device", dir.string()});
    EXPECT_EQ(r.err.find("vtk"), std::string::npos) << "VTK's own log: " << r.err;
    EXPECT_TRUE(fs::exists(dir / "0/particles.vtp"));
}

TEST_F(BadInput, scrambledBytesInsideAParticleFileFailItsChecksum)
{
    // 200 bytes in the middle of the raw appended data: VTK reads them as numbers.
    startGood();
    const fs::path file = dir / "0.2/particles.vtp";
    std::string bytes = readText(file);
    const std::size_t middle = bytes.size() / 2;
    for (std::size_t k = 0; k < 200; ++k) bytes[middle + k] = static_cast<char>(bytes[middle + k] ^ 0x5a);
    std::ofstream(file, std::ios::binary) << bytes;
    expectRejected("picSolver", badInput, {"0.2/particles.vtp", "cannot read particles", "checksum", "damaged"});
}

TEST_F(BadInput, aBrokenTimeFileIsNamedWithItsLine)
{
    startGood();
    std::ofstream(dir / "0.2/uniform/time") << "value 0.2;\nindex {\n";
    expectRejected("picSolver", badInput, {"0.2/uniform/time:2:", "'{'"});
}

// --- A damaged restart: the start directory's name, its particles' time and uniform/time must
// agree, and a directory picSolver wrote must still hold uniform/ and a checksummed particle file.

TEST_F(BadInput, aRestartFromAnEditedTimeFileIsRefused)
{
    startGood();
    const fs::path time = dir / "0.2/uniform/time";
    std::string text = readText(time);
    const std::size_t value = text.find("value");
    ASSERT_NE(value, std::string::npos) << text;
    text.replace(value, text.find(';', value) - value, "value   0.25");
    std::ofstream(time) << text;
    expectRejected("picSolver", badInput, {"0.2/particles.vtp", "its time 0.2", "0.2/uniform/time's 0.25"});
}

TEST_F(BadInput, aRestartFromADirectoryNamedForAnotherTimeIsRefused)
{
    // 0.2/ renamed 1e308: the latest time by its name, holding the state of t = 0.2 s.
    startGood();
    fs::rename(dir / "0.2", dir / "1e308");
    expectRejected("picSolver", badInput, {"1e308/particles.vtp", "its time 0.2", "directory 1e308"});
}

TEST_F(BadInput, aRestartWithoutUniformIsAnErrorNotAFreshStart)
{
    // Without uniform/ the run would start over (a silo its fill stage) from particles of 0.2 s.
    startGood();
    fs::remove_all(dir / "0.2/uniform");
    expectRejected("picSolver", badInput, {"0.2/uniform/time", "missing"});
}

TEST_F(BadInput, aRestartFromAParticleFileWithoutItsChecksumIsRefused)
{
    // The checksum's field array renamed: the file reads as one written without a checksum.
    startGood();
    const fs::path file = dir / "0.2/particles.vtp";
    std::string bytes = readText(file);
    const std::size_t at = bytes.find("Name=\"checksum\"");
    ASSERT_NE(at, std::string::npos);
    bytes.replace(at, 15, "Name=\"checksun\"");
    std::ofstream(file, std::ios::binary) << bytes;
    expectRejected("picSolver", badInput, {"0.2/particles.vtp", "cannot read particles", "no checksum"});
}

TEST_F(BadInput, theSolverBeforePicInitFindsNoTimeDirectoryWhateverStartFrom)
{
    // No startGood: the case has no time directory at all.
    for (const char* from : {"latestTime", "firstTime", "startTime"}) {
        setEntry(controlDict(), "startFrom", from);
        expectRejected("picSolver", badInput, {dir.string() + ": ", "no time director"});
    }
}

TEST_F(BadInput, aStartTimeWithoutItsDirectoryListsTheAvailableTimes)
{
    // The time itself is printed with 17 digits ("0.29999999999999999", libpic/io's
    // findTime), so only the words and the list are checked here.
    startGood();
    expectRejected("picSolver", badInput,
                   {"no time directory for time 0.", "available times: 0 0.1 0.2"}, "-time 0.3");
}

// --- Command line ---------------------------------------------------------------------------

TEST_F(BadInput, anUnknownCommandLineOptionIsRefused)
{
    startGood();
    expectRejected("picInit", badInput, {"command line", "unrecognised option '-bogus'", "-help"}, "-bogus");
    expectRejected("picSolver", badInput, {"command line", "unrecognised option '--nope'", "-help"},
                   "--nope");
    expectRejected("picSolver", badInput, {"command line", "'abc'", "time"}, "-time abc");
}

// --- Warnings -------------------------------------------------------------------------------

TEST_F(BadInput, aMistypedKeywordIsAWarningWithItsLineAndTheRunGoesOn)
{
    replaceText(materials(), "nu      0.3;", "nu      0.3;\n    nuu     0.3;");
    setEntry(controlDict(), "endTime", "0.1");
    for (const char* app : {"picInit", "picSolver"}) {
        SCOPED_TRACE(app);
        const AppResult r = runApplication(app, dir);
        EXPECT_FALSE(r.signalled);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(r.errorLines.empty()) << r.err;
        ASSERT_EQ(r.warningLines.size(), 1u) << r.err;
        const std::string& w = r.warningLines.front();
        EXPECT_EQ(w.rfind("Warning: constant/materials:9:", 0), 0u) << w;
        EXPECT_NE(w.find("'nuu'"), std::string::npos) << w;
        EXPECT_NE(w.find("not used"), std::string::npos) << w;
    }
    EXPECT_TRUE(fs::exists(dir / "0.1/particles.vtp"));
}

TEST_F(BadInput, picInitOverTheResultsOfARunIsRefusedUnlessAskedToOverwrite)
{
    startGood();
    // A new start beside 0.1 and 0.2 would be continued from them by picSolver.
    expectRejected("picInit", badInput, {"0.1, 0.2", "earlier run", "picInit -overwrite"});
    const AppResult r = runApplication("picInit", dir, "-overwrite");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "0/particles.vtp"));
    EXPECT_FALSE(fs::exists(dir / "0.1"));
    EXPECT_FALSE(fs::exists(dir / "0.2"));
    expectNoTemporaries(dir);
}

// --- Run failures (exit 2): the run stops, what was written before stays ---------------------

TEST_F(BadInput, aParticleLeavingTheGridStopsTheRunAndKeepsEarlierTimes)
{
    // Strong gravity pulls the lower disk, which touches the free bottom side, out of the grid.
    startGood();
    std::ofstream(dir / "constant/g") << "value (0 -100);\n";
    setEntry(controlDict(), "endTime", "4");
    expectRejected("picSolver", runFailed, {"run stopped", "particle", "outside the grid"});
}

TEST_F(BadInput, particlesSpeedingPastAFixedStepStopTheRunWithTheLimit)
{
    // deltaT 0.025 s is stable at the start (limit 0.0307 s) but not once gravity (from
    // t = 0.2) has sped the upper disk past 0.44 m/s: the run writes 0.3 to 0.5 and stops at
    // t = 0.55, before its step.
    startGood();
    std::ofstream(dir / "constant/g") << "value (0 -1);\n";
    setEntry(controlDict(), "deltaT", "0.025");
    setEntry(controlDict(), "endTime", "4");
    expectRejected("picSolver", runFailed,
                   {"run stopped", "at time 0.55", "stability limit", "deltaT"});
    // The time directories of the failed run are complete.
    for (const char* t : {"0.3", "0.4", "0.5"}) {
        gpic::Particles<2> p;
        double time = 0;
        EXPECT_NO_THROW(gpic::readParticles((dir / t / "particles.vtp").string(), p, time)) << t;
        EXPECT_EQ(p.size(), 632u) << t;
    }
    EXPECT_FALSE(fs::exists(dir / "0.6"));
}

TEST(RepeatedNames, aBodyNamedTwiceIsRefusedNotMergedIntoOne)
{
    // Two sub-dictionaries of one name are merged (OpenFOAM's rule): in constant/bodies that
    // silently lost a body (316 particles of 632). picInit refuses it at the second, naming
    // the first; constant/materials and constant/rigidBodies alike.
    ScratchDir scratch{"repeatedBody"};
    const fs::path dir = scratch.path() / "disks";
    copyCase(tutorialPath("verification/twoDisks"), dir);
    replaceText(dir / "constant/bodies", "lowerRight", "upperLeft");
    std::string message;
    try {
        gpic::initialiseCase(dir.string());
    } catch (const gpic::InputError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("constant/bodies:"), std::string::npos) << message;
    EXPECT_NE(message.find("body 'upperLeft' is given twice"), std::string::npos) << message;
    EXPECT_NE(message.find("(first at line"), std::string::npos) << message;
    EXPECT_FALSE(fs::exists(dir / "0")) << "nothing written";
}
