#include "solver/ParticleStrips.H"

#include "core/Threads.H"

#include <algorithm>

namespace gpic {

ParticleStrips::ParticleStrips(const Grid& grid)
    : axis_(grid.nx() >= grid.ny() ? 0 : 1),
      nStrips_(((axis_ == 0 ? grid.nx() : grid.ny()) + width - 1) / width)
{
    start_.assign(static_cast<std::size_t>(nStrips_) + 1, 0);
}

int ParticleStrips::stripOf(const Grid& grid, const Vector2& x) const
{
    int i, j;
    grid.cellOf(x, i, j);
    return (axis_ == 0 ? i : j) / width;
}

long ParticleStrips::cellKey(const Grid& grid, const Vector2& x) const
{
    int i, j;
    grid.cellOf(x, i, j);
    return axis_ == 0 ? long(i) * grid.ny() + j : long(j) * grid.nx() + i;
}

ParticleStrips::StripRun ParticleStrips::runOf(int colour, int t, int threads) const
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

void ParticleStrips::assign(const Grid& grid, const Particles& p)
{
    const auto n = static_cast<long>(p.size());
    strip_.resize(p.size());
    order_.resize(p.size());
#pragma omp parallel for schedule(static) if (n >= minParallelWork())
    for (long q = 0; q < n; ++q) strip_[q] = stripOf(grid, p.x[q]);
    // Counting sort: stable, so particles keep their index order inside a strip.
    std::fill(start_.begin(), start_.end(), 0);
    for (int s : strip_) ++start_[s + 1];
    for (int s = 0; s < nStrips_; ++s) start_[s + 1] += start_[s];
    fill_.assign(start_.begin(), start_.end() - 1);
    for (long q = 0; q < n; ++q) order_[fill_[strip_[q]]++] = static_cast<int>(q);
}

} // namespace gpic
