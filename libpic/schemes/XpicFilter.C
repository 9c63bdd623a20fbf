#include "schemes/XpicFilter.H"

namespace gpic {

void XpicFilter::at(StepPoint, EngineView& e, double dt)
{
    auto timer = e.timers.time("transferFilter");
    const int order = order_;
    const Grid& grid = e.grid;
    const GridCoupling& coupling = e.coupling;
    const int nFields = coupling.nFields();
    const auto nodes = static_cast<std::size_t>(grid.nNodes());
    filtered_.resize(static_cast<std::size_t>(nFields));
    scratch_.resize(2 * static_cast<std::size_t>(nFields));
    const auto isRigidField = [&](int f) { return coupling.isRigidField(f, e.rigid); };
    for (int f = 0; f < nFields; ++f) {
        filtered_[f].resize(nodes);
        scratch_[2 * f].resize(nodes);
        scratch_[2 * f + 1].resize(nodes);
        if (isRigidField(f)) continue;  // a rigid body's particles follow their driver
        const std::vector<Vector2>& v = coupling.velocity(grid, f);
        const std::vector<Vector2>& a = coupling.accel(grid, f);
        std::vector<Vector2>& w = scratch_[2 * f];
        grid.forEachActiveNode([&](int n) {
            w[n] = v[n] - dt * a[n];  // v^t with its conditions: the velocity the update started from
            filtered_[f][n] = double(order) * w[n];
        });
    }
    const Particles& p = e.particles;
    const ShapeWeights& weights = e.weights;
    const int stride = weights.stride;
    double binomial = order;  // C(m, k-1)
    for (int k = 2; k <= order; ++k) {
        binomial *= double(order - k + 1) / double(k);  // C(m, k)
        const double coefficient = (k % 2 == 0 ? -1.0 : 1.0) * binomial;
        for (int f = 0; f < nFields; ++f) {
            std::vector<Vector2>& next = scratch_[2 * f + 1];
            grid.forEachActiveNode([&](int n) { next[n].setZero(); });
        }
        // One projection grid -> particles -> grid per field: S^T M_p S w, then / m_i.
        e.strips.forEach([&](std::size_t q) {
            const int f = coupling.fieldOf(p.body[q]);
            if (isRigidField(f)) return;
            const std::vector<Vector2>& w = scratch_[2 * f];
            std::vector<Vector2>& next = scratch_[2 * f + 1];
            const std::size_t k0 = q * stride;
            Vector2 vq = Vector2::Zero();
            const double m = e.inertialMass(q);
            for (int c = 0; c < stride; ++c) {
                const int n = weights.node[k0 + c];
                if (n >= 0) vq += weights.N[k0 + c] * w[n];
            }
            for (int c = 0; c < stride; ++c) {
                const int n = weights.node[k0 + c];
                if (n >= 0) next[n] += (weights.N[k0 + c] * m) * vq;
            }
        });
        for (int f = 0; f < nFields; ++f) {
            if (isRigidField(f)) continue;
            const std::vector<double>& mass = coupling.mass(grid, f);
            std::vector<Vector2>& next = scratch_[2 * f + 1];
            grid.forEachActiveNode([&](int n) {
                next[n] = mass[n] > 0.0 ? Vector2(next[n] / mass[n]) : Vector2::Zero();
            });
            coupling.constrainFiltered(e, f, next, dt);
            grid.forEachActiveNode([&](int n) {
                filtered_[f][n] += coefficient * next[n];
            });
            scratch_[2 * f].swap(next);
        }
    }
}

} // namespace gpic
