#include "planar/CosseratRotation.H"

#include "core/Threads.H"
#include "engine/SolverInputs.H"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gpic {

GPIC_REGISTER_PASS(CosseratRotation, "cosseratRotation")

bool CosseratRotation::polarScene(const Particles<2>& particles, const std::vector<std::unique_ptr<Material<2>>>& materials)
{
    // A polar material that constant/materials lists but no body uses costs nothing.
    for (int m : particles.material)
        if (m >= 0 && m < static_cast<int>(materials.size()) && materials[m]->needsRotation()) return true;
    return false;
}

bool CosseratRotation::needed(const PassScene<2>& scene)
{
    return polarScene(scene.particles, scene.materials) || scene.inputs.carryRotation;
}

CosseratRotation::CosseratRotation(PassScene<2>& scene)
    : CosseratRotation(scene.materials, scene.sides, scene.grid.nNodes())
{
    ranks_ = scene.inputs.ranks;
    if (scene.inputs.rotationSides) setSideFixed(*scene.inputs.rotationSides);
    if (!scene.inputs.rigidRotation.empty()) setRigidFixed(std::move(scene.inputs.rigidRotation));
}

CosseratRotation::CosseratRotation(const std::vector<std::unique_ptr<Material<2>>>& materials,
                                   const GridSides<2>& sides, int nNodes)
{
    r_.materialPolar.assign(materials.size(), 0);
    r_.materialJ.assign(materials.size(), 0.0);
    for (std::size_t m = 0; m < materials.size(); ++m) {
        polar_.push_back(materials[m]->polar());
        r_.materialPolar[m] = polar_[m] != nullptr;
        r_.materialJ[m] = r_.materialPolar[m] ? polar_[m]->rotationalInertia() : 0.0;
    }
    for (int s = 0; s < GridSides<2>::count; ++s)  // w3c is odd under a reflection: zero on a symmetry plane
        r_.sideFixed[s] = sides.condition(static_cast<GridSide>(s)).isMirror();
    r_.allocate(nNodes);
}

std::vector<StepPoint> CosseratRotation::points() const
{
    return {StepPoint::afterParticlesToGrid, StepPoint::afterForces,      StepPoint::beforeGridUpdate,
            StepPoint::afterStrain,          StepPoint::afterStressUpdate, StepPoint::afterGridToParticles,
            StepPoint::afterRemap};
}

void CosseratRotation::at(StepPoint point, EngineView<2>& e, double dt)
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

void CosseratRotation::setUpParticles(Particles<2>& p)
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
    lightestHere_ = lightest;
}

double CosseratRotation::maxDeltaT(std::size_t m, double h, double massScale) const
{
    if (!polar_[m]) return 1e300;
    const double step = polar_[m]->rotationalTimeStep(h);
    return massScale == 1.0 ? step : step * std::sqrt(massScale);
}

void CosseratRotation::constrain(const Grid<2>& grid, std::vector<double>& field) const
{
    for (int n : grid.active)
        if (r_.fixed[n]) field[n] = 0.0;
}

void CosseratRotation::spinToGrid(EngineView<2>& e, bool withInertia)
{
    const Particles<2>& p = e.particles;
    const ShapeWeights<2>& weights = e.weights;
    const int stride = weights.stride;
    // Pointers captured by value (ParticleStrips::forEach, doc/threading.md).
    const PolarTest polar = polarTest(e);
    const int* node = weights.node.data();
    const double* Nw = weights.N.data();
    const int* material = p.material.data();
    const double* omega = p.polar.omega.data();
    const double* J = r_.materialJ.data();
    double* inertia = r_.inertia.data();
    double* momentum = r_.momentum.data();
    e.strips.forEach([&e, polar, node, Nw, material, omega, J, inertia, momentum, stride, withInertia](std::size_t q) {
        if (!polar(q)) return;
        const double mJ = e.inertialMass(q) * J[material[q]];
        const double w = omega[q];  // held: the stores below are doubles too
        const std::size_t k0 = q * stride;
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            if (n < 0) continue;
            const double NmJ = Nw[k0 + a] * mJ;
            if (withInertia) inertia[n] += NmJ;  // lumped rotational inertia
            momentum[n] += NmJ * w;  // spin momentum, as eq. 2.4.1
        }
    });
}

void CosseratRotation::toGrid(EngineView<2>& e)
{
    CosseratField& r = r_;
    e.grid.forEachActiveNode([&](int n) {
        r.inertia[n] = r.momentum[n] = r.moment[n] = r.accel[n] = 0.0;
        r.fixed[n] = 0;
    });
    spinToGrid(e, true);
    if (e.rankSums) {  // a parallel run: the other ranks' parts, and every rank's lightest
        e.rankSums->complete(e.grid, r.inertia);
        e.rankSums->complete(e.grid, r.momentum);
        const double none = std::numeric_limits<double>::max();
        const double lightest = ranks_.smallest(lightestHere_ > 0 ? lightestHere_ : none);
        r.minInertia = lightest < none ? 1e-9 * lightest : 0.0;
    }
    e.grid.forEachActiveNode([&](int n) { r.rate[n] = r.inertia[n] > 0.0 ? r.momentum[n] / r.inertia[n] : 0.0; });
    // Conditions: sides with `rotation fixed`, and the nodes a rigid body drives.
    for (int s = 0; s < GridSides<2>::count; ++s)
        if (r.sideFixed[s])
            for (int n : e.sides.constrainedNodes(static_cast<GridSide>(s))) r.fixed[n] = 1;
    const auto rigidFixed = [&](int b) { return r.rigidFixed.empty() || r.rigidFixed[static_cast<std::size_t>(b)]; };
    e.coupling.forEachRigidNode(e.grid, e.rigid, [&](int n, int b) {
        if (rigidFixed(b)) r.fixed[n] = 1;
    });
    constrain(e.grid, r.rate);
}

void CosseratRotation::forces(EngineView<2>& e)
{
    const Particles<2>& p = e.particles;
    const ShapeWeights<2>& weights = e.weights;
    const int stride = weights.stride;
    // Pointers captured by value (ParticleStrips::forEach, doc/threading.md).
    const PolarTest polar = polarTest(e);
    const int* node = weights.node.data();
    const double* Nw = weights.N.data();
    const Vector2* dNw = weights.dN.data();
    const int* body = p.body.data();
    const double* volume = p.V.data();
    const SymTensor* sigma = p.sigma.data();
    const double* sigma21 = p.polar.sigma21.data();
    const Vector2* couple = p.polar.mu.data();
    double* moment = r_.moment.data();
    Vector2* fInt = e.grid.fInt.data();
    const GridCoupling<2>& coupling = e.coupling;
    e.strips.forEach([&coupling, polar, node, Nw, dNw, body, volume, sigma, sigma21, couple, moment, fInt,
                      stride](std::size_t q) {
        if (!polar(q)) return;
        const double V = volume[q];
        const double skew = sigma[q][XY] - sigma21[q];  // sigma12 - sigma21
        const Vector2 mu = couple[q];
        const std::size_t k0 = q * stride;
        BodyField<2>* field = coupling.bodyField(body[q]);
        Vector2* bodyForce = field ? field->force.data() : nullptr;
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            if (n < 0) continue;
            const Vector2 dN = dNw[k0 + a];
            // Balance of angular momentum, weak form: -int (mu3j N_,j + N (sigma12 - sigma21)) dV
            moment[n] -= V * (mu.x() * dN.x() + mu.y() * dN.y() + Nw[k0 + a] * skew);
            // f_int,2 = -V (sigma21 N_,1 + sigma22 N_,2): computeForces used sigma12 in place of sigma21.
            const double correction = V * skew * dN.x();
            fInt[n].y() += correction;
            if (bodyForce) bodyForce[n].y() += correction;
        }
    });
}

void CosseratRotation::update(EngineView<2>& e, double dt)
{
    auto timer = e.timers.time("rotation");
    CosseratField& r = r_;
    if (e.rankSums) e.rankSums->complete(e.grid, r.moment);  // a parallel run: the other ranks' parts
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

void CosseratRotation::strain(EngineView<2>& e, double dt)
{
    auto timer = e.timers.time("rotation");
    Particles<2>& p = e.particles;
    const ShapeWeights<2>& weights = e.weights;
    const int stride = weights.stride;
    // Pointers held by value: the stores of Vector2 below may alias anything (doc/threading.md).
    const PolarTest polar = polarTest(e);
    const int* node = weights.node.data();
    const double* Nw = weights.N.data();
    const Vector2* dNw = weights.dN.data();
    const double* rate = r_.rate.data();
    const double* dOmega = p.dOmega.data();
    double* dRotation = p.polar.dRotation.data();
    Vector2* dKappa = p.polar.dKappa.data();
    Vector2* kappa = p.polar.kappa.data();
    parallelFor(static_cast<long>(p.size()), [=](long q) {
        if (!polar(static_cast<std::size_t>(q))) return;
        double w = 0.0;
        Vector2 gradient = Vector2::Zero();
        const std::size_t k0 = q * stride;
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            if (n < 0) continue;
            w += Nw[k0 + a] * rate[n];
            gradient += rate[n] * dNw[k0 + a];
        }
        // eq. 2.6.3: lambda12 = u1,2 + w3c, lambda21 = u2,1 - w3c, so their half difference
        // grows by the spin of the step dOmega = dt (v1,2 - v2,1)/2 plus dt w3c.
        dRotation[q] = dOmega[q] + dt * w;
        dKappa[q] = dt * gradient;  // eq. 2.6.2: kappa3j = w3c,j
        kappa[q] += dKappa[q];
    });
}

void CosseratRotation::addWork(EngineView<2>& e)
{
    Particles<2>& p = e.particles;
    const PolarTest polar = polarTest(e);
    const double* V = p.V.data();
    const SymTensor* sigma = p.sigma.data();
    const SymTensor* dEps = p.dEps.data();
    const double* dRotation = p.polar.dRotation.data();
    const Vector2* mu = p.polar.mu.data();
    const Vector2* dKappa = p.polar.dKappa.data();
    double* sigma21 = p.polar.sigma21.data();
    double* work = p.work.data();
    parallelFor(static_cast<long>(p.size()), [=](long q) {
        if (!polar(static_cast<std::size_t>(q))) {
            sigma21[q] = sigma[q][XY];  // a nonpolar stress is symmetric
            return;
        }
        // sigma12 dl12 + sigma21 dl21 + mu . dkappa beyond the 2 sigma12 de12 of the nonpolar work
        const double skew = sigma[q][XY] - sigma21[q];
        work[q] += 0.5 * V[q] * (skew * (dRotation[q] - dEps[q][XY]) + mu[q].dot(dKappa[q]));
    });
}

void CosseratRotation::toParticles(EngineView<2>& e, double dt)
{
    Particles<2>& p = e.particles;
    const ShapeWeights<2>& weights = e.weights;
    const int stride = weights.stride;
    const double flip = e.transfer.rotationFlipShare(dt);  // FLIP under every transfer but FLIP's own blend
    const PolarTest polar = polarTest(e);
    const int* node = weights.node.data();
    const double* Nw = weights.N.data();
    const double* rate = r_.rate.data();
    const double* accel = r_.accel.data();
    double* rotation = p.polar.w.data();
    double* omega = p.polar.omega.data();
    parallelFor(static_cast<long>(p.size()), [=](long q) {
        if (!polar(static_cast<std::size_t>(q))) return;
        double w = 0.0, a = 0.0;
        const std::size_t k0 = q * stride;
        for (int k = 0; k < stride; ++k) {
            const int n = node[k0 + k];
            if (n < 0) continue;
            w += Nw[k0 + k] * rate[n];
            a += Nw[k0 + k] * accel[n];
        }
        rotation[q] += dt * w;                                      // as eq. 2.4.7
        omega[q] = flip * (omega[q] + dt * a) + (1.0 - flip) * w;  // as eq. 2.4.8
    });
}

void CosseratRotation::remap(EngineView<2>& e)
{
    CosseratField& r = r_;
    e.grid.forEachActiveNode([&](int n) { r.momentum[n] = 0.0; });
    spinToGrid(e, false);  // the step's inertia stays
    if (e.rankSums) e.rankSums->complete(e.grid, r.momentum);
    e.grid.forEachActiveNode(
        [&](int n) { r.rate[n] = r.inertia[n] > 0.0 && !r.fixed[n] ? r.momentum[n] / r.inertia[n] : 0.0; });
}

} // namespace gpic
