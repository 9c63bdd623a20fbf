#include "shapeFunctions/BilinearShape.H"

#include "core/Threads.H"

namespace gpic {

GPIC_REGISTER(ShapeFunction, BilinearShape, "bilinear")

void BilinearShape::evaluate(const Grid& grid, const Particles& p, ShapeWeights& w) const
{
    w.resize(p.size(), 4);
    const Vector2 h = grid.cellSize();
    const auto n = static_cast<long>(p.size());
    // The arrays' pointers in locals: Eigen's SSE stores may alias anything, and the compiler
    // would otherwise reload them after each weight written.
    int* node = w.node.data();
    double* N = w.N.data();
    Vector2* dN = w.dN.data();
    const Vector2* x = p.x.data();
#pragma omp parallel for schedule(static) if (n >= minParallelWork())
    for (long q = 0; q < n; ++q) {
        int i, j;
        grid.cellOf(x[q], i, j);
        const Vector2 local = x[q] - grid.nodePosition(i, j);
        const double xi = local.x() / h.x(), eta = local.y() / h.y();
        const std::size_t k = q * 4;
        // Counter-clockwise from the lower-left node.
        const int nodes[4] = {grid.node(i, j), grid.node(i + 1, j), grid.node(i + 1, j + 1),
                              grid.node(i, j + 1)};
        const double Nx[4] = {1 - xi, xi, xi, 1 - xi}, Ny[4] = {1 - eta, 1 - eta, eta, eta};
        const double dNx[4] = {-1 / h.x(), 1 / h.x(), 1 / h.x(), -1 / h.x()};
        const double dNy[4] = {-1 / h.y(), -1 / h.y(), 1 / h.y(), 1 / h.y()};
        for (int a = 0; a < 4; ++a) {
            node[k + a] = nodes[a];
            N[k + a] = Nx[a] * Ny[a];
            dN[k + a] = Vector2(dNx[a] * Ny[a], Nx[a] * dNy[a]);
        }
    }
}

} // namespace gpic
