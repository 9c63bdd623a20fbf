#include "schemes/AffineVelocity.H"

#include "core/Threads.H"

#include <Eigen/LU>

namespace gpic {

GPIC_REGISTER_PASS_DIMS(AffineVelocity, "affineVelocity")

template <int D>
AffineVelocity<D>::AffineVelocity(const Grid<D>& grid, const ShapeFunction<D>& shape)
    : fromGradient_(shape.affineFromGradient())
{
    centre_.reserve(static_cast<std::size_t>(grid.nNodes()));
    for (int n = 0; n < grid.nNodes(); ++n) centre_.push_back(shape.affineCentre(grid, n));
}

template <int D>
void AffineVelocity<D>::form(Particles<D>& p, const ShapeWeights<D>& weights, std::size_t q,
                          const std::vector<Vector>& velocity, const Vector& xp, const double* mass,
                          const Vector& own) const
{
    const int stride = weights.stride;
    const std::size_t k0 = q * stride;
    const double light = lightShare * p.m[q];
    typename Space<D>::Gradient B = Space<D>::Gradient::Zero(), Dp = Space<D>::Gradient::Zero();
    for (int k = 0; k < stride; ++k) {
        const int n = weights.node[k0 + k];
        if (n < 0) continue;
        const double N = weights.N[k0 + k];
        const Vector r = centre_[static_cast<std::size_t>(n)] - xp;
        Dp.noalias() += (N * r) * r.transpose();  // D_p, h^2/4 I inside a B-spline grid
        // A light node's v^{t+1} holds dt F/m of a tiny mass, which bilinear cells would take
        // at full weight (doc/stability.md, "A node one particle reaches").
        const Vector& v = mass && mass[n] < light ? own : velocity[n];
        // bilinear: B_p D_p^-1 is the velocity gradient (D_p singular on a grid line)
        if (fromGradient_) B.noalias() += v * weights.dN[k0 + k].transpose();
        else B.noalias() += (N * v) * r.transpose();  // B_p (Jiang et al. 2015)
    }
    typename Space<D>::Gradient& C = p.affine[q];
    C = fromGradient_ ? B : typename Space<D>::Gradient(B * Dp.inverse());
    p.affineEnergy[q] = 0.5 * p.m[q] * (C * Dp * C.transpose()).trace();
}

template <int D>
void AffineVelocity<D>::at(StepPoint, EngineView<D>& e, double dt)
{
    // MUSL: C_p again, from the remapped nodal velocity: a mass-weighted mean of the
    // particles' motion, where v^{t+1} of a node that a particle barely touches holds
    // dt F/m of a tiny mass (the small-mass instability, Sulsky et al. 1995).
    Particles<D>& p = e.particles;
    const auto nParticles = static_cast<long>(p.size());
    parallelFor(nParticles, [&](long q) {
        if (e.isRigid(static_cast<std::size_t>(q))) return;
        const std::vector<Vector>& velocity = e.coupling.velocity(e.grid, e.coupling.fieldOf(p.body[q]));
        form(p, e.weights, static_cast<std::size_t>(q), velocity, e.remapCentre(static_cast<std::size_t>(q), dt));
    });
}

template class AffineVelocity<2>;
#if GPIC_WITH_3D
template class AffineVelocity<3>;
#endif

} // namespace gpic
