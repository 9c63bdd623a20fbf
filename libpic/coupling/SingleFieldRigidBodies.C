#include "coupling/SingleFieldRigidBodies.H"

#include "core/Registry.H"
#include "engine/EnginePass.H"

namespace gpic {

GPIC_REGISTER_DIMS(GridCoupling, SingleFieldRigidBodies, "singleFieldRigidBodies")

template <int D>
SingleFieldRigidBodies<D>::SingleFieldRigidBodies(CouplingParts<D>& parts) : SingleField<D>(parts)
{
    rigidNodes_.allocate(static_cast<std::size_t>(parts.grid->nNodes()));
    this->driven_ = &rigidNodes_;
}

template <int D>
void SingleFieldRigidBodies<D>::constrainFiltered(EngineView<D>& e, int f, std::vector<Vector>& w, double dt) const
{
    SingleField<D>::constrainFiltered(e, f, w, dt);
    // A node a rigid tool drives keeps the velocity the update started from.
    const Grid<D>& grid = e.grid;
    for (int n : grid.active)
        if (rigidNodes_.bodyAt(n) >= 0) w[n] = grid.velocity[n] - dt * grid.accel[n];
}

template <int D>
void SingleFieldRigidBodies<D>::forEachRigidNode(const Grid<D>& grid, const typename GridCoupling<D>::Drivers&,
                                              const std::function<void(int, int)>& visit) const
{
    for (int n : grid.active)
        if (rigidNodes_.bodyAt(n) >= 0) visit(n, rigidNodes_.bodyAt(n));
}

template class SingleFieldRigidBodies<2>;
#if GPIC_WITH_3D
template class SingleFieldRigidBodies<3>;
#endif

} // namespace gpic
