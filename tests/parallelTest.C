// The pieces of a parallel run that one process can check (doc/parallel.md; the exchanges
// themselves: tests/mpi/parallelMpiTest.C under mpirun):
// - particles packed and unpacked come back bit for bit, every carried array and the
//   materials' history arrays, and a set that carries other arrays refuses them;
// - the shared nodes of a decomposition agree between the ranks: what rank k shares with p
//   is what p shares with k; a node is shared exactly when two ranks reach it; every node
//   has one owner, who reaches it; a shape function wider than a cell shares more nodes.
#include "parallel/Decomposition.H"
#include "parallel/ParticlePacking.H"
#include "parallel/SharedNodes.H"
#include "particles/Particles.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>

using namespace gpic;

namespace {

Particles<3> someParticles(int n)
{
    Particles<3> p;
    p.carry(FieldGroup::plasticStrain);
    p.declareHistory("epsPs");
    for (int k = 0; k < n; ++k) {
        const std::size_t q = p.add(Eigen::Vector3d(0.1 * k, 0.2, 1.0 / (k + 3)), 0.3 + k, 1e-3 / (k + 1),
                                    Eigen::Vector3d(0.005, 0.005, 0.005), k % 2, k % 3);
        p.id[q] = 1000 + k;
        p.v[q] = Eigen::Vector3d(std::sqrt(2.0) * k, -1.0 / 7, 3.0);
        for (int c = 0; c < 6; ++c) p.sigma[q][c] = -1e3 * (c + 1) / (k + 1.0), p.epsP[q][c] = 1e-4 * c * k;
        p.history("epsPs")[q] = 0.01 * k / 3.0;
    }
    return p;
}

template <class T> bool sameBytes(const std::vector<T>& a, std::size_t i, const std::vector<T>& b, std::size_t j)
{
    return std::memcmp(&a[i], &b[j], sizeof(T)) == 0;
}

} // namespace

TEST(Parallel, packedParticlesComeBackBitForBit)
{
    const Particles<3> p = someParticles(7);
    const std::vector<std::size_t> which{5, 0, 3};
    Particles<3> q;
    q.carry(FieldGroup::plasticStrain);
    q.declareHistory("epsPs");
    EXPECT_EQ(unpackParticles(packParticles(p, which), q), 3u);
    ASSERT_EQ(q.size(), 3u);
    for (std::size_t k = 0; k < which.size(); ++k) {
        const std::size_t i = which[k];
        EXPECT_EQ(q.id[k], p.id[i]);
        EXPECT_TRUE(sameBytes(p.x, i, q.x, k) && sameBytes(p.v, i, q.v, k) && sameBytes(p.m, i, q.m, k) &&
                    sameBytes(p.V, i, q.V, k) && sameBytes(p.sigma, i, q.sigma, k) && sameBytes(p.epsP, i, q.epsP, k) &&
                    sameBytes(p.halfSize, i, q.halfSize, k) && sameBytes(p.material, i, q.material, k) &&
                    sameBytes(p.body, i, q.body, k) && sameBytes(p.history("epsPs"), i, q.history("epsPs"), k))
            << "particle " << i;
    }
    Particles<3> elastic;  // no plastic strain, no history: other arrays
    EXPECT_THROW(unpackParticles(packParticles(p, which), elastic), std::runtime_error);
}

TEST(Parallel, ranksAgreeOnTheNodesTheyShare)
{
    const Grid<2> grid(Eigen::Vector2d(0, 0), Eigen::Vector2d(0.1, 0.1), 12, 8);
    DecompositionSettings s;
    s.subdomains = 4;
    s.method = DecompositionSettings::Method::simple;
    s.n = {2, 2, 1};
    const auto owner = decomposeCells(grid, std::vector<int>(96, 1), s);
    for (int reach : {0, 1}) {
        std::vector<SharedNodes<2>> ranks;
        for (int r = 0; r < 4; ++r) ranks.emplace_back(grid, owner, r, reach);
        for (int n = 0; n < grid.nNodes(); ++n) {
            int reachedBy = 0;
            for (int r = 0; r < 4; ++r) reachedBy += ranks[r].reaches(n);
            EXPECT_GE(reachedBy, 1) << n;
            const int o = ranks[0].ownerOf(n);
            for (int r = 0; r < 4; ++r) EXPECT_EQ(ranks[r].ownerOf(n), o);
            EXPECT_TRUE(ranks[o].reaches(n)) << "node " << n << " not reached by its owner";
            int listed = 0;  // in how many (rank, peer) lists node n appears
            for (int r = 0; r < 4; ++r)
                for (std::size_t k = 0; k < ranks[r].peers().size(); ++k)
                    listed += std::binary_search(ranks[r].sharedWith(k).begin(), ranks[r].sharedWith(k).end(), n);
            EXPECT_EQ(listed, reachedBy * (reachedBy - 1)) << "node " << n;  // each pair, both ways
        }
        for (int r = 0; r < 4; ++r)
            for (std::size_t k = 0; k < ranks[r].peers().size(); ++k) {
                const int p = ranks[r].peers()[k];
                const auto& back = ranks[p].peers();
                const std::size_t j = static_cast<std::size_t>(std::find(back.begin(), back.end(), r) - back.begin());
                ASSERT_LT(j, back.size());
                EXPECT_EQ(ranks[r].sharedWith(k), ranks[p].sharedWith(j));
            }
    }
    // Bilinear cells (reach 0): the 2 x 2 blocks of 6 x 4 cells share the lines x = 6 and
    // y = 4: rank 0 shares 5 nodes with 1 (x = 6, j = 0..4), 7 with 2, 1 with 3 (the corner).
    SharedNodes<2> first(grid, owner, 0, 0);
    ASSERT_EQ(first.peers(), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(first.sharedWith(0).size(), 5u);
    EXPECT_EQ(first.sharedWith(1).size(), 7u);
    EXPECT_EQ(first.sharedWith(2).size(), 1u);
    EXPECT_GT(SharedNodes<2>(grid, owner, 0, 1).sharedCount(), first.sharedCount());
}
