#include "engine/ParticleStrips.H"

#include "core/Threads.H"

#include <algorithm>

namespace gpic {

namespace {
//- The axis of most cells (the first of equals): strips are cut across it.
template <int D> int longestAxis(const Grid<D>& grid)
{
    int axis = 0;
    for (int a = 1; a < D; ++a)
        if (grid.cells(a) > grid.cells(axis)) axis = a;
    return axis;
}
} // namespace

template <int D>
ParticleStrips<D>::ParticleStrips(const Grid<D>& grid)
    : axis_(longestAxis(grid)), nStrips_((grid.cells(axis_) + width - 1) / width)
{
    start_.assign(static_cast<std::size_t>(nStrips_) + 1, 0);
}

template <int D>
int ParticleStrips<D>::stripOf(const Grid<D>& grid, const Vector& x) const
{
    return grid.cellOf(x)[axis_] / width;
}

template <int D>
long ParticleStrips<D>::cellKey(const Grid<D>& grid, const Vector& x) const
{
    // The strip's axis first, then the others in axis order.
    const typename Grid<D>::Index c = grid.cellOf(x);
    long key = c[axis_];
    for (int a = 0; a < D; ++a)
        if (a != axis_) key = key * grid.cells(a) + c[a];
    return key;
}

template <int D>
typename ParticleStrips<D>::StripRun ParticleStrips<D>::runOf(int colour, int t, int threads) const
{
    long total = 0;
    for (int s = colour; s < nStrips_; s += 2) total += start_[s + 1] - start_[s];
    // A strip goes to the thread whose share holds its middle particle: owners rise with s.
    StripRun run{0, 0};
    bool found = false;
    long before = 0;
    for (int s = colour; s < nStrips_; s += 2) {
        const long count = start_[s + 1] - start_[s];
        const long owner = total > 0 ? std::min<long>(threads - 1, (2 * before + count) * threads / (2 * total)) : 0;
        before += count;
        if (owner == t) {
            if (!found) run.first = s;
            found = true;
            run.end = s + 1;
        } else if (owner > t) {
            break;
        }
    }
    return run;
}

template <int D>
void ParticleStrips<D>::assign(const Grid<D>& grid, const Particles<D>& p)
{
    const auto n = static_cast<long>(p.size());
    strip_.resize(p.size());
    order_.resize(p.size());
    // Counting sort, stable (particles keep their index order inside a strip) at any thread
    // count: each thread counts its own range of particles, then places them after those of
    // the same strip in the ranges before its own. Every step, so not left to one thread.
    fill_.resize(static_cast<std::size_t>(threadCount()));
#pragma omp parallel if (n >= minParallelWork())
    {
        const int t = threadIndex(), threads = teamSize();
        const long begin = n * t / threads, end = n * (t + 1) / threads;
        std::vector<int>& next = fill_[static_cast<std::size_t>(t)];
        next.assign(static_cast<std::size_t>(nStrips_), 0);
        // Neighbouring particles mostly share a strip (the particles are sorted by cell): its
        // count stays in a register while they do, instead of a load and store per particle,
        // each waiting for the last.
        int* strip = strip_.data();
        int* order = order_.data();
        int run = -1, counted = 0;
        for (long q = begin; q < end; ++q) {
            const int s = stripOf(grid, p.x[q]);
            strip[q] = s;
            if (s != run) {
                if (run >= 0) next[run] += counted;
                run = s;
                counted = 0;
            }
            ++counted;
        }
        if (run >= 0) next[run] += counted;
#pragma omp barrier
#pragma omp single
        {
            start_[0] = 0;
            for (int s = 0; s < nStrips_; ++s) {
                int at = start_[s];
                for (int u = 0; u < threads; ++u) {
                    int& slot = fill_[static_cast<std::size_t>(u)][s];
                    const int count = slot;
                    slot = at;
                    at += count;
                }
                start_[s + 1] = at;
            }
        }
        run = -1;
        int at = 0;  // the next place of strip `run`
        for (long q = begin; q < end; ++q) {
            const int s = strip[q];
            if (s != run) {
                if (run >= 0) next[run] = at;
                run = s;
                at = next[s];
            }
            order[at++] = static_cast<int>(q);
        }
    }
}

template class ParticleStrips<2>;
#if GPIC_WITH_3D
template class ParticleStrips<3>;
#endif

} // namespace gpic
