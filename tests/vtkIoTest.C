// VTK particle/grid files, the ParaView collection and time directories: restart files must
// round-trip bitwise, particle files must be the bytes VTK's own writer wrote and read back
// in VTK's reader, broken files must give InputError, and directory writes must be atomic.
#include "core/error.H"
#include "grid/Grid.H"
#include "io/GridVtk.H"
#include "io/ParticlesVtk.H"
#include "io/PvdCollection.H"
#include "io/TimeDirectories.H"
#include "io/VtkErrorGuard.H"
#include "particles/ParticleFields.H"
#include "particles/Particles.H"
#include "support/ReferenceParticlesWriter.H"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
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
#include <variant>

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
    //- Writes `p` with writeParticles and with VTK's writer; the files must be the same bytes.
    void expectBytesOfVtksWriter(const Particles<2>& p, const std::string& name, double time = 0.1 + 0.2,
                                 const std::vector<std::string>& materials = {"sand", "steel"},
                                 const std::vector<std::string>& bodies = {"column", "wall", "floor"});
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
Particles<2> sampleParticles(std::size_t n = 50)
{
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Particles<2> p;
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

void VtkIo::expectBytesOfVtksWriter(const Particles<2>& p, const std::string& name, double time,
                                    const std::vector<std::string>& materials,
                                    const std::vector<std::string>& bodies)
{
    const std::string ours = file(name + ".vtp"), vtks = file(name + "-vtk.vtp");
    writeParticles(ours, p, time, materials, bodies);
    reference::writeParticlesWithVtk(vtks, p, time, materials, bodies);
    const std::string a = readText(ours), b = readText(vtks);
    const auto [at, _] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
    const std::size_t k = static_cast<std::size_t>(at - a.begin());
    const auto near = [k](const std::string& text) {
        const std::size_t from = k < 60 ? 0 : k - 60;
        return text.substr(from, 120);
    };
    EXPECT_TRUE(a == b) << name << ": " << a.size() << " bytes against VTK's " << b.size()
                        << ", first difference at byte " << k << "\nours: " << near(a) << "\nVTK's: " << near(b);
}

//- A value no decimal or single-precision detour keeps, of magnitude near 10^decade.
double awkward(std::mt19937_64& rng, int decade)
{
    return std::uniform_real_distribution<double>(-1, 1)(rng) * 3.141592653589793 * std::pow(10.0, decade);
}

void fill(int& v, std::mt19937_64& rng, int) { v = static_cast<int>(rng() % 200001) - 100000; }
void fill(double& v, std::mt19937_64& rng, int decade) { v = awkward(rng, decade); }
template <class M> void fill(Eigen::MatrixBase<M>& v, std::mt19937_64& rng, int decade)
{
    for (Eigen::Index k = 0; k < v.size(); ++k) v(k) = awkward(rng, decade);
}

//- n particles carrying `groups` and `history`, every state array filled, each at its own scale.
Particles<2> particlesWith(std::size_t n, const std::vector<FieldGroup>& groups,
                        const std::vector<std::string>& history = {})
{
    Particles<2> p;
    for (FieldGroup g : groups) p.carry(g);
    p.resize(n);
    for (const auto& name : history) p.declareHistory(name);
    std::mt19937_64 rng(n + 17 * groups.size());
    int decade = -9;
    for (const ParticleField<2>& f : particleFields<2>()) {
        decade = decade < 6 ? decade + 3 : -8;
        if (!f.array || f.role != FieldRole::state || !p.carries(f.group)) continue;
        std::visit([&](auto* a) { for (auto& v : *a) fill(v, rng, decade); }, f.array(p));
    }
    for (const auto& name : history)
        for (double& v : p.history(name)) v = awkward(rng, -2);
    return p;
}

void expectInputError(const std::string& path, const std::string& fragment)
{
    Particles<2> p;
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
    const Particles<2> p = sampleParticles();
    const double time = 0.1 + 0.2;  // 0.30000000000000004
    const std::string path = file("particles.vtp");
    writeParticles(path, p, time, {"sand", "steel"}, {"column", "wall", "floor"});
    EXPECT_FALSE(fs::exists(path + ".tmp"));

    Particles<2> q;
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
    writeParticles(path, Particles<2>(), 0.0, {}, {});
    Particles<2> q = sampleParticles(3);
    double t = -1.0;
    readParticles(path, q, t);
    EXPECT_EQ(q.size(), 0u);
    EXPECT_EQ(t, 0.0);
}

TEST_F(VtkIo, particleFilesAreTheBytesOfVtksWriterForEveryGroup)
{
    using G = FieldGroup;
    expectBytesOfVtksWriter(particlesWith(40, {}), "plain");
    expectBytesOfVtksWriter(particlesWith(40, {G::plasticStrain}), "plasticStrain");
    expectBytesOfVtksWriter(particlesWith(40, {G::affine}), "affine");
    expectBytesOfVtksWriter(particlesWith(40, {G::polar}), "cosserat");
    expectBytesOfVtksWriter(particlesWith(40, {}, {"kappa", "damage"}), "history");
    expectBytesOfVtksWriter(particlesWith(40, {G::plasticStrain, G::affine, G::polar}, {"kappa"}), "everything");
    expectBytesOfVtksWriter(Particles<2>(), "empty", 0.0, {}, {});
    expectBytesOfVtksWriter(particlesWith(0, {G::polar}, {"kappa"}), "emptyWithGroups");
    expectBytesOfVtksWriter(particlesWith(1, {G::plasticStrain}, {"kappa"}), "one");
    expectBytesOfVtksWriter(sampleParticles(), "sample");
}

TEST_F(VtkIo, particleFilesAreTheBytesOfVtksWriterForAwkwardValuesAndManyParticles)
{
    // Enough particles that every array goes through the writer's buffer in several pieces
    // and VTK computes its ranges in parallel chunks.
    Particles<2> p = particlesWith(20011, {FieldGroup::plasticStrain, FieldGroup::polar}, {"kappa"});
    expectBytesOfVtksWriter(p, "many", 1e-300, {"", "s\xc3\xa4nd", "a b"}, {"x"});

    // What the ranges of the header make of NaN, infinities, values beyond VTK's 1e299 of an
    // empty range, magnitudes whose square overflows, subnormals and negative zeros.
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.m[i] = i % 7 == 3 ? nan : p.m[i];                   // NaNs among values
        p.V[i] = i == 5 ? inf : i == 9 ? -inf : p.V[i];       // both infinities
        p.work[i] = 1e300 * (1.0 + static_cast<double>(i));   // all beyond 1e299
        p.v[i] = i == 2 ? Vector2(1e200, 1.0) : i == 4 ? Vector2(nan, 1.0) : p.v[i];
        p.halfSize[i] = Vector2(4.9e-324, -4.9e-324) * static_cast<double>(i % 3 + 1);
        p.history("kappa")[i] = -0.0;
        p.polar.w[i] = nan;                                    // nothing but NaN
        p.polar.mu[i] = Vector2(nan, 0.0);                     // no magnitude but NaN
        p.sigma[i] = SymTensor::Zero();                        // pressure -0 everywhere
    }
    expectBytesOfVtksWriter(p, "awkward", std::nextafter(0.0, 1.0));
    for (std::size_t i = 0; i < p.size(); ++i) p.x[i] = Vector2(inf, -1.0);
    expectBytesOfVtksWriter(p, "infinitePoints", -inf);
}

TEST_F(VtkIo, vtksReaderReadsTheParticleFileAsItReadTheFileOfVtksWriter)
{
    // ParaView reads the file with vtkXMLPolyDataReader: what it reads must be what it read
    // from VTK's writer, and be the particles.
    const Particles<2> p = particlesWith(300, {FieldGroup::plasticStrain, FieldGroup::affine, FieldGroup::polar},
                                      {"kappa", "damage"});
    writeParticles(file("ours.vtp"), p, 2.5, {"sand", "steel"}, {"column"});
    reference::writeParticlesWithVtk(file("vtks.vtp"), p, 2.5, {"sand", "steel"}, {"column"});
    const auto read = [](const std::string& path) {
        auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
        vtkNew<gpic::detail::ErrorCollector> errors;
        reader->AddObserver(vtkCommand::ErrorEvent, errors);
        reader->SetFileName(path.c_str());
        reader->Update();
        EXPECT_FALSE(errors->failed) << errors->first;
        return vtkSmartPointer<vtkPolyData>(reader->GetOutput());
    };
    const auto ours = read(file("ours.vtp")), vtks = read(file("vtks.vtp"));
    const auto sameArray = [](vtkAbstractArray* a, vtkAbstractArray* b, const std::string& what) {
        ASSERT_NE(a, nullptr) << what;
        ASSERT_NE(b, nullptr) << what;
        EXPECT_STREQ(a->GetName(), b->GetName()) << what;
        EXPECT_EQ(a->GetDataType(), b->GetDataType()) << what;
        EXPECT_EQ(a->GetNumberOfComponents(), b->GetNumberOfComponents()) << what;
        ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues()) << what;
        for (int c = 0; c < a->GetNumberOfComponents(); ++c)
            EXPECT_STREQ(a->GetComponentName(c), b->GetComponentName(c)) << what << " component " << c;
        if (auto* s = vtkStringArray::SafeDownCast(a)) {
            for (vtkIdType k = 0; k < s->GetNumberOfValues(); ++k)
                EXPECT_EQ(s->GetValue(k), vtkStringArray::SafeDownCast(b)->GetValue(k)) << what;
            return;
        }
        EXPECT_EQ(std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
                              static_cast<std::size_t>(a->GetNumberOfValues() * a->GetDataTypeSize())),
                  0)
            << what;
    };
    ASSERT_EQ(ours->GetNumberOfPoints(), 300);
    ASSERT_EQ(ours->GetNumberOfVerts(), 300);
    sameArray(ours->GetPoints()->GetData(), vtks->GetPoints()->GetData(), "points");
    sameArray(ours->GetVerts()->GetConnectivityArray(), vtks->GetVerts()->GetConnectivityArray(), "connectivity");
    sameArray(ours->GetVerts()->GetOffsetsArray(), vtks->GetVerts()->GetOffsetsArray(), "offsets");
    ASSERT_EQ(ours->GetPointData()->GetNumberOfArrays(), vtks->GetPointData()->GetNumberOfArrays());
    for (int k = 0; k < ours->GetPointData()->GetNumberOfArrays(); ++k)
        sameArray(ours->GetPointData()->GetAbstractArray(k), vtks->GetPointData()->GetAbstractArray(k),
                  ours->GetPointData()->GetArrayName(k));
    ASSERT_EQ(ours->GetFieldData()->GetNumberOfArrays(), 4);
    for (int k = 0; k < 4; ++k)
        sameArray(ours->GetFieldData()->GetAbstractArray(k), vtks->GetFieldData()->GetAbstractArray(k),
                  ours->GetFieldData()->GetAbstractArray(k)->GetName());

    // And the values are the particles', in ParaView's layout.
    vtkPointData* pd = ours->GetPointData();
    EXPECT_EQ(ours->GetFieldData()->GetArray("TimeValue")->GetComponent(0, 0), 2.5);
    for (vtkIdType i : {vtkIdType(0), vtkIdType(137), vtkIdType(299)}) {
        const auto q = static_cast<std::size_t>(i);
        double xyz[3];
        ours->GetPoint(i, xyz);
        EXPECT_EQ(bits(xyz[0]), bits(p.x[q].x()));
        EXPECT_EQ(bits(xyz[1]), bits(p.x[q].y()));
        EXPECT_EQ(xyz[2], 0.0);
        EXPECT_EQ(pd->GetArray("id")->GetComponent(i, 0), p.id[q]);
        EXPECT_EQ(bits(pd->GetArray("velocity")->GetComponent(i, 1)), bits(p.v[q].y()));
        vtkDataArray* stress = pd->GetArray("stress");
        EXPECT_EQ(bits(stress->GetComponent(i, 1)), bits(p.sigma[q][XY]));
        EXPECT_EQ(bits(stress->GetComponent(i, 3)), bits(p.polar.sigma21[q]));  // the Cosserat yx
        EXPECT_EQ(bits(stress->GetComponent(i, 8)), bits(p.sigma[q][ZZ]));
        EXPECT_EQ(bits(pd->GetArray("affineVelocity")->GetComponent(i, 3)), bits(p.affine[q](1, 0)));
        EXPECT_EQ(bits(pd->GetArray("damage")->GetComponent(i, 0)), bits(p.history("damage")[q]));
    }
}

TEST_F(VtkIo, particlesOfEveryGroupRoundTripBitwiseFromVtksFilesToo)
{
    // Files written before the writer streamed (by VTK's writer) read as the new ones do.
    const Particles<2> p = particlesWith(77, {FieldGroup::plasticStrain, FieldGroup::affine, FieldGroup::polar},
                                      {"kappa"});
    reference::writeParticlesWithVtk(file("vtks.vtp"), p, 1.0, {"sand"}, {"column"});
    writeParticles(file("ours.vtp"), p, 1.0, {"sand"}, {"column"});
    for (const char* name : {"vtks.vtp", "ours.vtp"}) {
        SCOPED_TRACE(name);
        Particles<2> q;
        double t = 0;
        readParticles(file(name), q, t);
        ASSERT_EQ(q.size(), p.size());
        EXPECT_EQ(q.historyNames(), p.historyNames());
        for (const ParticleField<2>& f : particleFields<2>()) {
            if (!f.array || f.role != FieldRole::state) continue;
            EXPECT_EQ(q.carries(f.group), p.carries(f.group));
            std::visit(
                [&](auto* a) {
                    const auto* b = std::get<std::decay_t<decltype(a)>>(fieldArray(f, q));
                    ASSERT_EQ(a->size(), b->size());
                    EXPECT_EQ(std::memcmp(a->data(), b->data(), a->size() * sizeof((*a)[0])), 0)
                        << (*f.name ? f.name : f.storedIn);
                },
                fieldArray(f, p));
        }
        EXPECT_EQ(std::memcmp(q.history("kappa").data(), p.history("kappa").data(), p.size() * sizeof(double)), 0);
    }
}

TEST_F(VtkIo, anUnwritableParticleFileGivesRunErrorAndLeavesNothing)
{
    const std::string path = file("no/such/directory/particles.vtp");
    try {
        writeParticles(path, sampleParticles(3), 0.0, {}, {});
        FAIL() << "expected RunError";
    } catch (const RunError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write particles to " + path), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(VtkIo, historyNamedLikeBuiltinArrayIsRejected)
{
    Particles<2> p = sampleParticles(2);
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
    // Layouts writeParticles never writes are refused rather than misread.
    corrupt("byte_order=\"LittleEndian\"", "byte_order=\"BigEndian\"");
    corrupt("<AppendedData encoding=\"raw\">", "<AppendedData encoding=\"base64\">");
    corrupt("</Piece>", "</Piece><Piece NumberOfPoints=\"0\"></Piece>");
    corrupt("type=\"Int32\" Name=\"id\"", "type=\"Bit\" Name=\"id\"");
}

TEST_F(VtkIo, anArrayOfAnotherNumericTypeIsConvertedAsVtkDid)
{
    // Same bytes, another type of the same size: the values are taken as that type says.
    const std::string path = file("p.vtp");
    const Particles<2> p = sampleParticles(6);
    writeParticles(path, p, 0.0, {}, {});
    std::string text = readText(path);
    const auto at = text.find("type=\"Int32\" Name=\"body\"");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 12, "type=\"UInt32\"");
    writeText(path, text);
    Particles<2> q;
    double t = 0;
    readParticles(path, q, t);
    EXPECT_EQ(q.body, p.body);
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
    Grid<2> g(Vector2(-0.5, 1.0), Vector2(0.25, 0.5), 4, 3);
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
