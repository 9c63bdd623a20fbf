#include "bodies/RigidBodyDriver.H"
#include "particles/Particles.H"

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
    for (std::size_t q = 0; q < p.size(); ++q) {
        auto& b = info[p.body[q]];
        const Vector& a = p.halfSize[q];
        b.inertia += p.m[q] * ((p.x[q] - b.centroid).squaredNorm() + a.squaredNorm() / 3.0);
    }
    return info;
}

template class RigidBodyInfo<2>;

} // namespace gpic
