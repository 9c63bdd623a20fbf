// The scatter's strips (ParticleStrips): at any thread count every particle is visited once,
// a strip's particles in index order (the counting sort is stable); within a colour each
// thread works on one run of neighbouring strips, the runs in thread order along the grid;
// and the runs share the colour's particles evenly to within one strip's particles.
#include "core/Threads.H"
#include "engine/ParticleStrips.H"

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <vector>

using namespace gpic;

namespace {

//- A collapsing column's crowd: the strips on the left full, those on the right sparse, one
//  strip empty. The grid is longer in x1, so the strips are columns of cells.
Particles<2> unevenParticles(const Grid<2>& grid)
{
    Particles<2> p;
    const Vector2 h = grid.cellSize();
    for (int i = 0; i < grid.nx(); ++i) {
        if (i / ParticleStrips<2>::width == 5) continue;  // an empty strip
        const int perCell = i < 12 ? 6 : 1;
        for (int j = 0; j < grid.ny(); ++j)
            for (int k = 0; k < perCell; ++k)
                p.add(Vector2((i + (k + 0.5) / perCell) * h.x(), (j + 0.5) * h.y()), 1.0, 1.0, 0.25 * h, 0, 0);
    }
    return p;
}

struct Visit {
    int thread = -1;
    int team = 0;
    int count = 0;
    long sequence = -1;  //- place among the visits of its thread
};

} // namespace

TEST(ParticleStrips, eachThreadScattersOneBalancedRunOfStripsPerColour)
{
    const Grid<2> grid(Vector2::Zero(), Vector2(0.1, 0.1), 40, 10);
    const Particles<2> p = unevenParticles(grid);
    ParticleStrips<2> strips(grid);
    ASSERT_EQ(strips.count(), 10);

    const long savedWork = minParallelWork();
    const int savedThreads = omp_get_max_threads();
    minParallelWork() = 1;
    for (int threads : {1, 2, 3, 5}) {
        omp_set_num_threads(threads);
        strips.assign(grid, p);  // sorted at this thread count too
        std::vector<Visit> visits(p.size());
        std::vector<long> visitsOf(static_cast<std::size_t>(threads), 0);
        strips.forEach([&](std::size_t q) {
            visits[q].thread = threadIndex();
            visits[q].sequence = visitsOf[static_cast<std::size_t>(threadIndex())]++;
            visits[q].team = teamSize();
            ++visits[q].count;
        });
        for (int colour = 0; colour < 2; ++colour) {
            // Per strip of the colour, in order along the grid: its thread and particles.
            std::vector<int> owner;
            std::map<int, long> share;
            long total = 0, largest = 0;
            for (int s = colour; s < strips.count(); s += 2) {
                int thread = -1;
                long n = 0, lastSequence = -1;
                for (std::size_t q = 0; q < p.size(); ++q) {
                    if (strips.stripOf(grid, p.x[q]) != s) continue;
                    ASSERT_EQ(visits[q].count, 1) << "particle " << q << " at " << threads << " threads";
                    ASSERT_EQ(visits[q].team, threads);
                    if (thread >= 0) {
                        ASSERT_EQ(visits[q].thread, thread) << "strip " << s << " split";
                    }
                    thread = visits[q].thread;
                    // Particle order inside a strip, as the node sums need it.
                    ASSERT_GT(visits[q].sequence, lastSequence) << "particle " << q << " out of order";
                    lastSequence = visits[q].sequence;
                    ++n;
                }
                if (n == 0) continue;
                owner.push_back(thread);
                share[thread] += n;
                total += n;
                largest = std::max(largest, n);
            }
            EXPECT_TRUE(std::is_sorted(owner.begin(), owner.end())) << "runs out of thread order, colour " << colour;
            for (int t = 0; t < threads; ++t)
                EXPECT_LE(std::abs(share[t] - total / threads), largest)
                    << "thread " << t << " of " << threads << ", colour " << colour;
        }
    }
    omp_set_num_threads(savedThreads);
    minParallelWork() = savedWork;
}
