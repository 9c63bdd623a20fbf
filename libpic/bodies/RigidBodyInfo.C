#include "bodies/RigidBodyDriver.H"
#include "particles/Particles.H"

#include <Eigen/LU>

#include <type_traits>

namespace gpic {

template <int D>
std::vector<RigidBodyInfo<D>> RigidBodyInfo<D>::ofBodies(const Particles<D>& p, std::size_t nBodies, const Vector& gravity,
                                                        const RankReductions& ranks)
{
    std::vector<RigidBodyInfo<D>> info(nBodies);
    for (std::size_t q = 0; q < p.size(); ++q) {
        auto& b = info[p.body[q]];
        b.mass += p.m[q];
        b.centroid += p.m[q] * p.x[q];
        b.velocity += p.m[q] * p.v[q];
    }
    if (ranks.parallel()) {  // every rank's particles: the sums before they are divided
        std::vector<double> sums;
        for (const auto& b : info) {
            sums.push_back(b.mass);
            for (int a = 0; a < D; ++a) sums.insert(sums.end(), {b.centroid[a], b.velocity[a]});
        }
        ranks.sumOver(sums);
        std::size_t k = 0;
        for (auto& b : info) {
            b.mass = sums[k++];
            for (int a = 0; a < D; ++a) b.centroid[a] = sums[k++], b.velocity[a] = sums[k++];
        }
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
    if (ranks.parallel()) {
        std::vector<double> sums;
        const auto values = [](auto& x) -> double* {
            if constexpr (std::is_same_v<std::decay_t<decltype(x)>, double>) return &x;
            else return x.data();
        };
        const auto size = [](const auto& x) -> std::size_t {
            if constexpr (std::is_same_v<std::decay_t<decltype(x)>, double>) return 1;
            else return static_cast<std::size_t>(x.size());
        };
        for (std::size_t b = 0; b < nBodies; ++b)
            for (auto* x : {&info[b].inertia, &pointInertia[b]}) sums.insert(sums.end(), values(*x), values(*x) + size(*x));
        for (std::size_t b = 0; b < nBodies; ++b) sums.insert(sums.end(), values(momentum[b]), values(momentum[b]) + size(momentum[b]));
        ranks.sumOver(sums);
        std::size_t k = 0;
        for (std::size_t b = 0; b < nBodies; ++b)
            for (auto* x : {&info[b].inertia, &pointInertia[b]})
                for (std::size_t c = 0; c < size(*x); ++c) values(*x)[c] = sums[k++];
        for (std::size_t b = 0; b < nBodies; ++b)
            for (std::size_t c = 0; c < size(momentum[b]); ++c) values(momentum[b])[c] = sums[k++];
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
