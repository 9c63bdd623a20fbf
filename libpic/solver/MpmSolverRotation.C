// The micro-rotation passes of a polar (Cosserat) scene: MpmSolver member functions called
// from the translational passes only when hasRotation_ (seed 2.6, appendix F, A11; the
// derivation is in doc/cosserat.md). One rotational degree of freedom w3c per node, mapped
// like the velocity:
//     I_i = sum_p N_ip m_p J33_p,   I_i w_i = sum_p N_ip m_p J33_p w_p           (P2G)
//     M_i = -sum_p V_p [mu31 N_ip,1 + mu32 N_ip,2 + N_ip (sigma12 - sigma21)]     (weak form)
//     I_i dw_i/dt = M_i - alpha |M_i| sign(w_i),  w_i^{t+1} = w_i + dt dw_i/dt    (A3)
//     d lambda12 - d lambda21 = 2 (dOmega + dt sum N w_i),  d kappa3j = dt sum N_,j w_i
//     w_p += dt sum N w_i^{t+1},   w_p' += dt sum N dw_i/dt                      (G2P)
// With a contact pass every body shares this one rotation field.
#include "solver/MpmSolver.H"

#include "core/Threads.H"
#include "dictionary/Dictionary.H"

#include <algorithm>
#include <cmath>

namespace gpic {

void CosseratField::allocate(int nNodes)
{
    const auto n = static_cast<std::size_t>(nNodes);
    inertia.assign(n, 0.0);
    momentum.assign(n, 0.0);
    rate.assign(n, 0.0);
    moment.assign(n, 0.0);
    accel.assign(n, 0.0);
    fixed.assign(n, 0);
}

std::array<bool, 4> readRotationSides(const Dictionary& gridDict, const std::array<bool, 4>& mirror)
{
    std::array<bool, 4> fixed{};
    const Dictionary& sides = gridDict.subDict("boundaries");
    for (int s = 0; s < 4; ++s) {
        const Dictionary& side = sides.subDict(gridSideNames()[s]);
        const std::string deflt = mirror[s] ? "fixed" : "free";
        fixed[s] = side.getWordOrDefault("rotation", {"fixed", "free"}, deflt) == "fixed";
    }
    return fixed;
}

std::vector<char> readRigidRotation(const Dictionary& rigidBodies, const std::vector<std::string>& bodyNames)
{
    std::vector<char> fixed(bodyNames.size(), 1);
    for (std::size_t b = 0; b < bodyNames.size(); ++b)
        if (rigidBodies.isDict(bodyNames[b]))
            fixed[b] = rigidBodies.subDict(bodyNames[b]).getWordOrDefault("rotation", {"fixed", "free"}, "fixed") ==
                       "fixed";
    return fixed;
}

void MpmSolver::setupRotation()
{
    if (!hasRotation_) {
        rotation_ = CosseratField{};
        return;
    }
    CosseratField& r = rotation_;
    r.materialPolar.assign(materials_.size(), 0);
    r.materialJ.assign(materials_.size(), 0.0);
    for (std::size_t m = 0; m < materials_.size(); ++m) {
        r.materialPolar[m] = materials_[m]->needsRotation();
        r.materialJ[m] = r.materialPolar[m] ? materials_[m]->rotationalInertia() : 0.0;
    }
    for (int s = 0; s < 4; ++s)  // w3c is odd under a reflection: zero on a symmetry plane
        r.sideFixed[s] = boundaries_[s]->isMirror();
    r.allocate(grid_.nNodes());
}

void MpmSolver::setupRotationParticles()
{
    Particles& p = particles_;
    if (!hasRotation_) {
        p.drop(FieldGroup::polar);
        return;
    }
    if (!p.carries(FieldGroup::polar)) {
        // A state without rotation arrays (a new case, or particles new to the scene): no
        // micro-rotation, no couple stress, sigma21 = sigma12 (seed A2: the initial stress
        // is symmetric).
        p.carry(FieldGroup::polar);
        for (std::size_t q = 0; q < p.size(); ++q) p.polar.sigma21[q] = p.sigma[q][XY];
    }
    double lightest = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const double mJ = p.m[q] * rotation_.materialJ[static_cast<std::size_t>(p.material[q])];
        if (mJ > 0) lightest = lightest == 0 ? mJ : std::min(lightest, mJ);
    }
    rotation_.minInertia = 1e-9 * lightest;
}

void MpmSolver::constrainRotation(std::vector<double>& field) const
{
    for (int n : grid_.active)
        if (rotation_.fixed[n]) field[n] = 0.0;
}

void MpmSolver::rotationToGrid()
{
    CosseratField& r = rotation_;
    const Particles& p = particles_;
    grid_.forEachActiveNode([&](int n) {
        r.inertia[n] = r.momentum[n] = r.moment[n] = r.accel[n] = 0.0;
        r.fixed[n] = 0;
    });
    const int stride = weights_.stride;
    strips_.forEach([&](std::size_t q) {
        if (!isPolar(q)) return;
        const double mJ = p.m[q] * r.materialJ[static_cast<std::size_t>(p.material[q])];
        const std::size_t k0 = q * stride;
        for (int a = 0; a < stride; ++a) {
            const int n = weights_.node[k0 + a];
            if (n < 0) continue;
            const double NmJ = weights_.N[k0 + a] * mJ;
            r.inertia[n] += NmJ;                    // lumped rotational inertia
            r.momentum[n] += NmJ * p.polar.omega[q];  // spin momentum, as eq. 2.4.1
        }
    });
    grid_.forEachActiveNode([&](int n) {
        r.rate[n] = r.inertia[n] > 0.0 ? r.momentum[n] / r.inertia[n] : 0.0;
    });
    // Conditions: sides with `rotation fixed`, and the nodes a rigid body drives.
    for (int s = 0; s < 4; ++s)
        if (r.sideFixed[s])
            for (int n : sideNodes_[s]) r.fixed[n] = 1;
    const auto rigidFixed = [&](int b) {
        return r.rigidFixed.empty() || r.rigidFixed[static_cast<std::size_t>(b)];
    };
    if (drivesRigidNodes()) {
        for (int n : grid_.active)
            if (rigidNodes_.bodyAt(n) >= 0 && rigidFixed(rigidNodes_.bodyAt(n))) r.fixed[n] = 1;
    } else if (contact_ && !rigid_.empty()) {
        for (int b = 0; b < contact_->nBodies(); ++b)
            if (rigid_[b] && rigidFixed(b))
                for (int n : grid_.active)
                    if (contact_->field(b).mass[n] > 0.0) r.fixed[n] = 1;
    }
    constrainRotation(r.rate);
}

void MpmSolver::rotationForces()
{
    CosseratField& r = rotation_;
    const Particles& p = particles_;
    const int stride = weights_.stride;
    strips_.forEach([&](std::size_t q) {
        if (!isPolar(q)) return;
        const double V = p.V[q];
        const double skew = p.sigma[q][XY] - p.polar.sigma21[q];  // sigma12 - sigma21
        const Vector2& mu = p.polar.mu[q];
        const std::size_t k0 = q * stride;
        BodyField* body = contact_ ? &contact_->field(p.body[q]) : nullptr;
        for (int a = 0; a < stride; ++a) {
            const int n = weights_.node[k0 + a];
            if (n < 0) continue;
            const Vector2& dN = weights_.dN[k0 + a];
            // Balance of angular momentum, weak form: -int (mu3j N_,j + N (sigma12 - sigma21)) dV
            r.moment[n] -= V * (mu.x() * dN.x() + mu.y() * dN.y() + weights_.N[k0 + a] * skew);
            // f_int,2 = -V (sigma21 N_,1 + sigma22 N_,2): computeForces used sigma12 in place of sigma21.
            const double correction = V * skew * dN.x();
            grid_.fInt[n].y() += correction;
            if (body) body->force[n].y() += correction;
        }
    });
}

void MpmSolver::updateRotation(double dt)
{
    auto timer = timers_.time("rotation");
    CosseratField& r = rotation_;
    grid_.forEachActiveNode([&](int n) {
        if (r.fixed[n]) {
            r.accel[n] = 0.0;
            r.rate[n] = 0.0;
            return;
        }
        double M = r.moment[n];
        if (damping_ > 0) {  // A3: the moment is damped as a force, with the sign of w_i
            const double w = r.rate[n];
            M -= damping_ * std::abs(M) * (w > 0 ? 1.0 : (w < 0 ? -1.0 : 0.0));
        }
        r.accel[n] = r.inertia[n] > r.minInertia ? M / r.inertia[n] : 0.0;
        r.rate[n] += dt * r.accel[n];
    });
}

void MpmSolver::rotationStrain(double dt)
{
    auto timer = timers_.time("rotation");
    Particles& p = particles_;
    const CosseratField& r = rotation_;
    const int stride = weights_.stride;
    const auto nParticles = static_cast<long>(p.size());
    parallelFor(nParticles, [&](long q) {
        if (!isPolar(static_cast<std::size_t>(q))) return;
        double w = 0.0;
        Vector2 gradient = Vector2::Zero();
        const std::size_t k0 = q * stride;
        for (int a = 0; a < stride; ++a) {
            const int n = weights_.node[k0 + a];
            if (n < 0) continue;
            w += weights_.N[k0 + a] * r.rate[n];
            gradient += r.rate[n] * weights_.dN[k0 + a];
        }
        // eq. 2.6.3: lambda12 = u1,2 + w3c, lambda21 = u2,1 - w3c, so their half difference
        // grows by the spin of the step dOmega = dt (v1,2 - v2,1)/2 plus dt w3c.
        p.polar.dRotation[q] = p.dOmega[q] + dt * w;
        p.polar.dKappa[q] = dt * gradient;  // eq. 2.6.2: kappa3j = w3c,j
        p.polar.kappa[q] += p.polar.dKappa[q];
    });
}

void MpmSolver::addRotationWork()
{
    Particles& p = particles_;
    const auto nParticles = static_cast<long>(p.size());
    parallelFor(nParticles, [&](long q) {
        if (!isPolar(static_cast<std::size_t>(q))) {
            p.polar.sigma21[q] = p.sigma[q][XY];  // a nonpolar stress is symmetric
            return;
        }
        // sigma12 dl12 + sigma21 dl21 + mu . dkappa beyond the 2 sigma12 de12 of the nonpolar work
        const double skew = p.sigma[q][XY] - p.polar.sigma21[q];
        p.work[q] += 0.5 * p.V[q] *
                     (skew * (p.polar.dRotation[q] - p.dEps[q][XY]) + p.polar.mu[q].dot(p.polar.dKappa[q]));
    });
}

void MpmSolver::rotationToParticles(double dt)
{
    Particles& p = particles_;
    const CosseratField& r = rotation_;
    const int stride = weights_.stride;
    const auto nParticles = static_cast<long>(p.size());
    const double flip = transfer_->rotationFlipShare(dt);  // FLIP under every transfer but FLIP's own blend
    parallelFor(nParticles, [&](long q) {
        if (!isPolar(static_cast<std::size_t>(q))) return;
        double w = 0.0, a = 0.0;
        const std::size_t k0 = q * stride;
        for (int k = 0; k < stride; ++k) {
            const int n = weights_.node[k0 + k];
            if (n < 0) continue;
            w += weights_.N[k0 + k] * r.rate[n];
            a += weights_.N[k0 + k] * r.accel[n];
        }
        p.polar.w[q] += dt * w;  // as eq. 2.4.7
        p.polar.omega[q] = flip * (p.polar.omega[q] + dt * a) + (1.0 - flip) * w;  // as eq. 2.4.8
    });
}

void MpmSolver::remapRotation()
{
    CosseratField& r = rotation_;
    const Particles& p = particles_;
    grid_.forEachActiveNode([&](int n) { r.momentum[n] = 0.0; });
    const int stride = weights_.stride;
    strips_.forEach([&](std::size_t q) {
        if (!isPolar(q)) return;
        const double mJ = p.m[q] * r.materialJ[static_cast<std::size_t>(p.material[q])];
        const std::size_t k0 = q * stride;
        for (int a = 0; a < stride; ++a) {
            const int n = weights_.node[k0 + a];
            if (n >= 0) r.momentum[n] += weights_.N[k0 + a] * mJ * p.polar.omega[q];
        }
    });
    grid_.forEachActiveNode([&](int n) {
        r.rate[n] = r.inertia[n] > 0.0 && !r.fixed[n] ? r.momentum[n] / r.inertia[n] : 0.0;
    });
}

double MpmSolver::rotationalTimeStep() const
{
    double dt = 1e300;
    for (std::size_t m = 0; m < materials_.size(); ++m)
        if (materialDeforms_[m] && materials_[m]->needsRotation())
            dt = std::min(dt, materials_[m]->rotationalTimeStep(grid_.minCellSize()));
    return dt;
}

} // namespace gpic
