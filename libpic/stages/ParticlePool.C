#include "stages/ParticlePool.H"

#include "solver/MpmSolver.H"

#include <algorithm>
#include <numeric>

namespace gpic {

Particles selectParticles(const Particles& from, const std::vector<std::size_t>& which)
{
    Particles out = from;
    out.reorder(which);
    return out;
}

void appendParticles(Particles& to, const Particles& from)
{
    const std::size_t n0 = to.size(), n = from.size();
    for (const auto& h : from.historyNames()) to.declareHistory(h);
    if (from.hasAffine()) to.enableAffine();
    to.resize(n0 + n);
    const auto copy = [&](auto& a, const auto& b) { std::copy(b.begin(), b.end(), a.begin() + n0); };
    copy(to.id, from.id); copy(to.body, from.body); copy(to.material, from.material);
    copy(to.x, from.x); copy(to.x0, from.x0); copy(to.v, from.v);
    copy(to.m, from.m); copy(to.V, from.V); copy(to.halfSize, from.halfSize);
    copy(to.sigma, from.sigma); copy(to.eps, from.eps); copy(to.epsP, from.epsP); copy(to.work, from.work);
    copy(to.dEps, from.dEps); copy(to.dOmega, from.dOmega);
    for (const auto& h : from.historyNames()) copy(to.history(h), from.history(h));
    if (from.hasAffine()) {  // else zero: C_p starts at rest
        copy(to.affine, from.affine);
        copy(to.affineEnergy, from.affineEnergy);
    }
    if (from.polar.enabled()) {  // the Cosserat state of a polar scene
        to.polar.enable(n0 + n);
        copy(to.polar.w, from.polar.w); copy(to.polar.omega, from.polar.omega);
        copy(to.polar.sigma21, from.polar.sigma21); copy(to.polar.mu, from.polar.mu);
        copy(to.polar.kappa, from.polar.kappa);
    }
}

bool ParticlePool::exchange(MpmSolver& solver, const Predicate& sleep, const Predicate& wake, const OnWake& onWake)
{
    const Particles& active = solver.particles();
    std::vector<std::size_t> keep, asleep, woken, stay;
    for (std::size_t q = 0; q < active.size(); ++q) (sleep(active, q) ? asleep : keep).push_back(q);
    for (std::size_t q = 0; q < dormant_.size(); ++q) (wake(dormant_, q) ? woken : stay).push_back(q);
    if (asleep.empty() && woken.empty()) return false;

    Particles next = selectParticles(active, keep);
    const std::size_t begin = next.size();
    appendParticles(next, selectParticles(dormant_, woken));
    if (onWake) onWake(next, begin, next.size());

    Particles pool = selectParticles(dormant_, stay);
    appendParticles(pool, selectParticles(active, asleep));
    std::vector<std::size_t> byId(pool.size());
    std::iota(byId.begin(), byId.end(), std::size_t(0));
    std::stable_sort(byId.begin(), byId.end(), [&](std::size_t a, std::size_t b) { return pool.id[a] < pool.id[b]; });
    pool.reorder(byId);
    dormant_ = std::move(pool);
    solver.replaceParticles(std::move(next));
    return true;
}

double ParticlePool::remove(MpmSolver& solver, const Predicate& remove, std::size_t* count)
{
    const Particles& active = solver.particles();
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

} // namespace gpic
