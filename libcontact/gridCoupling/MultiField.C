#include "gridCoupling/MultiField.H"

#include "core/Registry.H"
#include "coupling/LocalDamping.H"
#include "engine/EnginePass.H"

#include <algorithm>

namespace gpic {

GPIC_REGISTER(GridCoupling<2>, MultiField, "multiField");

void MultiField::particlesToGrid(EngineView<2>& e, double t)
{
    Grid<2>& grid = e.grid;
    ContactPass<2>& bodies = *contact_;
    bodies.reset(grid.active);
    grid.resetFields();
    const Particles<2>& p = e.particles;
    const ShapeWeights<2>& w = e.weights;
    const int stride = w.stride;
    // Pointers captured by value or held in the kernel's locals, as in SingleField.
    const int* node = w.node.data();
    const double* Nw = w.N.data();
    const Grid<2>::ActiveMarker markActive = grid.activeMarker();
    const bool affine = p.carries(FieldGroup::affine);
    e.strips.forEach([&, node, Nw, markActive, affine, stride](std::size_t q) {
        const std::size_t k0 = q * stride;
        BodyField<2>& body = bodies.field(p.body[q]);
        double* mass = body.mass.data();
        Vector2* momentum = body.momentum.data();
        const double m = e.inertialMass(q);  // m_p, or scaled (MassScaling.H)
        const Vector2 vp = p.v[q];           // read once, not after every store (as SingleField)
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
    // The system (centre-of-mass) field is the sum of the bodies' (F.8.6).
    grid.forEachActiveNode([&](int n) {
        for (int b = 0; b < bodies.nBodies(); ++b) {
            const BodyField<2>& f = bodies.field(b);
            grid.mass[n] += f.mass[n];
            grid.momentum[n] += f.momentum[n];
        }
    });
    grid.velocitiesFromMomenta();
    e.sides.constrain(grid.velocity);
    findToolSideNodes(e);
    bodyVelocities(e, t);
}

void MultiField::findToolSideNodes(const EngineView<2>& e)
{
    toolSideNodes_.clear();
    if (e.rigid.empty()) return;
    const auto covered = [&](int n) {
        for (int b = 0; b < contact_->nBodies(); ++b)
            if (e.rigid[b] && contact_->field(b).mass[n] > 0.0) return true;
        return false;
    };
    for (int s = 0; s < GridSides<2>::count; ++s) {
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

void MultiField::constrainBody(EngineView<2>& e, std::vector<Vector2>& velocity, std::vector<Vector2>* accel,
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
        for (int a = 0; a < 2; ++a) {
            if (t.heldAxes & (1u << a)) continue;
            velocity[t.node][a] = keptVelocity_[k][a];
            if (accel) (*accel)[t.node][a] = keptAccel_[k][a];
        }
    }
}

void MultiField::bodyVelocities(EngineView<2>& e, double t)
{
    const Grid<2>& grid = e.grid;
    for (int b = 0; b < contact_->nBodies(); ++b) {
        BodyField<2>& f = contact_->field(b);
        const RigidBodyDriver<2>* driver = e.rigid.empty() ? nullptr : e.rigid[b].get();
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

void MultiField::constrainBodies(EngineView<2>& e, double dt)
{
    for (int b = 0; b < contact_->nBodies(); ++b)
        if (e.rigid.empty() || !e.rigid[b]) constrainBody(e, contact_->field(b).velocity, &contact_->field(b).accel, dt);
}

void MultiField::updateGrid(EngineView<2>& e, double tNew, double dt)
{
    Grid<2>& grid = e.grid;
    ContactPass<2>& bodies = *contact_;
    const int nBodies = bodies.nBodies();
    {
        auto timer = e.timers.time("gridUpdate");
        for (int b = 0; b < nBodies; ++b) {
            BodyField<2>& f = bodies.field(b);
            if (!e.rigid.empty() && e.rigid[b]) {  // a rigid body's field is its driver's velocity (seed A14)
                for (int n : grid.active) {  // drivers cache their motion: serial
                    if (!(f.mass[n] > 0.0)) continue;
                    const Vector2 vNew = e.rigid[b]->velocity(tNew, grid.nodePosition(n));
                    f.accel[n] = (vNew - f.velocity[n]) / dt;
                    f.velocity[n] = vNew;
                }
                continue;
            }
            grid.forEachActiveNode([&](int n) {
                if (!(f.mass[n] > 0.0)) return;
                Vector2 F = f.force[n];
                // eq. 3.3.5 on the body's own field. Not at a node shared with another body:
                // there the contact takes the unbalanced force, and a damping force would only
                // come back as a false contact load.
                if (e.damping > 0 && !bodies.shared(n)) applyLocalDamping(F, f.velocity[n], e.damping);
                f.accel[n] = f.mass[n] > e.minNodalMass ? Vector2(F / f.mass[n]) : Vector2::Zero();  // eq. 2.4.2
                f.velocity[n] += dt * f.accel[n];                                                  // eq. 2.4.3
            });
        }
        constrainBodies(e, dt);
    }
    {
        auto timer = e.timers.time("contact");  // seed G.4 steps 2 and 4
        contactNodes_ = bodies.correct(grid, e.particles, e.rigid, tNew, dt, loads_);
    }
    auto timer = e.timers.time("gridUpdate");
    constrainBodies(e, dt);
    // The centre-of-mass field, for the grid output and function objects.
    grid.forEachActiveNode([&](int n) {
        if (!(grid.mass[n] > 0.0)) return;
        Vector2 momentum = Vector2::Zero(), rate = Vector2::Zero();
        for (int b = 0; b < nBodies; ++b) {
            const BodyField<2>& f = bodies.field(b);
            momentum += f.mass[n] * f.velocity[n];
            rate += f.mass[n] * f.accel[n];
        }
        grid.velocity[n] = momentum / grid.mass[n];
        grid.accel[n] = rate / grid.mass[n];
    });
}

void MultiField::remapVelocity(EngineView<2>& e, double tNew, double dt)
{
    Grid<2>& grid = e.grid;
    ContactPass<2>& bodies = *contact_;
    const Particles<2>& p = e.particles;
    const ShapeWeights<2>& w = e.weights;
    const int stride = w.stride;
    grid.forEachActiveNode([&](int n) {
        grid.momentum[n].setZero();
        for (int b = 0; b < bodies.nBodies(); ++b) bodies.field(b).momentum[n].setZero();
    });
    const int* node = w.node.data();
    const double* Nw = w.N.data();
    Vector2* gridMomentum = grid.momentum.data();
    const bool affine = p.carries(FieldGroup::affine);
    e.strips.forEach([&, node, Nw, gridMomentum, affine, stride](std::size_t q) {
        const std::size_t k0 = q * stride;
        Vector2* bodyMomentum = bodies.field(p.body[q]).momentum.data();
        const Vector2 xp = e.remapCentre(q, dt);
        const double m = e.inertialMass(q);
        const Vector2 vp = p.v[q];
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            if (n < 0) continue;
            const Vector2 momentum = (Nw[k0 + a] * m) * (affine ? e.carriedVelocity(q, n, xp) : vp);
            gridMomentum[n] += momentum;
            bodyMomentum[n] += momentum;
        }
    });
    grid.velocitiesFromMomenta();
    e.sides.constrain(grid.velocity);
    bodyVelocities(e, tNew);
    bodies.correctRemapped(grid, e.rigid, tNew);
}

void MultiField::forEachRigidNode(const Grid<2>& grid, const Drivers& rigid,
                                  const std::function<void(int, int)>& visit) const
{
    if (rigid.empty()) return;
    for (int b = 0; b < contact_->nBodies(); ++b)
        if (rigid[b])
            for (int n : grid.active)
                if (contact_->field(b).mass[n] > 0.0) visit(n, b);
}

} // namespace gpic
