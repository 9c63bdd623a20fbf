// The exchanges of a parallel run, run under mpirun -np 2 and -np 4 (tests/CMakeLists.txt):
// - a sum over the ranks is added in rank order: every rank holds the bits of
//   ((v0 + v1) + v2) + v3, computed here from the values each rank is known to give;
// - the nodal sums on shared nodes, completed by SharedNodes, are the same rank-ordered sums
//   on every rank that reaches the node, and a node one rank alone reaches keeps its value;
// - a node a rank did not write this step adds nothing to its neighbours' sums, whatever its
//   array holds there; the largest value (a rigid body's id) and the nodes touched are shared;
// - particles packed on one rank and sent arrive bit for bit on another;
// - the smallest value over the ranks is the time step's.
#include "parallel/Communicator.H"
#include "parallel/Decomposition.H"
#include "parallel/ParticlePacking.H"
#include "parallel/SharedNodes.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace gpic;

namespace {

Communicator* world = nullptr;

//- The value rank r gives at node n (irrational enough that the order of adding shows).
double valueOf(int r, int n) { return std::sqrt(2.0 + n) / (r + 3.0) + 1e-3 * std::sin(n * 0.7 + r); }

} // namespace

TEST(ParallelMpi, sumsAreAddedInRankOrderOnEveryRank)
{
    std::vector<double> v{valueOf(world->rank(), 1), valueOf(world->rank(), 2)};
    world->sumInRankOrder(v);
    for (int i = 0; i < 2; ++i) {
        double expected = valueOf(0, i + 1);
        for (int r = 1; r < world->size(); ++r) expected += valueOf(r, i + 1);
        EXPECT_EQ(v[i], expected);
    }
    std::vector<double> smallest{1.0 + world->rank(), -1.0 - world->rank()};
    world->min(smallest);
    EXPECT_EQ(smallest, (std::vector<double>{1.0, -static_cast<double>(world->size())}));
}

TEST(ParallelMpi, sharedNodesHoldTheRankOrderedSum)
{
    const Grid<3> grid(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.1, 0.1), {8, 6, 5});
    DecompositionSettings s;
    s.subdomains = world->size();
    s.method = DecompositionSettings::Method::hierarchical;
    s.n = {world->size() >= 2 ? 2 : 1, world->size() >= 4 ? 2 : 1, 1};
    const auto owner = decomposeCells(grid, std::vector<int>(static_cast<std::size_t>(grid.nCells()), 1), s);
    for (int reach : {0, 1}) {
        std::vector<SharedNodes<3>> all;
        for (int r = 0; r < world->size(); ++r) all.emplace_back(grid, owner, r, reach);
        const SharedNodes<3>& mine = all[world->rank()];
        std::vector<double> field(3 * static_cast<std::size_t>(grid.nNodes()), 0.0);
        for (int n = 0; n < grid.nNodes(); ++n)
            if (mine.reaches(n))
                for (int c = 0; c < 3; ++c) field[3 * n + c] = valueOf(world->rank(), 3 * n + c);
        mine.complete(field.data(), 3, *world);
        for (int n = 0; n < grid.nNodes(); ++n) {
            if (!mine.reaches(n)) continue;
            for (int c = 0; c < 3; ++c) {
                double expected = 0;
                bool first = true;
                for (int r = 0; r < world->size(); ++r)
                    if (all[r].reaches(n)) expected = first ? valueOf(r, 3 * n + c) : expected + valueOf(r, 3 * n + c), first = false;
                ASSERT_EQ(field[3 * n + c], expected) << "node " << n << " reach " << reach;
            }
        }
    }
}

TEST(ParallelMpi, nodesARankDidNotWriteTakeNoPartAndMarksAreShared)
{
    const Grid<2> grid(Eigen::Vector2d(0, 0), Eigen::Vector2d(0.1, 0.1), {8, 6});
    DecompositionSettings s;
    s.subdomains = world->size();
    s.method = DecompositionSettings::Method::hierarchical;
    s.n = {world->size(), 1, 1};
    const auto owner = decomposeCells(grid, std::vector<int>(static_cast<std::size_t>(grid.nCells()), 1), s);
    std::vector<SharedNodes<2>> all;
    for (int r = 0; r < world->size(); ++r) all.emplace_back(grid, owner, r, 0);
    const SharedNodes<2>& mine = all[world->rank()];
    // Rank r writes the nodes (i, j) with (i + j + r) % 3 != 0 (on a shared node one rank, or
    // several); elsewhere its field holds a stale 1e6 (an iterate left from an earlier step),
    // which must not reach a neighbour's sum.
    const auto writes = [&grid](int r, int n) {
        const auto i = grid.nodeIndex(n);
        return (i[0] + i[1] + r) % 3 != 0;
    };
    const int me = world->rank();
    std::vector<double> field(static_cast<std::size_t>(grid.nNodes()), 1e6);
    std::vector<int> body(static_cast<std::size_t>(grid.nNodes()), -1);
    for (int n = 0; n < grid.nNodes(); ++n)
        if (writes(me, n)) field[n] = valueOf(me, n), body[n] = me;
    const auto written = [&](int n) { return writes(me, n); };
    mine.complete(field.data(), 1, *world, written);
    mine.completeMax(body.data(), *world, written);
    std::vector<int> marked;
    mine.shareMarks(written, [&](int n) { marked.push_back(n); }, *world);
    for (int n = 0; n < grid.nNodes(); ++n) {
        if (!mine.reaches(n) || !writes(me, n)) continue;
        double expected = 0;
        bool first = true;
        int largest = -1;
        for (int r = 0; r < world->size(); ++r) {
            if (!all[r].reaches(n)) continue;
            const double v = writes(r, n) ? valueOf(r, n) : 0.0;
            expected = first ? v : expected + v, first = false;
            if (writes(r, n)) largest = std::max(largest, r);
        }
        ASSERT_EQ(field[n], expected) << "node " << n;
        ASSERT_EQ(body[n], largest) << "node " << n;
    }
    // Marked here: exactly the nodes this rank reaches and did not write, which a rank that
    // shares them wrote; in ascending order.
    std::vector<int> expected;
    for (int n = 0; n < grid.nNodes(); ++n) {
        if (!mine.reaches(n) || writes(me, n)) continue;
        for (int r = 0; r < world->size(); ++r)
            if (r != me && all[r].reaches(n) && writes(r, n)) {
                expected.push_back(n);
                break;
            }
    }
    EXPECT_EQ(marked, expected);
    if (world->size() > 1) EXPECT_FALSE(expected.empty());
}

TEST(ParallelMpi, particlesArriveBitForBit)
{
    // Every rank sends to the next (and hears from the one before) two particles it makes.
    const int next = (world->rank() + 1) % world->size(), before = (world->rank() + world->size() - 1) % world->size();
    auto make = [](int r) {
        Particles<2> p;
        for (int k = 0; k < 2; ++k) {
            const std::size_t q = p.add(Eigen::Vector2d(r + 0.1 * k, std::sqrt(3.0 + r)), 1.0 / (r + 2), 1e-4,
                                        Eigen::Vector2d(0.01, 0.01), r, 0);
            p.id[q] = 100 * r + k;
            p.v[q] = Eigen::Vector2d(1.0 / 3 + r, -k / 7.0);
        }
        return p;
    };
    if (world->size() == 1) GTEST_SKIP() << "one rank";
    const std::vector<int> peers = next == before ? std::vector<int>{next} : std::vector<int>{before, next};
    std::vector<std::vector<char>> send(peers.size());
    for (std::size_t k = 0; k < peers.size(); ++k)
        if (peers[k] == next) send[k] = packParticles(make(world->rank()), {0, 1});
        else send[k] = packParticles(Particles<2>(), {});
    const auto received = world->exchange(peers, send);
    Particles<2> got;
    for (const auto& bytes : received) unpackParticles(bytes, got);
    const Particles<2> expected = make(before);
    ASSERT_EQ(got.size(), 2u);
    for (std::size_t q = 0; q < 2; ++q) {
        EXPECT_EQ(got.id[q], expected.id[q]);
        EXPECT_EQ(std::memcmp(&got.x[q], &expected.x[q], sizeof got.x[q]), 0);
        EXPECT_EQ(std::memcmp(&got.v[q], &expected.v[q], sizeof got.v[q]), 0);
        EXPECT_EQ(got.m[q], expected.m[q]);
    }
}

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    auto comm = mpiCommunicator(&argc, &argv);
    world = comm.get();
    // Only rank 0 prints; every rank runs every test (the exchanges need them all).
    if (world->rank() != 0) {
        auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
        delete listeners.Release(listeners.default_result_printer());
    }
    const int failed = RUN_ALL_TESTS();
    std::vector<double> anyFailed{static_cast<double>(failed != 0)};
    world->sumInRankOrder(anyFailed);  // a failure on any rank fails the job
    return anyFailed[0] > 0 ? 1 : 0;
}
