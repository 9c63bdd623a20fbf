#include "contact/MultiFieldContact.H"

#include <cmath>

namespace gpic {

namespace {
Vector2 unit(const Vector2& v)
{
    const double len = v.norm();
    return len > 0.0 ? Vector2(v / len) : Vector2::Zero();
}

inline double cross(const Vector2& a, const Vector2& b) { return a.x() * b.y() - a.y() * b.x(); }
} // namespace

MultiFieldContact::MultiFieldContact(std::unique_ptr<ContactLaw> law, ContactNormals normals,
                                     std::vector<std::unique_ptr<RigidSurface>> surfaces, int nBodies,
                                     const Grid& grid)
    : law_(std::move(law)), normals_(normals), surfaces_(std::move(surfaces)),
      fields_(static_cast<std::size_t>(nBodies)), nx_(grid.nx()), ny_(grid.ny()),
      h_(grid.cellSize())
{
    surfaces_.resize(fields_.size());
    const auto nodes = static_cast<std::size_t>(grid.nNodes());
    for (auto& f : fields_) {
        f.mass.assign(nodes, 0.0);
        f.momentum.assign(nodes, Vector2::Zero());
        f.velocity.assign(nodes, Vector2::Zero());
        f.force.assign(nodes, Vector2::Zero());
        f.accel.assign(nodes, Vector2::Zero());
    }
    present_.reserve(fields_.size());
}

void MultiFieldContact::reset(const std::vector<int>& active)
{
    for (auto& f : fields_)
        for (int n : active) {
            f.mass[n] = 0.0;
            f.momentum[n].setZero();
            f.velocity[n].setZero();
            f.force[n].setZero();
            f.accel[n].setZero();
        }
}

void MultiFieldContact::computeDensities(const Grid& grid, const Particles& p)
{
    const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    density_.assign(fields_.size() * cells, 0.0);
    const Vector2 h = grid.cellSize();
    for (std::size_t q = 0; q < p.size(); ++q) {
        // Element centres within one cell of the particle, with bilinear weights S1.
        const Vector2 s = Vector2((p.x[q] - grid.origin()).array() / h.array()) - Vector2(0.5, 0.5);
        const int i0 = static_cast<int>(std::floor(s.x())), j0 = static_cast<int>(std::floor(s.y()));
        const double fx = s.x() - i0, fy = s.y() - j0;
        double* rho = density_.data() + static_cast<std::size_t>(p.body[q]) * cells;
        for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) {
                const int i = i0 + a, j = j0 + b;
                if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
                const double S1 = (a ? fx : 1.0 - fx) * (b ? fy : 1.0 - fy);
                rho[i + j * nx_] += p.m[q] * S1;
            }
    }
}

Vector2 MultiFieldContact::gradientNormal(int body, int node) const
{
    const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    const double* rho = density_.data() + static_cast<std::size_t>(body) * cells;
    const int i = node % (nx_ + 1), j = node / (nx_ + 1);
    // c_cv = (+-dy/2, +-dx/2) of the node in each element around it points from the element
    // centre to the node (G.3): the sum of c_cv rho_c points away from the dense side.
    Vector2 g = Vector2::Zero();
    for (int b = -1; b <= 0; ++b)
        for (int a = -1; a <= 0; ++a) {
            const int ci = i + a, cj = j + b;
            if (ci < 0 || cj < 0 || ci >= nx_ || cj >= ny_) continue;
            const double r = rho[ci + cj * nx_];
            g += r * Vector2(a < 0 ? h_.y() : -h_.y(), b < 0 ? h_.x() : -h_.x());
        }
    return unit(g);
}

Vector2 MultiFieldContact::impulse(int b, int other, int n, const Vector2& vRef, const Vector2& normal, double dt)
{
    BodyField& f = fields_[static_cast<std::size_t>(b)];
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
    // Only on steps with contact: the mass gradients (they also tell a rigid surface which
    // of its faces the material is on) and the rigid surfaces where the bodies are now.
    computeDensities(grid, p);
    for (int b = 0; b < nb; ++b)
        if (surfaces_[b]) surfaces_[b]->place(p, b);

    for (int n : contactNodes_) {
        present_.clear();
        int r = -1;  // the heaviest rigid body at the node
        for (int b = 0; b < nb; ++b) {
            if (!(fields_[b].mass[n] > 0.0)) continue;
            present_.push_back(b);
            if (isRigid(b) && (r < 0 || fields_[b].mass[n] > fields_[r].mass[n])) r = b;
        }
        const bool surface = r >= 0 && surfaces_[r] != nullptr;
        const Vector2 x = grid.nodePosition(n);
        if (surface && !surfaces_[r]->facesNode(x)) continue;  // beyond a corner (header)
        if (r >= 0) {
            // Seed A14: only the deformable bodies are corrected, against the rigid velocity.
            const Vector2 vRef = rigid[r]->velocity(tNew, x);
            const Vector2 nRigid = surface ? Vector2::Zero() : gradientNormal(r, n);
            for (int b : present_) {
                if (isRigid(b)) continue;
                const Vector2 nBody = gradientNormal(b, n);
                const Vector2 normal = surface ? Vector2(-surfaces_[r]->outwardNormal(x, nBody)) : unit(nBody - nRigid);
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
            mass += fields_[b].mass[n];
            momentum += fields_[b].mass[n] * fields_[b].velocity[n];
        }
        const Vector2 vCm = momentum / mass;
        Vector2 pairNormal = Vector2::Zero();
        if (present_.size() == 2)
            pairNormal = unit(gradientNormal(present_[0], n) - gradientNormal(present_[1], n));
        for (std::size_t k = 0; k < present_.size(); ++k) {
            const int b = present_[k];
            Vector2 normal;
            if (present_.size() == 2) normal = k == 0 ? pairNormal : Vector2(-pairNormal);
            else normal = gradientNormal(b, n);
            if (normal.isZero()) continue;
            int other = -1;
            for (int o : present_)
                if (o != b && (other < 0 || fields_[o].mass[n] > fields_[other].mass[n])) other = o;
            const Vector2 f = impulse(b, other, n, vCm, normal, dt);
            loads[b].force += f;
            loads[b].moment += cross(x, f);
            if (k == 0) grid.fContact[n] += f;
        }
    }
    return static_cast<int>(contactNodes_.size());
}

} // namespace gpic
