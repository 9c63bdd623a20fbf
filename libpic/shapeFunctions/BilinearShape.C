#include "shapeFunctions/BilinearShape.H"

#include "core/Threads.H"
#include "shapeFunctions/TensorProduct.H"

namespace gpic {

GPIC_REGISTER_DIMS(ShapeFunction, BilinearShape, "bilinear")

template <int D> void BilinearShape<D>::evaluate(const Grid<D>& grid, const Particles<D>& p, ShapeWeights<D>& w) const
{
    using Vector = typename Space<D>::Vector;
    constexpr int nodes = power(2, D);
    w.resize(p.size(), nodes);
    const Vector h = grid.cellSize();
    const auto n = static_cast<long>(p.size());
    // The arrays' pointers in locals: Eigen's SSE stores may alias anything, and the compiler
    // would otherwise reload them after each weight written.
    int* node = w.node.data();
    double* N = w.N.data();
    Vector* dN = w.dN.data();
    const Vector* x = p.x.data();
    // The gradients' factors are the same for every particle: computed once (as divisions,
    // so they round as they did per particle).
    Vector down, up;
    for (int a = 0; a < D; ++a) {
        down[a] = -1 / h[a];
        up[a] = 1 / h[a];
    }
#pragma omp parallel for schedule(static) if (n >= minParallelWork())
    for (long q = 0; q < n; ++q) {
        AxisWeights<D, 2> axis;
        axis.first = grid.cellOf(x[q]);
        const Vector local = x[q] - grid.nodePosition(axis.first);
        staticFor<D>([&](auto a) {
            const double xi = local[a] / h[a];
            axis.S[a][0] = 1 - xi;
            axis.S[a][1] = xi;
            axis.dS[a][0] = down[a];
            axis.dS[a][1] = up[a];
            axis.exists[a][0] = axis.exists[a][1] = true;
        });
        const std::size_t k = q * nodes;
        writeTensorProduct<D, 2, true>(grid, axis, node + k, N + k, dN + k);
    }
}

template class BilinearShape<2>;
#if GPIC_WITH_3D
template class BilinearShape<3>;
#endif

} // namespace gpic
