#include "multiField/MultiFieldContact.H"

#include "core/error.H"

#include <cmath>

namespace gpic {

GPIC_REGISTER_DIMS(ContactPass, MultiFieldContact, "multiField")

namespace {
template <int D> typename Space<D>::Vector unit(const typename Space<D>::Vector& v)
{
    const double len = v.norm();
    return len > 0.0 ? typename Space<D>::Vector(v / len) : Space<D>::Vector::Zero();
}
} // namespace

template <int D>
MultiFieldContact<D>::MultiFieldContact(const Dictionary& dict, ContactParts<D>& parts)
    : ContactPass<D>(parts.nBodies, *parts.grid), law_(std::move(parts.law)), normals_(std::move(parts.normals)),
      normalsName_(parts.normalsName), correctRemapped_(dict.getOrDefault<bool>("correctRemapped", false)),
      remappedChoiceMade_(dict.found("correctRemapped")), fileName_(dict.fileName()), cellSize_(parts.grid->cellSize()),
      ranks_(parts.ranks)
{
    present_.reserve(static_cast<std::size_t>(this->nBodies()));
    if (dict.found("separationCutoff")) {
        separationCutoff_ = dict.getChecked<double>("separationCutoff", [](double c) { return c > 0.0 && c <= 2.0; },
                                                    "a distance in cells, 0 < cutoff <= 2 (0.8 for two particles per cell axis)");
        this->trackPositions();
    }
}

template <int D> bool MultiFieldContact<D>::touching(int a, int b, int n, const Vector& normal) const
{
    if (separationCutoff_ == 0.0) return true;
    const BodyField<D>& fa = this->field(a);
    const BodyField<D>& fb = this->field(b);
    const Vector gap = fb.position[n] / fb.mass[n] - fa.position[n] / fa.mass[n];
    return gap.dot(normal) <= separationCutoff_ * normal.cwiseProduct(cellSize_).norm();
}

template <int D>
typename MultiFieldContact<D>::Vector MultiFieldContact<D>::correctVelocity(int b, int other, int n, const Vector& vRef,
                                                                            const Vector& normal, bool approachOnly)
{
    BodyField<D>& f = this->field(b);
    const Vector v = f.velocity[n];
    if (approachOnly) {
        const double approach = (v - vRef).dot(normal);  // G.2.22: the normal approach speed
        if (approach > 0.0) f.velocity[n] = v - approach * normal;  // G.2.3
    } else {
        f.velocity[n] = law_->correct(v, vRef, normal, b, other);
    }
    return f.velocity[n] - v;
}

template <int D>
int MultiFieldContact<D>::correct(Grid<D>& grid, const Particles<D>& p, const Drivers& rigid, double tNew, double dt,
                                  std::vector<RigidBodyLoad<D>>& loads)
{
    for (auto& l : loads) l = RigidBodyLoad<D>{};
    contactNodes_.clear();
    for (int n : grid.active)
        if (this->shared(n)) contactNodes_.push_back(n);
    // Only on steps with contact: the normals where the bodies are now. A parallel run
    // places them on every rank when any has contact (the normals sum over the ranks).
    std::vector<double> none{contactNodes_.empty() ? 1.0 : 0.0};
    ranks_.minOver(none);
    if (none[0] > 0.0) return 0;
    normals_->place(grid, p, contactNodes_);
    correctNodes(grid, rigid, tNew, dt, &loads);
    if (this->rankSums_) this->rankSums_->sumLoads(loads);
    return static_cast<int>(contactNodes_.size());
}

template <int D> void MultiFieldContact<D>::correctRemapped(Grid<D>& grid, const Drivers& rigid, double tNew)
{
    if (!remappedChoiceMade_) {  // the scheme remaps (MUSL): a choice the scene has to make
        remappedChoiceMade_ = true;
        warning(fileName_, 0,
                "keyword 'correctRemapped' not given (default no, the seed's contact pass): 'no' suits a tool "
                "pushing or followed by material, as in the tool tutorials; under MUSL a deformable body left "
                "resting on another (a block on a plate) needs 'yes', or it gains energy and lifts off "
                "(doc/contact.md, \"Which correctRemapped\")");
    }
    if (correctRemapped_ && !contactNodes_.empty()) correctNodes(grid, rigid, tNew, 0.0, nullptr);
}

template <int D>
void MultiFieldContact<D>::correctNodes(Grid<D>& grid, const Drivers& rigid, double tNew, double dt,
                                       std::vector<RigidBodyLoad<D>>* loads)
{
    const auto field = [this](int b) -> BodyField<D>& { return this->field(b); };
    const int nb = this->nBodies();
    const auto isRigid = [&](int b) { return !rigid.empty() && rigid[b] != nullptr; };
    // The step's correction: a~ = a + (v~ - v) / dt, so v~ = v^t + dt a~ (G.4.1), and the
    // force on body b is its impulse over dt.
    const auto apply = [&](int b, int other, int n, const Vector& vRef, const Vector& normal) -> Vector {
        const Vector dv = correctVelocity(b, other, n, vRef, normal, !loads);
        if (!loads) return Vector::Zero();
        field(b).accel[n] += dv / dt;
        return (field(b).mass[n] / dt) * dv;
    };

    for (int n : contactNodes_) {
        // A parallel run: the loads from the nodes this rank owns (each node counted once).
        const bool counted = !this->rankSums_ || this->rankSums_->owns(n);
        present_.clear();
        int r = -1;  // the heaviest rigid body at the node
        for (int b = 0; b < nb; ++b) {
            if (!(field(b).mass[n] > 0.0)) continue;
            present_.push_back(b);
            if (isRigid(b) && (r < 0 || field(b).mass[n] > field(r).mass[n])) r = b;
        }
        const Vector x = grid.nodePosition(n);
        if (r >= 0) {
            if (!normals_->acts(r, n, x)) continue;  // e.g. beyond a rigid surface's corner
            // Seed A14: only the deformable bodies are corrected, against the rigid velocity.
            const Vector vRef = rigid[r]->velocity(tNew, x);
            for (int b : present_) {
                if (isRigid(b)) continue;
                const Vector normal = normals_->towardsRigid(b, r, n, x);
                if (normal.isZero() || !touching(b, r, n, normal)) continue;
                const Vector f = apply(b, r, n, vRef, normal);
                if (!loads) continue;
                grid.fContact[n] -= f;
                if (!counted) continue;
                (*loads)[b].force += f;
                (*loads)[b].moment += momentOf(x, f);
                (*loads)[r].force -= f;
                (*loads)[r].moment -= momentOf(x, f);
            }
            continue;
        }
        double mass = 0;
        Vector momentum = Vector::Zero();
        for (int b : present_) {
            mass += field(b).mass[n];
            momentum += field(b).mass[n] * field(b).velocity[n];
        }
        const Vector vCm = momentum / mass;
        Vector pairNormal = Vector::Zero();
        if (present_.size() == 2) {
            pairNormal = unit<D>(normals_->outward(present_[0], n) - normals_->outward(present_[1], n));
            if (!pairNormal.isZero() && !touching(present_[0], present_[1], n, pairNormal)) continue;
        }
        for (std::size_t k = 0; k < present_.size(); ++k) {
            const int b = present_[k];
            Vector normal;
            if (present_.size() == 2) normal = k == 0 ? pairNormal : Vector(-pairNormal);
            else normal = normals_->outward(b, n);
            if (normal.isZero()) continue;
            int other = -1;
            for (int o : present_)
                if (o != b && (other < 0 || field(o).mass[n] > field(other).mass[n])) other = o;
            const Vector f = apply(b, other, n, vCm, normal);
            if (!loads) continue;
            if (k == 0) grid.fContact[n] += f;
            if (!counted) continue;
            (*loads)[b].force += f;
            (*loads)[b].moment += momentOf(x, f);
        }
    }
}

template class MultiFieldContact<2>;
#if GPIC_WITH_3D
template class MultiFieldContact<3>;
#endif

} // namespace gpic
