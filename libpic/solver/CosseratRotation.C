#include "solver/CosseratRotation.H"

#include "core/Threads.H"

#include <algorithm>
#include <cmath>

namespace gpic {

CosseratRotation::CosseratRotation(const std::vector<std::unique_ptr<Material>>& materials,
                                   const GridSides& sides, int nNodes)
{
    r_.materialPolar.assign(materials.size(), 0);
    r_.materialJ.assign(materials.size(), 0.0);
    for (std::size_t m = 0; m < materials.size(); ++m) {
        r_.materialPolar[m] = materials[m]->needsRotation();
        r_.materialJ[m] = r_.materialPolar[m] ? materials[m]->rotationalInertia() : 0.0;
    }
    for (int s = 0; s < GridSides::count; ++s)  // w3c is odd under a reflection: zero on a symmetry plane
        r_.sideFixed[s] = sides.condition(static_cast<GridSide>(s)).isMirror();
    r_.allocate(nNodes);
}

std::vector<StepPoint> CosseratRotation::points() const
{
    return {StepPoint::afterParticlesToGrid, StepPoint::afterForces,      StepPoint::beforeGridUpdate,
            StepPoint::afterStrain,          StepPoint::afterStressUpdate, StepPoint::afterGridToParticles,
            StepPoint::afterRemap};
}

void CosseratRotation::at(StepPoint point, EngineView& e, double dt)
{
    switch (point) {
    case StepPoint::afterParticlesToGrid: toGrid(e); break;
    case StepPoint::afterForces: forces(e); break;
    case StepPoint::beforeGridUpdate: update(e, dt); break;
    case StepPoint::afterStrain:
        strain(e, dt);
        addWork(e);  // the first half, with the stress of the start of the step
        break;
    case StepPoint::afterStressUpdate: addWork(e); break;  // the second half
    case StepPoint::afterGridToParticles: toParticles(e, dt); break;
    case StepPoint::afterRemap: remap(e); break;
    default: break;  // not one of points()
    }
}

void CosseratRotation::setUpParticles(Particles& p)
{
    if (!p.carries(FieldGroup::polar)) {
        // A state without rotation arrays (a new case, or particles new to the scene): no
        // micro-rotation, no couple stress, sigma21 = sigma12 (seed A2: the initial stress
        // is symmetric).
        p.carry(FieldGroup::polar);
        for (std::size_t q = 0; q < p.size(); ++q) p.polar.sigma21[q] = p.sigma[q][XY];
    }
    double lightest = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const double mJ = p.m[q] * r_.materialJ[static_cast<std::size_t>(p.material[q])];
        if (mJ > 0) lightest = lightest == 0 ? mJ : std::min(lightest, mJ);
    }
    r_.minInertia = 1e-9 * lightest;
}

double CosseratRotation::timeStep(const std::vector<std::unique_ptr<Material>>& materials,
                                  const std::vector<char>& deforms, double minCellSize,
                                  const std::vector<double>& massScale) const
{
    double dt = 1e300;
    for (std::size_t m = 0; m < materials.size(); ++m)
        if (deforms[m] && materials[m]->needsRotation()) {
            const double step = materials[m]->rotationalTimeStep(minCellSize);
            dt = std::min(dt, massScale.empty() ? step : step * std::sqrt(massScale[m]));
        }
    return dt;
}

void CosseratRotation::constrain(const Grid& grid, std::vector<double>& field) const
{
    for (int n : grid.active)
        if (r_.fixed[n]) field[n] = 0.0;
}

void CosseratRotation::spinToGrid(EngineView& e, bool withInertia)
{
    CosseratField& r = r_;
    const Particles& p = e.particles;
    const ShapeWeights& weights = e.weights;
    const int stride = weights.stride;
    e.strips.forEach([&](std::size_t q) {
        if (!isPolar(e, q)) return;
        const double mJ = e.inertialMass(q) * r.materialJ[static_cast<std::size_t>(p.material[q])];
        const std::size_t k0 = q * stride;
        for (int a = 0; a < stride; ++a) {
            const int n = weights.node[k0 + a];
            if (n < 0) continue;
            const double NmJ = weights.N[k0 + a] * mJ;
            if (withInertia) r.inertia[n] += NmJ;  // lumped rotational inertia
            r.momentum[n] += NmJ * p.polar.omega[q];  // spin momentum, as eq. 2.4.1
        }
    });
}

void CosseratRotation::toGrid(EngineView& e)
{
    CosseratField& r = r_;
    e.grid.forEachActiveNode([&](int n) {
        r.inertia[n] = r.momentum[n] = r.moment[n] = r.accel[n] = 0.0;
        r.fixed[n] = 0;
    });
    spinToGrid(e, true);
    e.grid.forEachActiveNode([&](int n) { r.rate[n] = r.inertia[n] > 0.0 ? r.momentum[n] / r.inertia[n] : 0.0; });
    // Conditions: sides with `rotation fixed`, and the nodes a rigid body drives.
    for (int s = 0; s < GridSides::count; ++s)
        if (r.sideFixed[s])
            for (int n : e.sides.constrainedNodes(static_cast<GridSide>(s))) r.fixed[n] = 1;
    const auto rigidFixed = [&](int b) { return r.rigidFixed.empty() || r.rigidFixed[static_cast<std::size_t>(b)]; };
    e.coupling.forEachRigidNode(e.grid, e.rigid, [&](int n, int b) {
        if (rigidFixed(b)) r.fixed[n] = 1;
    });
    constrain(e.grid, r.rate);
}

void CosseratRotation::forces(EngineView& e)
{
    CosseratField& r = r_;
    const Particles& p = e.particles;
    const ShapeWeights& weights = e.weights;
    const int stride = weights.stride;
    e.strips.forEach([&](std::size_t q) {
        if (!isPolar(e, q)) return;
        const double V = p.V[q];
        const double skew = p.sigma[q][XY] - p.polar.sigma21[q];  // sigma12 - sigma21
        const Vector2& mu = p.polar.mu[q];
        const std::size_t k0 = q * stride;
        BodyField* body = e.coupling.bodyField(p.body[q]);
        for (int a = 0; a < stride; ++a) {
            const int n = weights.node[k0 + a];
            if (n < 0) continue;
            const Vector2& dN = weights.dN[k0 + a];
            // Balance of angular momentum, weak form: -int (mu3j N_,j + N (sigma12 - sigma21)) dV
            r.moment[n] -= V * (mu.x() * dN.x() + mu.y() * dN.y() + weights.N[k0 + a] * skew);
            // f_int,2 = -V (sigma21 N_,1 + sigma22 N_,2): computeForces used sigma12 in place of sigma21.
            const double correction = V * skew * dN.x();
            e.grid.fInt[n].y() += correction;
            if (body) body->force[n].y() += correction;
        }
    });
}

void CosseratRotation::update(EngineView& e, double dt)
{
    auto timer = e.timers.time("rotation");
    CosseratField& r = r_;
    const double damping = e.damping;
    e.grid.forEachActiveNode([&](int n) {
        if (r.fixed[n]) {
            r.accel[n] = 0.0;
            r.rate[n] = 0.0;
            return;
        }
        double M = r.moment[n];
        if (damping > 0) {  // A3: the moment is damped as a force, with the sign of w_i
            const double w = r.rate[n];
            M -= damping * std::abs(M) * (w > 0 ? 1.0 : (w < 0 ? -1.0 : 0.0));
        }
        r.accel[n] = r.inertia[n] > r.minInertia ? M / r.inertia[n] : 0.0;
        r.rate[n] += dt * r.accel[n];
    });
}

void CosseratRotation::strain(EngineView& e, double dt)
{
    auto timer = e.timers.time("rotation");
    Particles& p = e.particles;
    const CosseratField& r = r_;
    const ShapeWeights& weights = e.weights;
    const int stride = weights.stride;
    parallelFor(static_cast<long>(p.size()), [&](long q) {
        if (!isPolar(e, static_cast<std::size_t>(q))) return;
        double w = 0.0;
        Vector2 gradient = Vector2::Zero();
        const std::size_t k0 = q * stride;
        for (int a = 0; a < stride; ++a) {
            const int n = weights.node[k0 + a];
            if (n < 0) continue;
            w += weights.N[k0 + a] * r.rate[n];
            gradient += r.rate[n] * weights.dN[k0 + a];
        }
        // eq. 2.6.3: lambda12 = u1,2 + w3c, lambda21 = u2,1 - w3c, so their half difference
        // grows by the spin of the step dOmega = dt (v1,2 - v2,1)/2 plus dt w3c.
        p.polar.dRotation[q] = p.dOmega[q] + dt * w;
        p.polar.dKappa[q] = dt * gradient;  // eq. 2.6.2: kappa3j = w3c,j
        p.polar.kappa[q] += p.polar.dKappa[q];
    });
}

void CosseratRotation::addWork(EngineView& e)
{
    Particles& p = e.particles;
    parallelFor(static_cast<long>(p.size()), [&](long q) {
        if (!isPolar(e, static_cast<std::size_t>(q))) {
            p.polar.sigma21[q] = p.sigma[q][XY];  // a nonpolar stress is symmetric
            return;
        }
        // sigma12 dl12 + sigma21 dl21 + mu . dkappa beyond the 2 sigma12 de12 of the nonpolar work
        const double skew = p.sigma[q][XY] - p.polar.sigma21[q];
        p.work[q] += 0.5 * p.V[q] * (skew * (p.polar.dRotation[q] - p.dEps[q][XY]) + p.polar.mu[q].dot(p.polar.dKappa[q]));
    });
}

void CosseratRotation::toParticles(EngineView& e, double dt)
{
    Particles& p = e.particles;
    const CosseratField& r = r_;
    const ShapeWeights& weights = e.weights;
    const int stride = weights.stride;
    const double flip = e.transfer.rotationFlipShare(dt);  // FLIP under every transfer but FLIP's own blend
    parallelFor(static_cast<long>(p.size()), [&](long q) {
        if (!isPolar(e, static_cast<std::size_t>(q))) return;
        double w = 0.0, a = 0.0;
        const std::size_t k0 = q * stride;
        for (int k = 0; k < stride; ++k) {
            const int n = weights.node[k0 + k];
            if (n < 0) continue;
            w += weights.N[k0 + k] * r.rate[n];
            a += weights.N[k0 + k] * r.accel[n];
        }
        p.polar.w[q] += dt * w;                                                     // as eq. 2.4.7
        p.polar.omega[q] = flip * (p.polar.omega[q] + dt * a) + (1.0 - flip) * w;  // as eq. 2.4.8
    });
}

void CosseratRotation::remap(EngineView& e)
{
    CosseratField& r = r_;
    e.grid.forEachActiveNode([&](int n) { r.momentum[n] = 0.0; });
    spinToGrid(e, false);  // the step's inertia stays
    e.grid.forEachActiveNode(
        [&](int n) { r.rate[n] = r.inertia[n] > 0.0 && !r.fixed[n] ? r.momentum[n] / r.inertia[n] : 0.0; });
}

} // namespace gpic
