#include "coupling/SingleField.H"

#include "core/Registry.H"
#include "coupling/LocalDamping.H"
#include "engine/EnginePass.H"

namespace gpic {

GPIC_REGISTER_DIMS(GridCoupling, SingleField, "singleField")

template <int D>
void SingleField<D>::particlesToGrid(EngineView<D>& e, double t)
{
    Grid<D>& grid = e.grid;
    if (driven_) driven_->reset(grid.active);
    grid.resetFields();
    const Particles<D>& p = e.particles;
    const ShapeWeights<D>& w = e.weights;
    const int stride = w.stride;
    // Pointers and flags captured by value (ParticleStrips::forEach): Eigen's SSE stores may
    // alias anything, and what the loop reads through memory is reloaded after each of them.
    const int* node = w.node.data();
    const double* Nw = w.N.data();
    double* mass = grid.mass.data();
    Vector* momentum = grid.momentum.data();
    const typename Grid<D>::ActiveMarker markActive = grid.activeMarker();
    const bool affine = p.carries(FieldGroup::affine);
    e.strips.forEach([&, node, Nw, mass, momentum, markActive, affine, stride](std::size_t q) {
        const std::size_t k0 = q * stride;
        const bool rigidParticle = driven_ && e.rigid[p.body[q]];
        const double m = e.inertialMass(q);  // m_p, or scaled (MassScaling.H)
        const Vector vp = p.v[q];
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            const double N = Nw[k0 + a];
            if (n < 0) continue;
            markActive(n);  // also at N = 0: its gradient may still carry force
            const Vector v = affine ? e.carriedVelocity(q, n, p.x[q]) : vp;  // APIC: v_p + C_p (x_i - x_p)
            if (rigidParticle) driven_->add(n, p.body[q], N, N * m, v);
            mass[n] += N * m;             // lumped mass, row sums of eq. 2.3.7
            momentum[n] += (N * m) * v;  // eq. 2.4.1
        }
    });
    grid.collectActive();
    if (e.rankSums) {  // a parallel run: the other ranks' parts
        // The loads on rigid bodies sum over the nodes each rank owns: those touched shared first.
        e.rankSums->completeMassAndMomentum(grid, driven_ != nullptr);
        if (driven_) driven_->complete(grid, *e.rankSums);
    }
    grid.velocitiesFromMomenta();
    if (driven_) driven_->constrain(grid, e.rigid, t);
    e.sides.constrain(grid.velocity);
}

template <int D>
void SingleField<D>::updateGrid(EngineView<D>& e, double tNew, double dt)
{
    auto timer = e.timers.time("gridUpdate");
    Grid<D>& grid = e.grid;
    const double alpha = e.damping;
    grid.forEachActiveNode([&](int n) {
        Vector F = grid.fInt[n] + grid.fExt[n];
        if (alpha > 0) applyLocalDamping(F, grid.velocity[n], alpha);  // of F_ext + F_int
        // Nodes far lighter than any particle (a particle just touching the cell) would
        // get a huge F/m: USL then feeds it into the strain (the small-mass instability).
        grid.accel[n] = grid.mass[n] > e.minNodalMass ? Vector(F / grid.mass[n]) : Vector::Zero();  // eq. 2.4.2
    });
    // Rigid nodes: the acceleration that brings them to the body's velocity.
    if (driven_) driven_->update(grid, e.rigid, tNew, dt, e.gravity, e.minNodalMass, this->loads_, e.rankSums);
    grid.forEachActiveNode([&](int n) {
        grid.velocity[n] += dt * grid.accel[n];  // eq. 2.4.3
    });
    e.sides.constrainUpdate(grid.velocity, grid.accel, dt);
}

template <int D>
void SingleField<D>::remapVelocity(EngineView<D>& e, double tNew, double dt)
{
    Grid<D>& grid = e.grid;
    const ShapeWeights<D>& w = e.weights;
    const int stride = w.stride;
    grid.forEachActiveNode([&](int n) { grid.momentum[n].setZero(); });
    const int* node = w.node.data();
    const double* Nw = w.N.data();
    Vector* momentum = grid.momentum.data();
    const bool affine = e.particles.carries(FieldGroup::affine);
    e.strips.forEach([&, node, Nw, momentum, affine, stride](std::size_t q) {  // as particlesToGrid
        const std::size_t k0 = q * stride;
        const Vector xp = e.remapCentre(q, dt);
        const double m = e.inertialMass(q);
        const Vector vp = e.particles.v[q];
        for (int a = 0; a < stride; ++a) {
            const int n = node[k0 + a];
            if (n < 0) continue;
            momentum[n] += (Nw[k0 + a] * m) * (affine ? e.carriedVelocity(q, n, xp) : vp);
        }
    });
    if (e.rankSums) e.rankSums->completeMomentum(grid);
    grid.velocitiesFromMomenta();
    if (driven_) driven_->constrain(grid, e.rigid, tNew);
    e.sides.constrain(grid.velocity);
}

template class SingleField<2>;
#if GPIC_WITH_3D
template class SingleField<3>;
#endif

} // namespace gpic
