#include "multiField/MultiFieldContact.H"

#include <cmath>

namespace gpic {

GPIC_REGISTER(ContactPass, MultiFieldContact, "multiField")

namespace {
Vector2 unit(const Vector2& v)
{
    const double len = v.norm();
    return len > 0.0 ? Vector2(v / len) : Vector2::Zero();
}

inline double cross(const Vector2& a, const Vector2& b) { return a.x() * b.y() - a.y() * b.x(); }
} // namespace

MultiFieldContact::MultiFieldContact(const Dictionary&, ContactParts& parts)
    : ContactPass(parts.nBodies, *parts.grid), law_(std::move(parts.law)), normals_(std::move(parts.normals)),
      normalsName_(parts.normalsName)
{
    present_.reserve(static_cast<std::size_t>(nBodies()));
}

Vector2 MultiFieldContact::impulse(int b, int other, int n, const Vector2& vRef, const Vector2& normal, double dt)
{
    BodyField& f = field(b);
    const Vector2 v = f.velocity[n];
    const Vector2 vNew = law_->correct(v, vRef, normal, b, other);
    const Vector2 dv = vNew - v;
    f.velocity[n] = vNew;
    f.accel[n] += dv / dt;  // G.4.1: a~ = (v~^{t+1} - v^t) / dt
    return (f.mass[n] / dt) * dv;
}

int MultiFieldContact::correct(Grid& grid, const Particles& p,
                               const std::vector<std::unique_ptr<RigidBodyDriver>>& rigid, double tNew,
                               double dt, std::vector<RigidBodyLoad>& loads)
{
    for (auto& l : loads) l = RigidBodyLoad{};
    const int nb = nBodies();
    contactNodes_.clear();
    for (int n : grid.active)
        if (shared(n)) contactNodes_.push_back(n);
    if (contactNodes_.empty()) return 0;
    const auto isRigid = [&](int b) { return !rigid.empty() && rigid[b] != nullptr; };
    // Only on steps with contact: the normals where the bodies are now.
    normals_->place(grid, p);

    for (int n : contactNodes_) {
        present_.clear();
        int r = -1;  // the heaviest rigid body at the node
        for (int b = 0; b < nb; ++b) {
            if (!(field(b).mass[n] > 0.0)) continue;
            present_.push_back(b);
            if (isRigid(b) && (r < 0 || field(b).mass[n] > field(r).mass[n])) r = b;
        }
        const Vector2 x = grid.nodePosition(n);
        if (r >= 0) {
            if (!normals_->acts(r, n, x)) continue;  // e.g. beyond a rigid surface's corner
            // Seed A14: only the deformable bodies are corrected, against the rigid velocity.
            const Vector2 vRef = rigid[r]->velocity(tNew, x);
            for (int b : present_) {
                if (isRigid(b)) continue;
                const Vector2 normal = normals_->towardsRigid(b, r, n, x);
                if (normal.isZero()) continue;
                const Vector2 f = impulse(b, r, n, vRef, normal, dt);
                loads[b].force += f;
                loads[b].moment += cross(x, f);
                loads[r].force -= f;
                loads[r].moment -= cross(x, f);
                grid.fContact[n] -= f;
            }
            continue;
        }
        double mass = 0;
        Vector2 momentum = Vector2::Zero();
        for (int b : present_) {
            mass += field(b).mass[n];
            momentum += field(b).mass[n] * field(b).velocity[n];
        }
        const Vector2 vCm = momentum / mass;
        Vector2 pairNormal = Vector2::Zero();
        if (present_.size() == 2)
            pairNormal = unit(normals_->outward(present_[0], n) - normals_->outward(present_[1], n));
        for (std::size_t k = 0; k < present_.size(); ++k) {
            const int b = present_[k];
            Vector2 normal;
            if (present_.size() == 2) normal = k == 0 ? pairNormal : Vector2(-pairNormal);
            else normal = normals_->outward(b, n);
            if (normal.isZero()) continue;
            int other = -1;
            for (int o : present_)
                if (o != b && (other < 0 || field(o).mass[n] > field(other).mass[n])) other = o;
            const Vector2 f = impulse(b, other, n, vCm, normal, dt);
            loads[b].force += f;
            loads[b].moment += cross(x, f);
            if (k == 0) grid.fContact[n] += f;
        }
    }
    return static_cast<int>(contactNodes_.size());
}

} // namespace gpic
