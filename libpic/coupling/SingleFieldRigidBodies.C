#include "coupling/SingleFieldRigidBodies.H"

#include "core/Registry.H"
#include "engine/EnginePass.H"

namespace gpic {

GPIC_REGISTER(GridCoupling, SingleFieldRigidBodies, "singleFieldRigidBodies");

SingleFieldRigidBodies::SingleFieldRigidBodies(CouplingParts& parts) : SingleField(parts)
{
    rigidNodes_.allocate(static_cast<std::size_t>(parts.grid->nNodes()));
    driven_ = &rigidNodes_;
}

void SingleFieldRigidBodies::constrainFiltered(EngineView& e, int f, std::vector<Vector2>& w, double dt) const
{
    SingleField::constrainFiltered(e, f, w, dt);
    // A node a rigid tool drives keeps the velocity the update started from.
    const Grid& grid = e.grid;
    for (int n : grid.active)
        if (rigidNodes_.bodyAt(n) >= 0) w[n] = grid.velocity[n] - dt * grid.accel[n];
}

void SingleFieldRigidBodies::forEachRigidNode(const Grid& grid, const Drivers&,
                                              const std::function<void(int, int)>& visit) const
{
    for (int n : grid.active)
        if (rigidNodes_.bodyAt(n) >= 0) visit(n, rigidNodes_.bodyAt(n));
}

} // namespace gpic
