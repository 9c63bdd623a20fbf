// VTK particle/grid files, the ParaView collection and time directories: restart files must
// round-trip bitwise, broken files must give InputError, and directory writes must be atomic.
#include "core/error.H"
#include "grid/Grid.H"
#include "io/GridVtk.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "particles/Particles.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace gpic;

namespace {

//- A fresh directory per test, removed afterwards.
class VtkIo : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path() /
              ("gpic-vtkIoTest-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string file(const std::string& name) const { return (dir / name).string(); }
    fs::path dir;
};

std::uint64_t bits(double x)
{
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

void expectBitwise(const Vector2& a, const Vector2& b)
{
    EXPECT_EQ(bits(a.x()), bits(b.x()));
    EXPECT_EQ(bits(a.y()), bits(b.y()));
}

void expectBitwise(const SymTensor& a, const SymTensor& b)
{
    for (int k = 0; k < 4; ++k) EXPECT_EQ(bits(a[k]), bits(b[k])) << "component " << k;
}

//- Particles whose values do not survive any decimal or single-precision detour.
Particles sampleParticles(std::size_t n = 50)
{
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Particles p;
    for (std::size_t i = 0; i < n; ++i)
        p.add(Vector2(u(rng), u(rng)), 1.0 + u(rng) / 3.0, 0.01 / 3.0, Vector2(0.1 / 3, 0.2 / 7),
              static_cast<int>(i % 3), static_cast<int>(i % 2));
    p.declareHistory("kappa");
    p.declareHistory("damage");
    p.carry(FieldGroup::plasticStrain);
    for (std::size_t i = 0; i < n; ++i) {
        p.id[i] = static_cast<int>(1000 + i);
        p.x0[i] += Vector2(u(rng), u(rng)) * 1e-3;
        p.v[i] = Vector2(u(rng), u(rng)) * 3.141592653589793;
        p.V[i] = std::ldexp(u(rng), -1060);  // subnormal
        p.sigma[i] = SymTensor(u(rng), u(rng), u(rng), u(rng)) * 1e5;
        p.eps[i] = SymTensor(u(rng), u(rng), u(rng), u(rng)) * 1e-3;
        p.epsP[i] = SymTensor(u(rng), u(rng), u(rng), u(rng)) * 1e-7;
        p.history("kappa")[i] = u(rng) / 7.0;
        p.history("damage")[i] = i == 0 ? -0.0 : u(rng);
    }
    return p;
}

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeText(const std::string& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
}

void expectInputError(const std::string& path, const std::string& fragment)
{
    Particles p;
    double time = 0.0;
    try {
        readParticles(path, p, time);
        FAIL() << "expected InputError for " << path;
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_NE(e.message().find(fragment), std::string::npos) << e.what();
    }
}

} // namespace

TEST_F(VtkIo, particlesRoundTripBitwise)
{
    const Particles p = sampleParticles();
    const double time = 0.1 + 0.2;  // 0.30000000000000004
    const std::string path = file("particles.vtp");
    writeParticles(path, p, time, {"sand", "steel"}, {"column", "wall", "floor"});
    EXPECT_FALSE(fs::exists(path + ".tmp"));

    Particles q;
    q.declareHistory("stale");  // replaced, not merged
    double t = 0.0;
    std::vector<std::string> materials, bodies;
    readParticles(path, q, t, &materials, &bodies);

    EXPECT_EQ(bits(t), bits(time));
    EXPECT_EQ(materials, (std::vector<std::string>{"sand", "steel"}));
    EXPECT_EQ(bodies, (std::vector<std::string>{"column", "wall", "floor"}));
    ASSERT_EQ(q.size(), p.size());
    EXPECT_EQ(q.historyNames(), (std::vector<std::string>{"kappa", "damage"}));
    EXPECT_EQ(q.id, p.id);
    EXPECT_EQ(q.body, p.body);
    EXPECT_EQ(q.material, p.material);
    for (std::size_t i = 0; i < p.size(); ++i) {
        expectBitwise(q.x[i], p.x[i]);
        expectBitwise(q.x0[i], p.x0[i]);
        expectBitwise(q.v[i], p.v[i]);
        expectBitwise(q.halfSize[i], p.halfSize[i]);
        EXPECT_EQ(bits(q.m[i]), bits(p.m[i]));
        EXPECT_EQ(bits(q.V[i]), bits(p.V[i]));
        expectBitwise(q.sigma[i], p.sigma[i]);
        expectBitwise(q.eps[i], p.eps[i]);
        expectBitwise(q.epsP[i], p.epsP[i]);
        EXPECT_EQ(bits(q.history("kappa")[i]), bits(p.history("kappa")[i]));
        EXPECT_EQ(bits(q.history("damage")[i]), bits(p.history("damage")[i]));
    }
    EXPECT_EQ(q.dEps.size(), p.size());
    EXPECT_EQ(q.dOmega.size(), p.size());
}

TEST_F(VtkIo, particlesFileLayout)
{
    const std::string path = file("particles.vtp");
    writeParticles(path, sampleParticles(5), 1.5, {"sand"}, {"column"});
    const std::string text = readText(path);
    EXPECT_NE(text.find("type=\"PolyData\""), std::string::npos);
    EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
    EXPECT_NE(text.find("NumberOfVerts=\"5\""), std::string::npos);
    for (const char* array :
         {"Name=\"id\"", "Name=\"velocity\" NumberOfComponents=\"3\"",
          "Name=\"displacement\" NumberOfComponents=\"3\"",
          "Name=\"halfSize\" NumberOfComponents=\"2\"",
          "Name=\"stress\" NumberOfComponents=\"9\"",
          "Name=\"plasticStrain\" NumberOfComponents=\"9\"",
          "Name=\"pressure\"", "Name=\"vonMisesStress\"", "Name=\"kappa\"", "Name=\"TimeValue\"",
          "Name=\"materialNames\"", "Name=\"bodyNames\""})
        EXPECT_NE(text.find(array), std::string::npos) << array;
    EXPECT_NE(text.find("type=\"Int32\" Name=\"id\""), std::string::npos);
    EXPECT_NE(text.find("type=\"Float64\" Name=\"stress\""), std::string::npos);
}

TEST_F(VtkIo, emptyParticlesRoundTrip)
{
    const std::string path = file("empty.vtp");
    writeParticles(path, Particles(), 0.0, {}, {});
    Particles q = sampleParticles(3);
    double t = -1.0;
    readParticles(path, q, t);
    EXPECT_EQ(q.size(), 0u);
    EXPECT_EQ(t, 0.0);
}

TEST_F(VtkIo, historyNamedLikeBuiltinArrayIsRejected)
{
    Particles p = sampleParticles(2);
    p.declareHistory("pressure");
    EXPECT_THROW(writeParticles(file("p.vtp"), p, 0.0, {}, {}), std::logic_error);
    EXPECT_FALSE(fs::exists(file("p.vtp")));
}

TEST_F(VtkIo, missingFileGivesInputError)
{
    expectInputError(file("nothere.vtp"), "cannot read particles");
}

TEST_F(VtkIo, garbageFileGivesInputError)
{
    writeText(file("garbage.vtp"), "this is not XML at all \x01\x02\x03\n<<<<");
    expectInputError(file("garbage.vtp"), "cannot read particles");
    writeText(file("empty.vtp"), "");
    expectInputError(file("empty.vtp"), "cannot read particles");
    writeText(file("wrongType.vtp"),
              "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\"></VTKFile>\n");
    expectInputError(file("wrongType.vtp"), "cannot read particles");
}

TEST_F(VtkIo, truncatedFileGivesInputError)
{
    const std::string good = file("good.vtp");
    writeParticles(good, sampleParticles(), 2.0, {"sand"}, {"column"});
    const std::string text = readText(good);
    const std::string path = file("truncated.vtp");
    // Cut inside the XML header, at the start of the binary data and inside it, up to the
    // last array with data (the point coordinates; only empty cell arrays follow them).
    const std::size_t appended = text.find("<AppendedData encoding=\"raw\">");
    const std::size_t pointsTag = text.find("Name=\"Points\"");
    ASSERT_NE(appended, std::string::npos);
    ASSERT_NE(pointsTag, std::string::npos);
    const std::size_t data = text.find('_', appended) + 1;  // '_' starts the binary block
    const std::size_t offsetAt = text.find("offset=\"", pointsTag) + 8;
    const std::size_t points = data + std::stoul(text.substr(offsetAt));
    for (std::size_t cut : {std::size_t(0), std::size_t(10), appended / 2, appended, data + 40,
                            (data + points) / 2, points + 20, points + 200}) {
        writeText(path, text.substr(0, cut));
        SCOPED_TRACE("cut at " + std::to_string(cut) + " of " + std::to_string(text.size()));
        expectInputError(path, "cannot read particles");
    }
}

TEST_F(VtkIo, corruptHeadersGiveInputError)
{
    // Corruptions that crash VTK 9.1 itself unless caught before it parses the file.
    const std::string good = file("good.vtp");
    writeParticles(good, sampleParticles(8), 0.0, {"sand"}, {"column"});
    const std::string text = readText(good);
    const auto corrupt = [&](const std::string& from, const std::string& to) {
        std::string bad = text;
        const auto at = bad.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        bad.replace(at, from.size(), to);
        writeText(file("bad.vtp"), bad);
        SCOPED_TRACE(from + " -> " + to);
        expectInputError(file("bad.vtp"), "cannot read particles");
    };
    corrupt("type=\"Float64\" Name=\"TimeValue\"", "type=\"Float6@\" Name=\"TimeValue\"");
    corrupt("header_type=\"UInt64\"", "header_type=\"UInt32\"");
    corrupt("header_type=\"UInt64\"", "heaDer_type=\"UInt64\"");
    corrupt("raw\">\n ", "raw\">\n\x19");
    corrupt("NumberOfPoints=\"8\"", "NumberOfPoints=\"9\"");
    // The byte count of the first string array (materialNames, "sand\0" = 5 bytes).
    const std::string count("\x05\0\0\0\0\0\0\0sand", 12);
    corrupt(count, std::string("\x05\0\0\0\0\0\0\x7fsand", 12));
    corrupt(count, std::string("\x04\0\0\0\0\0\0\0sand", 12));
}

TEST_F(VtkIo, missingArrayGivesInputError)
{
    const std::string path = file("p.vtp");
    writeParticles(path, sampleParticles(4), 0.0, {}, {});
    std::string text = readText(path);
    // Same length, so the binary offsets stay valid and only the array is "missing".
    const auto at = text.find("Name=\"mass\"");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 11, "Name=\"mas5\"");
    writeText(path, text);
    expectInputError(path, "missing point array 'mass'");
}

TEST_F(VtkIo, gridFileReadableByVtk)
{
    Grid g(Vector2(-0.5, 1.0), Vector2(0.25, 0.5), 4, 3);
    for (int n = 0; n < g.nNodes(); ++n) {
        g.mass[n] = n;
        g.velocity[n] = Vector2(n, -n);
    }
    const std::string path = file("grid.vti");
    writeGrid(path, g, 0.125);
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    const GridVtkInfo info = readGridInfo(path);
    EXPECT_EQ(info.dimensions, (std::array<int, 3>{5, 4, 1}));
    EXPECT_EQ(info.origin, (std::array<double, 3>{-0.5, 1.0, 0.0}));
    EXPECT_EQ(info.spacing, (std::array<double, 3>{0.25, 0.5, 1.0}));
    EXPECT_EQ(info.time, 0.125);
    EXPECT_EQ(info.pointArrays,
              (std::vector<std::string>{"mass", "velocity", "internalForce", "externalForce"}));

    writeText(file("bad.vti"), "garbage");
    EXPECT_THROW(readGridInfo(file("bad.vti")), InputError);
}

TEST_F(VtkIo, pvdAddReplaceRemoveReload)
{
    const std::string path = file("case.pvd");
    {
        PvdCollection pvd(path);
        EXPECT_TRUE(pvd.entries().empty());
        pvd.add(1.0, "1/particles.vtp");
        pvd.add(0.1, "0.1/particles.vtp");
        pvd.add(0.1, "0.1/grid.vti", 1);
        pvd.add(0.25, "0.25/particles.vtp");
        pvd.add(0.1, "0.1/particlesNew.vtp");  // replaces time 0.1 part 0
        pvd.add(0.1 + 1e-16, "0.1/again.vtp"); // same time within round-off
        ASSERT_EQ(pvd.entries().size(), 4u);
        EXPECT_EQ(pvd.entries()[0].file, "0.1/again.vtp");
        EXPECT_EQ(pvd.entries()[1].file, "0.1/grid.vti");
        EXPECT_EQ(pvd.entries()[1].part, 1);
        EXPECT_EQ(pvd.entries()[3].time, 1.0);
        pvd.write();
    }
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    const std::string text = readText(path);
    EXPECT_EQ(text.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
                         "byte_order=\"LittleEndian\">\n  <Collection>\n",
                         0),
              0u);
    EXPECT_NE(text.find("<DataSet timestep=\"0.25\" group=\"\" part=\"0\" "
                        "file=\"0.25/particles.vtp\"/>"),
              std::string::npos);

    PvdCollection reloaded(path);
    ASSERT_EQ(reloaded.entries().size(), 4u);
    EXPECT_EQ(bits(reloaded.entries()[0].time), bits(0.1));  // the first value is kept
    EXPECT_EQ(reloaded.entries()[0].file, "0.1/again.vtp");
    EXPECT_EQ(bits(reloaded.entries()[1].time), bits(0.1));
    reloaded.removeAfter(0.25 * (1 + 1e-14));  // restart time with round-off keeps 0.25
    ASSERT_EQ(reloaded.entries().size(), 3u);
    EXPECT_EQ(reloaded.entries().back().file, "0.25/particles.vtp");
    reloaded.removeTime(0.1);
    ASSERT_EQ(reloaded.entries().size(), 1u);
    reloaded.write();
    EXPECT_EQ(PvdCollection(path).entries().size(), 1u);
}

TEST_F(VtkIo, pvdReadingIsTolerant)
{
    const std::string path = file("hand.pvd");
    writeText(path, "<VTKFile type='Collection'><Collection>\n"
                    "<DataSet part='2' timestep = '3' file='3/a &amp; b.vtp' />\n"
                    "<DataSet timestep=\"oops\" file=\"x.vtp\"/>\n"
                    "<DataSet timestep=\"1e-3\" file=\"0.001/p.vtp\">\n"
                    "</Collection></VTKFile>\n");
    PvdCollection pvd(path);
    ASSERT_EQ(pvd.entries().size(), 2u);
    EXPECT_EQ(pvd.entries()[0].time, 1e-3);
    EXPECT_EQ(pvd.entries()[0].part, 0);
    EXPECT_EQ(pvd.entries()[1].part, 2);
    EXPECT_EQ(pvd.entries()[1].file, "3/a & b.vtp");
    pvd.write();
    EXPECT_NE(readText(path).find("file=\"3/a &amp; b.vtp\""), std::string::npos);
}

TEST(TimeDirectories, timeName)
{
    EXPECT_EQ(timeName(0.0), "0");
    EXPECT_EQ(timeName(-0.0), "0");
    EXPECT_EQ(timeName(0.1), "0.1");
    EXPECT_EQ(timeName(0.1 + 0.2), "0.3");
    EXPECT_EQ(timeName(1e-5), "1e-05");
    EXPECT_EQ(timeName(1.0), "1");
    EXPECT_EQ(timeName(10.0), "10");
    EXPECT_EQ(timeName(0.25), "0.25");
    EXPECT_EQ(timeName(1234567.0), "1.23457e+06");
    EXPECT_EQ(timeName(1234567.0, 8), "1234567");
    EXPECT_EQ(timeName(0.123456789, 3), "0.123");
}

TEST_F(VtkIo, listTimeDirectoriesSortsNumericNames)
{
    for (const char* d : {"10", "0.25", "1", "0.1", "constant", "system", "postProcessing",
                          ".0.5.tmp", ".hidden", "1abc", "abc", "nan", "inf", "1e-05"})
        fs::create_directory(dir / d);
    writeText(file("2"), "a file, not a directory");
    const auto times = listTimeDirectories(dir.string());
    std::vector<std::string> names;
    for (const auto& [t, name] : times) names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"1e-05", "0.1", "0.25", "1", "10"}));
    EXPECT_EQ(times[2].first, 0.25);
    EXPECT_EQ(latestTime(dir.string()), "10");
    EXPECT_EQ(findTime(dir.string(), 0.25), "0.25");
    EXPECT_EQ(findTime(dir.string(), 0.1 * (1 + 1e-14)), "0.1");
    try {
        findTime(dir.string(), 0.5);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), dir.string());
        EXPECT_NE(e.message().find("1e-05 0.1 0.25 1 10"), std::string::npos) << e.what();
    }
}

TEST_F(VtkIo, latestTimeWithoutTimesThrows)
{
    fs::create_directory(dir / "constant");
    EXPECT_THROW(latestTime(dir.string()), InputError);
    EXPECT_THROW(listTimeDirectories(file("noCase")), InputError);
}

TEST_F(VtkIo, atomicTimeDirectoryWrite)
{
    const std::string caseDir = dir.string();
    writeTimeDirectoryAtomically(caseDir, "0.5", [](const std::string& tmp) {
        EXPECT_NE(tmp.find(".0.5.tmp"), std::string::npos);
        writeText(tmp + "/particles.vtp", "first");
    });
    EXPECT_EQ(readText(file("0.5/particles.vtp")), "first");

    // A failing write leaves the earlier directory as it was and no temporary behind.
    EXPECT_THROW(writeTimeDirectoryAtomically(caseDir, "0.5",
                                              [](const std::string& tmp) {
                                                  writeText(tmp + "/particles.vtp", "partial");
                                                  throw RunError("disk full");
                                              }),
                 RunError);
    EXPECT_EQ(readText(file("0.5/particles.vtp")), "first");
    EXPECT_FALSE(fs::exists(dir / ".0.5.tmp"));
    EXPECT_FALSE(fs::exists(dir / ".0.5.old"));

    // A failing first write leaves nothing.
    EXPECT_THROW(writeTimeDirectoryAtomically(caseDir, "0.75",
                                              [](const std::string&) { throw RunError("x"); }),
                 RunError);
    EXPECT_FALSE(fs::exists(dir / "0.75"));
    EXPECT_FALSE(fs::exists(dir / ".0.75.tmp"));

    // A successful rewrite replaces the whole directory (stale files go).
    writeText(file("0.5/stale"), "old");
    writeTimeDirectoryAtomically(caseDir, "0.5", [](const std::string& tmp) {
        writeText(tmp + "/particles.vtp", "second");
    });
    EXPECT_EQ(readText(file("0.5/particles.vtp")), "second");
    EXPECT_FALSE(fs::exists(dir / "0.5" / "stale"));
    EXPECT_FALSE(fs::exists(dir / ".0.5.old"));
    EXPECT_FALSE(fs::exists(dir / ".0.5.tmp"));
}

TEST_F(VtkIo, removeTimeDirectory)
{
    fs::create_directories(dir / "0.5");
    fs::create_directories(dir / "constant");
    removeTimeDirectory(dir.string(), "0.5");
    EXPECT_FALSE(fs::exists(dir / "0.5"));
    removeTimeDirectory(dir.string(), "0.5");  // absent: nothing to do
    EXPECT_THROW(removeTimeDirectory(dir.string(), "constant"), std::invalid_argument);
    EXPECT_TRUE(fs::exists(dir / "constant"));
}
