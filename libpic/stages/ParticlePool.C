#include "stages/ParticlePool.H"

#include "engine/MpmSolver.H"

#include <algorithm>
#include <numeric>

namespace gpic {

template <int D> Particles<D> selectParticles(const Particles<D>& from, const std::vector<std::size_t>& which)
{
    Particles<D> out = from;
    out.reorder(which);
    return out;
}

template <int D>
bool ParticlePool<D>::exchange(MpmSolver<D>& solver, const Predicate& sleep, const Predicate& wake, const OnWake& onWake)
{
    const Particles<D>& active = solver.particles();
    std::vector<std::size_t> keep, asleep, woken, stay;
    for (std::size_t q = 0; q < active.size(); ++q) (sleep(active, q) ? asleep : keep).push_back(q);
    for (std::size_t q = 0; q < dormant_.size(); ++q) (wake(dormant_, q) ? woken : stay).push_back(q);
    if (asleep.empty() && woken.empty()) return false;

    Particles<D> next = selectParticles(active, keep);
    const std::size_t begin = next.size();
    next.append(selectParticles(dormant_, woken));
    if (onWake) onWake(next, begin, next.size());

    Particles<D> pool = selectParticles(dormant_, stay);
    pool.append(selectParticles(active, asleep));
    std::vector<std::size_t> byId(pool.size());
    std::iota(byId.begin(), byId.end(), std::size_t(0));
    std::stable_sort(byId.begin(), byId.end(), [&](std::size_t a, std::size_t b) { return pool.id[a] < pool.id[b]; });
    pool.reorder(byId);
    dormant_ = std::move(pool);
    solver.replaceParticles(std::move(next));
    return true;
}

template <int D>
double ParticlePool<D>::remove(MpmSolver<D>& solver, const Predicate& remove, std::size_t* count)
{
    const Particles<D>& active = solver.particles();
    std::vector<std::size_t> keep;
    double mass = 0;
    for (std::size_t q = 0; q < active.size(); ++q) {
        if (remove(active, q)) mass += active.m[q];
        else keep.push_back(q);
    }
    const std::size_t removed = active.size() - keep.size();
    if (count) *count = removed;
    if (removed > 0) solver.replaceParticles(selectParticles(active, keep));
    return mass;
}

template class ParticlePool<2>;
#if GPIC_WITH_3D
template class ParticlePool<3>;
#endif

} // namespace gpic
