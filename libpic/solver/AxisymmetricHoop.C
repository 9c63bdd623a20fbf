#include "solver/AxisymmetricHoop.H"

#include "core/Threads.H"

namespace gpic {

void AxisymmetricHoop::at(StepPoint point, EngineView& e, double dt)
{
    if (point == StepPoint::afterForces) addHoopForces(e);
    else addHoopStrain(e, dt);
}

void AxisymmetricHoop::addHoopForces(EngineView& e) const
{
    const Particles& p = e.particles;
    const ShapeWeights& w = e.weights;
    const int stride = w.stride;
    e.strips.forEach([&](std::size_t q) {
        if (e.isRigid(q)) return;  // a rigid body carries no stress
        BodyField* body = e.coupling.bodyField(p.body[q]);
        const std::size_t k0 = q * stride;
        // -V_p sigma_tt <N_i / r>: N_i(x_p) / r_p at a point, the ring's own weight for uGIMP.
        const bool own = !w.hoop.empty();
        const double hoop = own ? p.V[q] * p.sigma[q][ZZ] : p.V[q] * p.sigma[q][ZZ] / p.x[q].x();
        for (int a = 0; a < stride; ++a) {
            const int n = w.node[k0 + a];
            if (n < 0) continue;
            const double f = -hoop * (own ? w.hoop[k0 + a] : w.N[k0 + a]);
            e.grid.fInt[n].x() += f;
            if (body) body->force[n].x() += f;
        }
    });
}

void AxisymmetricHoop::addHoopStrain(EngineView& e, double dt) const
{
    Particles& p = e.particles;
    const ShapeWeights& w = e.weights;
    const int stride = w.stride;
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
    });
}

} // namespace gpic
