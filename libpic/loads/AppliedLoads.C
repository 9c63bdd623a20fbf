#include "loads/AppliedLoads.H"

#include "engine/SolverInputs.H"

namespace gpic {

GPIC_REGISTER_PASS(AppliedLoads, "appliedLoads")

bool AppliedLoads::needed(const PassScene& scene) { return !scene.inputs.loads.empty(); }

AppliedLoads::AppliedLoads(PassScene& scene)
    : AppliedLoads(std::move(scene.inputs.loads), scene.particles, scene.grid, scene.inputs.bodyNames)
{
}

AppliedLoads::AppliedLoads(std::vector<std::unique_ptr<ParticleLoad>> loads, const Particles& particles,
                           const Grid& grid, const std::vector<std::string>& bodyNames)
    : loads_(std::move(loads)), force_(particles.size(), Vector2::Zero())
{
    for (auto& load : loads_) load->initialise(particles, grid, bodyNames);
}

void AppliedLoads::at(StepPoint, EngineView& e, double)
{
    const Particles& p = e.particles;
    std::fill(force_.begin(), force_.end(), Vector2::Zero());
    for (const auto& load : loads_) load->addForces(e.time, p, force_);
    Grid& grid = e.grid;
    const ShapeWeights& w = e.weights;
    const int stride = w.stride;
    e.strips.forEach([&](std::size_t q) {
        const Vector2& f = force_[q];
        if (f.x() == 0.0 && f.y() == 0.0) return;  // most particles carry no load
        BodyField* body = e.coupling.bodyField(p.body[q]);
        const std::size_t k0 = q * stride;
        for (int a = 0; a < stride; ++a) {
            const int n = w.node[k0 + a];
            if (n < 0) continue;
            const Vector2 fExt = w.N[k0 + a] * f;  // eq. 2.3.9, traction term
            grid.fExt[n] += fExt;
            if (body) body->force[n] += fExt;
        }
    });
}

void AppliedLoads::renumber(const std::vector<std::size_t>& newIndex, std::size_t nParticles)
{
    for (auto& load : loads_) load->renumber(newIndex);
    force_.resize(nParticles);
}

} // namespace gpic
