// The particle field table (ParticleFields.H) drives every bulk operation on particles. These
// tests walk the table itself, so an array added to it is checked by them without a new
// line here: every state array of every group must survive the VTK file bitwise, follow a
// reorder and an append, and a group's arrays must exist exactly while it is carried.
#include "io/ParticlesVtk.H"
#include "particles/ParticleFields.H"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace gpic;

namespace {

constexpr std::array<FieldGroup, 3> optionalGroups{FieldGroup::plasticStrain, FieldGroup::affine, FieldGroup::polar};

//- A value that no decimal or single-precision detour keeps.
double awkward(std::mt19937_64& rng) { return std::uniform_real_distribution<double>(-1, 1)(rng) * 3.141592653589793; }

void fill(int& v, std::mt19937_64& rng) { v = static_cast<int>(rng() % 100000); }
void fill(double& v, std::mt19937_64& rng) { v = awkward(rng); }
template <class M> void fill(Eigen::MatrixBase<M>& v, std::mt19937_64& rng)
{
    for (Eigen::Index k = 0; k < v.size(); ++k) v(k) = awkward(rng);
}

//- n particles carrying every group, every array of the table filled with distinct values.
Particles<2> everything(std::size_t n)
{
    Particles<2> p;
    for (FieldGroup g : optionalGroups) p.carry(g);
    p.resize(n);
    p.declareHistory("damage");
    std::mt19937_64 rng(7);
    for (const ParticleField<2>& f : particleFields<2>()) {
        if (!f.array) continue;
        std::visit([&](auto* a) { for (auto& v : *a) fill(v, rng); }, f.array(p));
    }
    for (double& h : p.history("damage")) h = awkward(rng);
    for (std::size_t q = 0; q < n; ++q) p.material[q] = static_cast<int>(q % 3);
    return p;
}

template <class T> bool sameBits(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }

//- Particle q of a equals particle r of b bitwise in every array of `role` that both carry.
void expectSameParticle(const Particles<2>& a, std::size_t q, const Particles<2>& b, std::size_t r, FieldRole role)
{
    for (const ParticleField<2>& f : particleFields<2>()) {
        if (!f.array || f.role != role || !a.carries(f.group)) continue;
        std::visit(
            [&](auto* x) {
                const auto* y = std::get<std::decay_t<decltype(x)>>(fieldArray(f, b));
                EXPECT_TRUE(sameBits((*x)[q], (*y)[r])) << (*f.name ? f.name : f.storedIn ? f.storedIn : "scratch")
                                                        << " of particle " << q;
            },
            fieldArray(f, a));
    }
    EXPECT_TRUE(sameBits(a.history("damage")[q], b.history("damage")[r]));
}

std::size_t arraySize(const ParticleField<2>& f, const Particles<2>& p)
{
    return std::visit([](const auto* a) { return a->size(); }, fieldArray(f, p));
}

} // namespace

TEST(ParticleFields, everyStateArrayOfEveryGroupRoundTripsThroughTheFileBitwise)
{
    const fs::path dir = fs::temp_directory_path() / ("gpic-particleFields-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const Particles<2> p = everything(40);
    const std::string path = (dir / "particles.vtp").string();
    writeParticles(path, p, 0.25, {"a", "b", "c"}, {"body"});
    Particles<2> q;
    double t = 0;
    readParticles(path, q, t);
    fs::remove_all(dir);
    for (FieldGroup g : optionalGroups) EXPECT_TRUE(q.carries(g)) << static_cast<int>(g);
    ASSERT_EQ(q.size(), p.size());
    for (std::size_t i = 0; i < p.size(); ++i) expectSameParticle(p, i, q, i, FieldRole::state);
}

TEST(ParticleFields, aFileOfTheCoreGroupReadsBackWithoutTheOptionalGroups)
{
    const fs::path dir = fs::temp_directory_path() / ("gpic-particleFields-core-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    Particles<2> p = everything(10);
    for (FieldGroup g : optionalGroups) p.drop(g);
    const std::string path = (dir / "particles.vtp").string();
    writeParticles(path, p, 0.0, {"a", "b", "c"}, {"body"});
    Particles<2> q = everything(3);  // replaced, not merged
    double t = 0;
    readParticles(path, q, t);
    fs::remove_all(dir);
    for (FieldGroup g : optionalGroups) EXPECT_FALSE(q.carries(g)) << static_cast<int>(g);
    EXPECT_TRUE(q.epsP.empty());
    for (std::size_t i = 0; i < p.size(); ++i) expectSameParticle(p, i, q, i, FieldRole::state);
}

TEST(ParticleFields, everyCombinationOfGroupsRoundTripsThroughTheFileBitwise)
{
    // The file is written and read array by array through fixed buffers: no set, small or
    // large (many buffers' worth), of any groups, may lose a bit or a group.
    const fs::path dir = fs::temp_directory_path() / ("gpic-particleFields-groups-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string path = (dir / "particles.vtp").string();
    for (unsigned mask = 0; mask < 8; ++mask) {
        for (std::size_t n : {0, 1, 9000}) {
            SCOPED_TRACE("groups " + std::to_string(mask) + ", " + std::to_string(n) + " particles");
            Particles<2> p = everything(n);
            for (std::size_t k = 0; k < optionalGroups.size(); ++k)
                if (!(mask & (1u << k))) p.drop(optionalGroups[k]);
            writeParticles(path, p, 0.5, {"a", "b", "c"}, {"body"});
            Particles<2> q = everything(3);  // replaced, not merged
            double t = 0;
            readParticles(path, q, t);
            for (FieldGroup g : optionalGroups) EXPECT_EQ(q.carries(g), p.carries(g)) << static_cast<int>(g);
            ASSERT_EQ(q.size(), p.size());
            EXPECT_EQ(q.historyNames(), p.historyNames());
            for (std::size_t i = 0; i < p.size(); ++i) expectSameParticle(p, i, q, i, FieldRole::state);
        }
    }
    fs::remove_all(dir);
}

TEST(ParticleFields, reorderAndAppendMoveEveryArrayTogether)
{
    const Particles<2> p = everything(30);
    const std::vector<std::size_t> order{29, 3, 3, 0, 17};  // a repeat, drops the rest
    Particles<2> r = p;
    r.reorder(order);
    ASSERT_EQ(r.size(), order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        for (FieldRole role : {FieldRole::state, FieldRole::scratch}) expectSameParticle(r, k, p, order[k], role);

    // Appended to a set without the optional groups: they are carried, zero for the old ones.
    Particles<2> a;
    a.add(Vector2(1, 2), 3.0, 0.5, Vector2(0.1, 0.1), 0, 0);
    a.append(p);
    ASSERT_EQ(a.size(), 31u);
    for (FieldGroup g : optionalGroups) EXPECT_TRUE(a.carries(g));
    EXPECT_TRUE(a.epsP[0].isZero());
    EXPECT_TRUE(a.affine[0].isZero());
    EXPECT_EQ(a.polar.w[0], 0.0);
    EXPECT_EQ(a.history("damage")[0], 0.0);
    for (std::size_t k = 0; k < p.size(); ++k) expectSameParticle(a, k + 1, p, k, FieldRole::state);
}

TEST(ParticleFields, aGroupHasArraysExactlyWhileItIsCarried)
{
    Particles<2> p = everything(12);
    const std::size_t all = p.bytes();
    for (FieldGroup g : optionalGroups) {
        Particles<2> d = p;
        d.drop(g);
        std::size_t heldByGroup = 0;
        for (const ParticleField<2>& f : particleFields<2>()) {
            if (!f.array) continue;
            EXPECT_EQ(arraySize(f, d), f.group == g ? 0u : d.size()) << (*f.name ? f.name : "an unnamed array");
            if (f.group == g) heldByGroup += arraySize(f, p);
        }
        EXPECT_GT(heldByGroup, 0u);
        EXPECT_LT(d.bytes(), all);  // dropping releases the memory
        d.resize(20);
        d.carry(g);  // back, zero for all
        for (const ParticleField<2>& f : particleFields<2>()) {
            if (f.array) {
                EXPECT_EQ(arraySize(f, d), 20u);
            }
        }
    }
    EXPECT_THROW(p.drop(FieldGroup::core), std::logic_error);
}
