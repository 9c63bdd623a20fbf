#include "coupling/RigidNodeCoupling.H"

namespace gpic {

template <int D>
void RigidNodeCoupling<D>::allocate(std::size_t nodes)
{
    std::vector<int>(nodes, -1).swap(body_);
    std::vector<double>(nodes, 0.0).swap(mass_);
    std::vector<Vector>(nodes, Vector::Zero()).swap(momentum_);
}

template <int D>
void RigidNodeCoupling<D>::reset(const std::vector<int>& active)
{
    for (int n : active) {
        body_[n] = -1;
        mass_[n] = 0.0;
        momentum_[n].setZero();
    }
}

template <int D> void RigidNodeCoupling<D>::complete(const Grid<D>& grid, const RankSums<D>& sums)
{
    sums.complete(grid, mass_);
    sums.complete(grid, momentum_);
    sums.completeMax(grid, body_);
}

template <int D>
void RigidNodeCoupling<D>::constrain(Grid<D>& grid, const Drivers& rigid, double t) const
{
    for (int n : grid.active)
        if (body_[n] >= 0) grid.velocity[n] = rigid[body_[n]]->velocity(t, grid.nodePosition(n));
}

template <int D>
void RigidNodeCoupling<D>::update(Grid<D>& grid, const Drivers& rigid, double tNew, double dt, const Vector& gravity,
                               double minNodalMass, std::vector<RigidBodyLoad<D>>& loads, const RankSums<D>* sums) const
{
    for (auto& load : loads) load = RigidBodyLoad<D>{};
    for (int n : grid.active) {
        const int b = body_[n];
        if (b < 0) continue;
        const Vector x = grid.nodePosition(n);
        const Vector vNew = rigid[b]->velocity(tNew, x);
        const double materialMass = grid.mass[n] - mass_[n];
        const Vector materialMomentum = grid.momentum[n] - momentum_[n];
        // The force the material exerts on the body (seed A14): its nodal force (rigid
        // particles carry no stress, only their weight) less the rate of the impulse that
        // brings its momentum to the body's velocity.
        const Vector materialForce = grid.fInt[n] + grid.fExt[n] - mass_[n] * gravity;
        const Vector f = materialForce - (materialMass * vNew - materialMomentum) / dt;
        grid.fContact[n] = f;
        if (!sums || sums->owns(n)) {
            loads[b].force += f;
            loads[b].moment += momentOf(x, f);
        }
        // The material's particles take the contact impulse (FLIP update): the acceleration
        // brings the material's own nodal velocity, not the body's, to the body's new one.
        const Vector vMaterial = materialMass > minNodalMass ? Vector(materialMomentum / materialMass)
                                                              : grid.velocity[n];
        grid.accel[n] = (vNew - vMaterial) / dt;
        grid.velocity[n] = vMaterial;
    }
    if (sums) sums->sumLoads(loads);
}

template class RigidNodeCoupling<2>;
#if GPIC_WITH_3D
template class RigidNodeCoupling<3>;
#endif

} // namespace gpic
