#include "schemes/XpicFilter.H"

namespace gpic {

GPIC_REGISTER_PASS_DIMS(XpicFilter, "xpicFilter")

template <int D>
void XpicFilter<D>::at(StepPoint, EngineView<D>& e, double dt)
{
    auto timer = e.timers.time("transferFilter");
    const int order = order_;
    const Grid<D>& grid = e.grid;
    const GridCoupling<D>& coupling = e.coupling;
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
        const Vector* v = coupling.velocity(grid, f).data();
        const Vector* a = coupling.accel(grid, f).data();
        Vector* w = scratch_[2 * f].data();
        Vector* filtered = filtered_[f].data();
        grid.forEachActiveNode([=](int n) {
            w[n] = v[n] - dt * a[n];  // v^t with its conditions: the velocity the update started from
            filtered[n] = double(order) * w[n];
        });
    }
    const Particles<D>& p = e.particles;
    const ShapeWeights<D>& weights = e.weights;
    const int stride = weights.stride;
    double binomial = order;  // C(m, k-1)
    for (int k = 2; k <= order; ++k) {
        binomial *= double(order - k + 1) / double(k);  // C(m, k)
        const double coefficient = (k % 2 == 0 ? -1.0 : 1.0) * binomial;
        for (int f = 0; f < nFields; ++f) {
            Vector* next = scratch_[2 * f + 1].data();
            grid.forEachActiveNode([=](int n) { next[n].setZero(); });
        }
        // One projection grid -> particles -> grid per field: S^T M_p S w, then / m_i. The
        // arrays' pointers in locals and tables: Eigen's SSE stores may alias anything, and
        // what the loop reads through memory is reloaded after each (doc/threading.md).
        std::vector<const Vector*> iterateOf(nFields);
        std::vector<Vector*> projectedOf(nFields);
        std::vector<char> rigidOf(nFields);
        for (int f = 0; f < nFields; ++f) {
            iterateOf[f] = scratch_[2 * f].data();
            projectedOf[f] = scratch_[2 * f + 1].data();
            rigidOf[f] = isRigidField(f);
        }
        const Vector* const* from = iterateOf.data();
        Vector* const* to = projectedOf.data();
        const char* skip = rigidOf.data();
        const int* node = weights.node.data();
        const double* Nw = weights.N.data();
        const int* body = p.body.data();
        e.strips.forEach([&e, &coupling, from, to, skip, node, Nw, body, stride](std::size_t q) {
            const int f = coupling.fieldOf(body[q]);
            if (skip[f]) return;  // a rigid body's particles follow their driver
            const Vector* w = from[f];
            Vector* next = to[f];
            const std::size_t k0 = q * stride;
            Vector vq = Vector::Zero();
            const double m = e.inertialMass(q);
            for (int c = 0; c < stride; ++c) {
                const int n = node[k0 + c];
                if (n >= 0) vq += Nw[k0 + c] * w[n];
            }
            for (int c = 0; c < stride; ++c) {
                const int n = node[k0 + c];
                if (n >= 0) next[n] += (Nw[k0 + c] * m) * vq;
            }
        });
        for (int f = 0; f < nFields; ++f) {
            if (isRigidField(f)) continue;
            const double* mass = coupling.mass(grid, f).data();
            std::vector<Vector>& next = scratch_[2 * f + 1];
            if (e.rankSums) e.rankSums->complete(grid, next);  // a parallel run: the other ranks' parts
            Vector* projected = next.data();
            grid.forEachActiveNode([=](int n) {
                projected[n] = mass[n] > 0.0 ? Vector(projected[n] / mass[n]) : Vector::Zero();
            });
            coupling.constrainFiltered(e, f, next, dt);
            Vector* filtered = filtered_[f].data();
            grid.forEachActiveNode([=](int n) { filtered[n] += coefficient * projected[n]; });
            scratch_[2 * f].swap(next);
        }
    }
}

template class XpicFilter<2>;
#if GPIC_WITH_3D
template class XpicFilter<3>;
#endif

} // namespace gpic
