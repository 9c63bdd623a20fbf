#include "gridCoupling/MultiField.H"

#include "core/Registry.H"
#include "coupling/LocalDamping.H"
#include "engine/EnginePass.H"

#include <algorithm>

namespace gpic {

GPIC_REGISTER_DIMS(GridCoupling, MultiField, "multiField")

template <int D> void MultiField<D>::particlesToGrid(EngineView<D>& e, double t)
{
    Grid<D>& grid = e.grid;
    ContactPass<D>& bodies = *this->contact_;
    bodies.reset(grid.active);
    grid.resetFields();
    const Particles<D>& p = e.particles;
    const ShapeWeights<D>& w = e.weights;
    const int stride = w.stride;
    // Pointers captured by value or held in the kernel's locals, as in SingleField.
    const int* node = w.node.data();
    const double* Nw = w.N.data();
    const typename Grid<D>::ActiveMarker markActive = grid.activeMarker();
    const bool affine = p.carries(FieldGroup::affine);
    const bool positions = bodies.tracksPositions();
    e.strips.forEach([&, node, Nw, markActive, affine, stride, positions](std::size_t q) {
        const std::size_t k0 = q * stride;
        BodyField<D>& body = bodies.field(p.body[q]);
        double* mass = body.mass.data();
        Vector* momentum = body.momentum.data();
        const double m = e.inertialMass(q);  // m_p, or scaled (MassScaling.H)
        if (positions) {  // the separation check's nodal positions (MultiFieldContact.H)
            Vector* position = body.position.data();
            for (int a = 0; a < stride; ++a)
                if (node[k0 + a] >= 0) position[node[k0 + a]] += (Nw[k0 + a] * m) * p.x[q];
        }
        const Vector vp = p.v[q];           // read once, not after every store (as SingleField)
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            const double N = Nw[k0 + a];
            if (n < 0) continue;
            markActive(n);  // also at N = 0: its gradient may still carry force
            // The body's own field, from its particles only (seed G.4 step 1).
            mass[n] += N * m;
            momentum[n] += (N * m) * (affine ? e.carriedVelocity(q, n, p.x[q]) : vp);
        }
    });
    grid.collectActive();
    bodies.setRankSums(e.rankSums);
    if (e.rankSums) {  // a parallel run: the other ranks' parts, on every node the owner sums over
        e.rankSums->shareActiveNodes(grid);
        for (int b = 0; b < bodies.nBodies(); ++b) {
            BodyField<D>& f = bodies.field(b);
            e.rankSums->complete(grid, f.mass);
            e.rankSums->complete(grid, f.momentum);
            if (positions) e.rankSums->complete(grid, f.position);
        }
    }
    // The system (centre-of-mass) field is the sum of the bodies' (F.8.6).
    grid.forEachActiveNode([&](int n) {
        for (int b = 0; b < bodies.nBodies(); ++b) {
            const BodyField<D>& f = bodies.field(b);
            grid.mass[n] += f.mass[n];
            grid.momentum[n] += f.momentum[n];
        }
    });
    grid.velocitiesFromMomenta();
    e.sides.constrain(grid.velocity);
    findToolSideNodes(e);
    bodyVelocities(e, t);
}

template <int D> void MultiField<D>::findToolSideNodes(const EngineView<D>& e)
{
    toolSideNodes_.clear();
    if (e.rigid.empty()) return;
    const auto covered = [&](int n) {
        for (int b = 0; b < this->contact_->nBodies(); ++b)
            if (e.rigid[b] && this->contact_->field(b).mass[n] > 0.0) return true;
        return false;
    };
    for (int s = 0; s < GridSides<D>::count; ++s) {
        const auto side = static_cast<GridSide>(s);
        if (!e.sides.condition(side).isWall()) continue;
        for (int n : e.sides.constrainedNodes(side)) {
            if (!covered(n)) continue;
            const unsigned bit = 1u << sideAxis(side);
            auto it = std::find_if(toolSideNodes_.begin(), toolSideNodes_.end(),
                                   [n](const ToolSideNode& t) { return t.node == n; });
            if (it == toolSideNodes_.end()) toolSideNodes_.push_back({n, bit});
            else it->heldAxes |= bit;
        }
    }
}

template <int D> void MultiField<D>::constrainBody(EngineView<D>& e, std::vector<Vector>& velocity, std::vector<Vector>* accel,
                               double dt)
{
    keptVelocity_.clear();
    keptAccel_.clear();
    for (const ToolSideNode& t : toolSideNodes_) {
        keptVelocity_.push_back(velocity[t.node]);
        if (accel) keptAccel_.push_back((*accel)[t.node]);
    }
    if (accel) e.sides.constrainUpdate(velocity, *accel, dt);
    else e.sides.constrain(velocity);
    for (std::size_t k = 0; k < toolSideNodes_.size(); ++k) {
        const ToolSideNode& t = toolSideNodes_[k];
        for (int a = 0; a < D; ++a) {
            if (t.heldAxes & (1u << a)) continue;
            velocity[t.node][a] = keptVelocity_[k][a];
            if (accel) (*accel)[t.node][a] = keptAccel_[k][a];
        }
    }
}

template <int D> void MultiField<D>::bodyVelocities(EngineView<D>& e, double t)
{
    const Grid<D>& grid = e.grid;
    for (int b = 0; b < this->contact_->nBodies(); ++b) {
        BodyField<D>& f = this->contact_->field(b);
        const RigidBodyDriver<D>* driver = e.rigid.empty() ? nullptr : e.rigid[b].get();
        if (driver) {  // drivers cache their motion: serial
            for (int n : grid.active)
                if (f.mass[n] > 0.0) f.velocity[n] = driver->velocity(t, grid.nodePosition(n));
            continue;
        }
        grid.forEachActiveNode([&](int n) {
            if (f.mass[n] > 0.0) f.velocity[n] = f.momentum[n] / f.mass[n];
        });
        constrainBody(e, f.velocity, nullptr, 0.0);
    }
}

template <int D> void MultiField<D>::constrainBodies(EngineView<D>& e, double dt)
{
    for (int b = 0; b < this->contact_->nBodies(); ++b)
        if (e.rigid.empty() || !e.rigid[b]) constrainBody(e, this->contact_->field(b).velocity, &this->contact_->field(b).accel, dt);
}

template <int D> void MultiField<D>::updateGrid(EngineView<D>& e, double tNew, double dt)
{
    Grid<D>& grid = e.grid;
    ContactPass<D>& bodies = *this->contact_;
    const int nBodies = bodies.nBodies();
    if (e.rankSums)
        for (int b = 0; b < nBodies; ++b) e.rankSums->complete(grid, bodies.field(b).force);
    {
        auto timer = e.timers.time("gridUpdate");
        for (int b = 0; b < nBodies; ++b) {
            BodyField<D>& f = bodies.field(b);
            if (!e.rigid.empty() && e.rigid[b]) {  // a rigid body's field is its driver's velocity (seed A14)
                for (int n : grid.active) {  // drivers cache their motion: serial
                    if (!(f.mass[n] > 0.0)) continue;
                    const Vector vNew = e.rigid[b]->velocity(tNew, grid.nodePosition(n));
                    f.accel[n] = (vNew - f.velocity[n]) / dt;
                    f.velocity[n] = vNew;
                }
                continue;
            }
            grid.forEachActiveNode([&](int n) {
                if (!(f.mass[n] > 0.0)) return;
                Vector F = f.force[n];
                // eq. 3.3.5 on the body's own field. Not at a node shared with another body:
                // there the contact takes the unbalanced force, and a damping force would only
                // come back as a false contact load.
                if (e.damping > 0 && !bodies.shared(n)) applyLocalDamping(F, f.velocity[n], e.damping);
                f.accel[n] = f.mass[n] > e.minNodalMass ? Vector(F / f.mass[n]) : Vector::Zero();  // eq. 2.4.2
                f.velocity[n] += dt * f.accel[n];                                                  // eq. 2.4.3
            });
        }
        constrainBodies(e, dt);
    }
    {
        auto timer = e.timers.time("contact");  // seed G.4 steps 2 and 4
        this->contactNodes_ = bodies.correct(grid, e.particles, e.rigid, tNew, dt, this->loads_);
    }
    auto timer = e.timers.time("gridUpdate");
    constrainBodies(e, dt);
    // The centre-of-mass field, for the grid output and function objects.
    grid.forEachActiveNode([&](int n) {
        if (!(grid.mass[n] > 0.0)) return;
        Vector momentum = Vector::Zero(), rate = Vector::Zero();
        for (int b = 0; b < nBodies; ++b) {
            const BodyField<D>& f = bodies.field(b);
            momentum += f.mass[n] * f.velocity[n];
            rate += f.mass[n] * f.accel[n];
        }
        grid.velocity[n] = momentum / grid.mass[n];
        grid.accel[n] = rate / grid.mass[n];
    });
}

template <int D> void MultiField<D>::remapVelocity(EngineView<D>& e, double tNew, double dt)
{
    Grid<D>& grid = e.grid;
    ContactPass<D>& bodies = *this->contact_;
    const Particles<D>& p = e.particles;
    const ShapeWeights<D>& w = e.weights;
    const int stride = w.stride;
    grid.forEachActiveNode([&](int n) {
        grid.momentum[n].setZero();
        for (int b = 0; b < bodies.nBodies(); ++b) bodies.field(b).momentum[n].setZero();
    });
    const int* node = w.node.data();
    const double* Nw = w.N.data();
    Vector* gridMomentum = grid.momentum.data();
    const bool affine = p.carries(FieldGroup::affine);
    e.strips.forEach([&, node, Nw, gridMomentum, affine, stride](std::size_t q) {
        const std::size_t k0 = q * stride;
        Vector* bodyMomentum = bodies.field(p.body[q]).momentum.data();
        const Vector xp = e.remapCentre(q, dt);
        const double m = e.inertialMass(q);
        const Vector vp = p.v[q];
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            if (n < 0) continue;
            const Vector momentum = (Nw[k0 + a] * m) * (affine ? e.carriedVelocity(q, n, xp) : vp);
            gridMomentum[n] += momentum;
            bodyMomentum[n] += momentum;
        }
    });
    if (e.rankSums) {
        e.rankSums->completeMomentum(grid);
        for (int b = 0; b < bodies.nBodies(); ++b) e.rankSums->complete(grid, bodies.field(b).momentum);
    }
    grid.velocitiesFromMomenta();
    e.sides.constrain(grid.velocity);
    bodyVelocities(e, tNew);
    bodies.correctRemapped(grid, e.rigid, tNew);
}

template <int D> void MultiField<D>::forEachRigidNode(const Grid<D>& grid, const Drivers& rigid,
                                  const std::function<void(int, int)>& visit) const
{
    if (rigid.empty()) return;
    for (int b = 0; b < this->contact_->nBodies(); ++b)
        if (rigid[b])
            for (int n : grid.active)
                if (this->contact_->field(b).mass[n] > 0.0) visit(n, b);
}

template class MultiField<2>;
#if GPIC_WITH_3D
template class MultiField<3>;
#endif

} // namespace gpic
