#include "coupling/RigidNodeCoupling.H"

namespace gpic {

void RigidNodeCoupling::allocate(std::size_t nodes)
{
    std::vector<int>(nodes, -1).swap(body_);
    std::vector<double>(nodes, 0.0).swap(mass_);
    std::vector<Vector2>(nodes, Vector2::Zero()).swap(momentum_);
}

void RigidNodeCoupling::reset(const std::vector<int>& active)
{
    for (int n : active) {
        body_[n] = -1;
        mass_[n] = 0.0;
        momentum_[n].setZero();
    }
}

void RigidNodeCoupling::constrain(Grid& grid, const Drivers& rigid, double t) const
{
    for (int n : grid.active)
        if (body_[n] >= 0) grid.velocity[n] = rigid[body_[n]]->velocity(t, grid.nodePosition(n));
}

void RigidNodeCoupling::update(Grid& grid, const Drivers& rigid, double tNew, double dt, const Vector2& gravity,
                               double minNodalMass, std::vector<RigidBodyLoad>& loads) const
{
    for (auto& load : loads) load = RigidBodyLoad{};
    for (int n : grid.active) {
        const int b = body_[n];
        if (b < 0) continue;
        const Vector2 x = grid.nodePosition(n);
        const Vector2 vNew = rigid[b]->velocity(tNew, x);
        const double materialMass = grid.mass[n] - mass_[n];
        const Vector2 materialMomentum = grid.momentum[n] - momentum_[n];
        // The force the material exerts on the body (seed A14): its nodal force (rigid
        // particles carry no stress, only their weight) less the rate of the impulse that
        // brings its momentum to the body's velocity.
        const Vector2 materialForce = grid.fInt[n] + grid.fExt[n] - mass_[n] * gravity;
        const Vector2 f = materialForce - (materialMass * vNew - materialMomentum) / dt;
        grid.fContact[n] = f;
        loads[b].force += f;
        loads[b].moment += x.x() * f.y() - x.y() * f.x();
        // The material's particles take the contact impulse (FLIP update): the acceleration
        // brings the material's own nodal velocity, not the body's, to the body's new one.
        const Vector2 vMaterial = materialMass > minNodalMass ? Vector2(materialMomentum / materialMass)
                                                              : grid.velocity[n];
        grid.accel[n] = (vNew - vMaterial) / dt;
        grid.velocity[n] = vMaterial;
    }
}

} // namespace gpic
