#include "loads/AppliedLoads.H"

#include "engine/SolverInputs.H"
#include "core/error.H"
#include "parallel/ParticlePacking.H"

#include <algorithm>
#include <numeric>

namespace gpic {

GPIC_REGISTER_PASS_DIMS(AppliedLoads, "appliedLoads")

template <int D>
bool AppliedLoads<D>::needed(const PassScene<D>& scene) { return !scene.inputs.loads.empty(); }

template <int D>
AppliedLoads<D>::AppliedLoads(PassScene<D>& scene)
    : loads_(std::move(scene.inputs.loads)), force_(scene.particles.size(), Vector::Zero())
{
    if (scene.inputs.ranks.parallel())
        chooseAmongRanks(scene.particles, scene.grid, scene.inputs.bodyNames, scene.inputs.ranks);
    else
        for (auto& load : loads_) load->initialise(scene.particles, scene.grid, scene.inputs.bodyNames);
}

template <int D>
void AppliedLoads<D>::chooseAmongRanks(const Particles<D>& particles, const Grid<D>& grid,
                                       const std::vector<std::string>& bodyNames, const RankReductions& ranks)
{
    byId_ = true;
    std::vector<std::size_t> mine(particles.size());
    std::iota(mine.begin(), mine.end(), std::size_t(0));
    Particles<D> all = particles;
    all.reorder({});
    for (const auto& bytes : ranks.gather(packParticles(particles, mine))) unpackParticles(bytes, all);
    // One order on every rank, whatever the decomposition: by material, then id.
    std::vector<std::size_t> order(all.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return all.material[a] != all.material[b] ? all.material[a] < all.material[b] : all.id[a] < all.id[b];
    });
    all.reorder(order);
    for (auto& load : loads_) {
        load->initialise(all, grid, bodyNames);
        const std::vector<std::size_t> chosen = load->loadedParticles();
        if (chosen.empty())
            throw RunError("constant/loads: a load of a type that does not list the particles it loads "
                           "(ParticleLoad::loadedParticles): not yet in a parallel run; run it without -parallel");
        for (std::size_t q : chosen) loadedIndex_.push_back(q);
    }
    std::sort(loadedIndex_.begin(), loadedIndex_.end(), [&](std::size_t a, std::size_t b) { return all.id[a] < all.id[b]; });
    loadedIndex_.erase(std::unique(loadedIndex_.begin(), loadedIndex_.end()), loadedIndex_.end());
    for (std::size_t q : loadedIndex_) loadedIds_.push_back(all.id[q]);
    allForce_.assign(all.size(), Vector::Zero());
}

template <int D>
AppliedLoads<D>::AppliedLoads(std::vector<std::unique_ptr<ParticleLoad<D>>> loads, const Particles<D>& particles,
                           const Grid<D>& grid, const std::vector<std::string>& bodyNames)
    : loads_(std::move(loads)), force_(particles.size(), Vector::Zero())
{
    for (auto& load : loads_) load->initialise(particles, grid, bodyNames);
}

template <int D>
void AppliedLoads<D>::at(StepPoint, EngineView<D>& e, double)
{
    const Particles<D>& p = e.particles;
    std::fill(force_.begin(), force_.end(), Vector::Zero());
    if (byId_) {  // a parallel run: the loads' forces on every rank's particles, then this rank's by id
        force_.resize(p.size(), Vector::Zero());
        Particles<D> none;
        for (const auto& load : loads_) load->addForces(e.time, none, allForce_);
        for (std::size_t q = 0; q < p.size(); ++q) {
            const auto it = std::lower_bound(loadedIds_.begin(), loadedIds_.end(), p.id[q]);
            if (it != loadedIds_.end() && *it == p.id[q]) force_[q] = allForce_[loadedIndex_[it - loadedIds_.begin()]];
        }
        for (std::size_t q : loadedIndex_) allForce_[q].setZero();
    } else {
        for (const auto& load : loads_) load->addForces(e.time, p, force_);
    }
    Grid<D>& grid = e.grid;
    const ShapeWeights<D>& w = e.weights;
    const int stride = w.stride;
    e.strips.forEach([&](std::size_t q) {
        const Vector& f = force_[q];
        if ((f.array() == 0.0).all()) return;  // most particles carry no load
        BodyField<D>* body = e.coupling.bodyField(p.body[q]);
        const std::size_t k0 = q * stride;
        for (int a = 0; a < stride; ++a) {
            const int n = w.node[k0 + a];
            if (n < 0) continue;
            const Vector fExt = w.N[k0 + a] * f;  // eq. 2.3.9, traction term
            grid.fExt[n] += fExt;
            if (body) body->force[n] += fExt;
        }
    });
}

template <int D>
void AppliedLoads<D>::renumber(const std::vector<std::size_t>& newIndex, std::size_t nParticles)
{
    if (!byId_)
        for (auto& load : loads_) load->renumber(newIndex);
    force_.resize(nParticles);
}

template class AppliedLoads<2>;
#if GPIC_WITH_3D
template class AppliedLoads<3>;
#endif

} // namespace gpic
