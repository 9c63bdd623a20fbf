#include "loads/AppliedLoads.H"

#include "engine/SolverInputs.H"

namespace gpic {

GPIC_REGISTER_PASS_DIMS(AppliedLoads, "appliedLoads")

template <int D>
bool AppliedLoads<D>::needed(const PassScene<D>& scene) { return !scene.inputs.loads.empty(); }

template <int D>
AppliedLoads<D>::AppliedLoads(PassScene<D>& scene)
    : AppliedLoads<D>(std::move(scene.inputs.loads), scene.particles, scene.grid, scene.inputs.bodyNames)
{
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
    for (const auto& load : loads_) load->addForces(e.time, p, force_);
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
    for (auto& load : loads_) load->renumber(newIndex);
    force_.resize(nParticles);
}

template class AppliedLoads<2>;
#if GPIC_WITH_3D
template class AppliedLoads<3>;
#endif

} // namespace gpic
