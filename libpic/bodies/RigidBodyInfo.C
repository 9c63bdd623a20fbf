#include "bodies/RigidBodyDriver.H"
#include "particles/Particles.H"

#include <Eigen/LU>

namespace gpic {

template <int D>
std::vector<RigidBodyInfo<D>> RigidBodyInfo<D>::ofBodies(const Particles<D>& p, std::size_t nBodies, const Vector& gravity)
{
    std::vector<RigidBodyInfo<D>> info(nBodies);
    for (std::size_t q = 0; q < p.size(); ++q) {
        auto& b = info[p.body[q]];
        b.mass += p.m[q];
        b.centroid += p.m[q] * p.x[q];
        b.velocity += p.m[q] * p.v[q];
    }
    for (auto& b : info) {
        if (b.mass > 0) b.centroid /= b.mass;
        if (b.mass > 0) b.velocity /= b.mass;
        b.gravity = gravity;
    }
    // The spin comes from the points' own inertia and angular momentum: the inertia adds each
    // particle's domain, which a point's velocity does not turn.
    std::vector<typename Space<D>::Inertia> pointInertia(nBodies, zeroInertia());
    std::vector<typename Space<D>::Moment> momentum(nBodies, Space<D>::zeroMoment());
    for (std::size_t q = 0; q < p.size(); ++q) {
        auto& b = info[p.body[q]];
        const Vector& a = p.halfSize[q];
        const Vector r = p.x[q] - b.centroid;
        momentum[p.body[q]] += p.m[q] * momentOf(r, p.v[q]);
        if constexpr (D == 2) {
            b.inertia += p.m[q] * (r.squaredNorm() + a.squaredNorm() / 3.0);
            pointInertia[p.body[q]] += p.m[q] * r.squaredNorm();
        } else {  // the point's parallel-axis term and its box of half-sizes a about its centre
            const Vector a2 = a.cwiseProduct(a);
            const Vector box(a2.y() + a2.z(), a2.x() + a2.z(), a2.x() + a2.y());
            const Space<3>::Inertia point = (r.squaredNorm() * Space<3>::Inertia::Identity() - r * r.transpose()).eval();
            b.inertia += p.m[q] * (point + Space<3>::Inertia(box.asDiagonal()) / 3.0);
            pointInertia[p.body[q]] += p.m[q] * point;
        }
    }
    for (std::size_t b = 0; b < nBodies; ++b) {
        if constexpr (D == 2) {
            if (pointInertia[b] > 0.0) info[b].angularVelocity = momentum[b] / pointInertia[b];
        } else {
            const Eigen::FullPivLU<Space<3>::Inertia> lu(pointInertia[b]);
            if (lu.rank() == 3) info[b].angularVelocity = lu.solve(momentum[b]);  // none for points on a line
        }
    }
    return info;
}

template class RigidBodyInfo<2>;
#if GPIC_WITH_3D
template class RigidBodyInfo<3>;
#endif

} // namespace gpic
