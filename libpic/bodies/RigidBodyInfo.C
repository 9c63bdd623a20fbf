#include "bodies/RigidBodyDriver.H"
#include "particles/Particles.H"

namespace gpic {

std::vector<RigidBodyInfo> RigidBodyInfo::ofBodies(const Particles& p, std::size_t nBodies, const Vector2& gravity)
{
    std::vector<RigidBodyInfo> info(nBodies);
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
        const Vector2& a = p.halfSize[q];
        b.inertia += p.m[q] * ((p.x[q] - b.centroid).squaredNorm() + a.squaredNorm() / 3.0);
    }
    return info;
}

} // namespace gpic
