#include "planar/AxisymmetricHoop.H"

#include "core/Threads.H"
#include "engine/SolverInputs.H"

#include <cmath>
#include <limits>

namespace gpic {

GPIC_REGISTER_PASS(AxisymmetricHoop, "axisymmetricHoop")

AxisymmetricHoop::AxisymmetricHoop(PassScene<2>& scene) : AxisymmetricHoop(scene.inputs.cellMeanDilatation) {}

double AxisymmetricHoop::stepLength(const Grid<2>& grid, const Particles<2>& particles,
                                    const DeformingParticles<2>& deforms) const
{
    // The hoop term stiffens the radial motion of a node at radius r_i by about a quarter of
    // (h / r_i)^2 of its in-plane stiffness (lumped mass, 2 x 2 particles a cell: 0.19 at the
    // first node off the axis): the step shrinks by the root of 1 + (h / r_i)^2 / 4 at the
    // innermost node a deforming particle moves (not the axis, where u_r = 0).
    const double hr = grid.cellSize().x(), r0 = grid.origin().x();
    double rNode = std::numeric_limits<double>::infinity();
    for (std::size_t q = 0; q < particles.size(); ++q) {
        if (!deforms(particles, q)) continue;
        const double r = r0 + std::floor((particles.x[q].x() - r0) / hr) * hr;
        rNode = std::min(rNode, r > 0.5 * hr ? r : r + hr);
    }
    if (!std::isfinite(rNode)) return grid.minCellSize();
    return grid.minCellSize() / std::sqrt(1.0 + 0.25 * (hr / rNode) * (hr / rNode));
}

namespace {

//- (sigma_rr + sigma_zz + sigma_tt) / 3
double meanStressOf(const Particles<2>& p, std::size_t q) { return (p.sigma[q][XX] + p.sigma[q][YY] + p.sigma[q][ZZ]) / 3; }

} // namespace

void AxisymmetricHoop::at(StepPoint point, EngineView<2>& e, double dt)
{
    if (point == StepPoint::afterParticlesToGrid) means_.assign(e.grid, e.particles, [&](std::size_t q) { return e.isRigid(q); });
    else if (point == StepPoint::afterForces) addHoopForces(e);
    else if (point == StepPoint::afterStressUpdate) means_.holdCellPressure(e.particles, mean_);
    else addHoopStrain(e, dt);
}

void AxisymmetricHoop::addHoopForces(EngineView<2>& e)
{
    const Particles<2>& p = e.particles;
    const ShapeWeights<2>& w = e.weights;
    const int stride = w.stride;
    if (cellMean_) means_.average(p, [&](std::size_t q) { return meanStressOf(p, q); }, mean_);
    // The arrays' pointers in locals: the stores into the nodes may alias anything, and what
    // the loop reads through memory is reloaded after each of them (doc/threading.md).
    const int* node = w.node.data();
    // -V_p sigma_tt <N_i / r>: N_i(x_p) / r_p at a point, the ring's own weight for uGIMP.
    const bool own = !w.hoop.empty();
    const double* weight = own ? w.hoop.data() : w.N.data();
    const Vector2* dN = w.dN.data();
    Vector2* fInt = e.grid.fInt.data();
    const bool cellMean = cellMean_;
    const double* mean = mean_.data();
    e.strips.forEach([&e, &p, node, own, weight, dN, fInt, cellMean, mean, stride](std::size_t q) {
        if (e.isRigid(q)) return;  // a rigid body carries no stress
        BodyField<2>* body = e.coupling.bodyField(p.body[q]);
        Vector2* bodyForce = body ? body->force.data() : nullptr;
        const std::size_t k0 = q * stride;
        // cellMean: the cell's mean stress in place of the particle's own, sigma + dp I; the
        // in-plane part of that shift is the correction -V_p dp grad N_ip.
        const double dp = cellMean ? mean[q] - meanStressOf(p, q) : 0.0;
        const double stt = p.sigma[q][ZZ] + dp;
        const double Vp = p.V[q];
        const double hoop = own ? Vp * stt : Vp * stt / p.x[q].x();
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            if (n < 0) continue;
            const double f = -hoop * weight[k0 + a];
            fInt[n].x() += f;
            if (bodyForce) bodyForce[n].x() += f;
            if (cellMean) {
                const Vector2 shift = -(Vp * dp) * dN[k0 + a];
                fInt[n] += shift;
                if (bodyForce) bodyForce[n] += shift;
            }
        }
    });
}

void AxisymmetricHoop::addHoopStrain(EngineView<2>& e, double dt)
{
    Particles<2>& p = e.particles;
    const ShapeWeights<2>& w = e.weights;
    const int stride = w.stride;
    if (cellMean_) value_.assign(p.size(), 0.0);
    parallelFor(static_cast<long>(p.size()), [&](long q) {
        if (e.isRigid(static_cast<std::size_t>(q))) return;
        const std::vector<Vector2>& velocity = e.coupling.velocity(e.grid, e.coupling.fieldOf(p.body[q]));
        const std::size_t k0 = static_cast<std::size_t>(q) * stride;
        double de;
        if (w.hoop.empty()) {  // v_r(x_p) / r_p
            double vr = 0;
            for (int a = 0; a < stride; ++a) {
                const int n = w.node[k0 + a];
                if (n >= 0) vr += w.N[k0 + a] * velocity[n].x();
            }
            de = dt * vr / p.x[q].x();
        } else {  // <v_r / r> over the ring
            double vrOverR = 0;
            for (int a = 0; a < stride; ++a) {
                const int n = w.node[k0 + a];
                if (n >= 0) vrOverR += w.hoop[k0 + a] * velocity[n].x();
            }
            de = dt * vrOverR;
        }
        p.dEps[q][ZZ] = de;
        p.eps[q][ZZ] += de;
        p.V[q] *= 1.0 + de;
        p.work[q] += 0.5 * p.V[q] * p.sigma[q][ZZ] * de;  // the first half of the trapezoid, as in-plane
        if (cellMean_) value_[q] = p.dEps[q][XX] + p.dEps[q][YY] + de;  // the dilatation increment
    });
    if (!cellMean_) return;
    // The cell's mean dilatation increment in place of the particle's own: each normal strain
    // takes a third of the difference; shear and spin stay the particle's own.
    means_.average(p, [&](std::size_t q) { return value_[q]; }, mean_);
    parallelFor(static_cast<long>(p.size()), [&](long q) {
        if (e.isRigid(static_cast<std::size_t>(q))) return;
        const double c = (mean_[q] - value_[q]) / 3;
        for (int k : {XX, YY, ZZ}) {
            p.dEps[q][k] += c;
            p.eps[q][k] += c;
        }
        p.V[q] *= (1.0 + c) * (1.0 + c) * (1.0 + c);
        p.work[q] += 0.5 * p.V[q] * 3 * meanStressOf(p, q) * c;
    });
}

} // namespace gpic
