#include "shapeFunctions/QuadraticBSplineShape.H"

#include "core/Threads.H"
#include "shapeFunctions/TensorProduct.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER_DIMS(ShapeFunction, QuadraticBSplineShape, "quadraticBSpline")

namespace {
//- Knot k of the open knot vector 0 0 0 3/2 5/2 ... n-3/2 n n n (in cells).
double knot(int k, int n)
{
    if (k < 3) return 0.0;
    if (k > n) return double(n);
    return k - 1.5;
}

//- Is u in the knot span [a, b)? The last span is closed so the side u = n belongs to it.
bool inSpan(double u, double a, double b, int n)
{
    return b > a && u >= a && (u < b || (b >= n && u <= b));
}

//- Linear B-spline on knots a <= b <= c.
double linear(double u, double a, double b, double c, int n)
{
    if (inSpan(u, a, b, n)) return (u - a) / (b - a);
    if (inSpan(u, b, c, n)) return (c - u) / (c - b);
    return 0.0;
}
} // namespace

int QuadraticBSpline::firstNode(double u, int n)
{
    return n < 2 ? 0 : std::clamp(static_cast<int>(std::floor(u - 0.5)), 0, n - 2);
}

void QuadraticBSpline::weight1D(int i, double u, int n, double& S, double& dS)
{
    if (n == 1) {  // one cell across (a bar, a layer): the linear splines of its two nodes
        S = i == 0 ? 1.0 - u : (i == 1 ? u : 0.0);
        dS = i == 0 ? -1.0 : (i == 1 ? 1.0 : 0.0);
        return;
    }
    // Cox-de Boor on knots t0..t3 of node i; a zero-length span contributes nothing.
    const double t0 = knot(i, n), t1 = knot(i + 1, n), t2 = knot(i + 2, n), t3 = knot(i + 3, n);
    const double left = t2 > t0 ? linear(u, t0, t1, t2, n) / (t2 - t0) : 0.0;
    const double right = t3 > t1 ? linear(u, t1, t2, t3, n) / (t3 - t1) : 0.0;
    S = (u - t0) * left + (t3 - u) * right;
    dS = 2.0 * (left - right);
}

double QuadraticBSpline::greville(int i, int n) { return n == 1 ? double(i) : 0.5 * (knot(i + 1, n) + knot(i + 2, n)); }

template <int D> typename Space<D>::Vector QuadraticBSplineShape<D>::affineCentre(const Grid<D>& grid, int n) const
{
    const typename Grid<D>::Index i = grid.nodeIndex(n);
    Vector x;
    for (int a = 0; a < D; ++a)
        x[a] = grid.origin()[a] + QuadraticBSpline::greville(i[a], grid.cells(a)) * grid.cellSize()[a];
    return x;
}

template <int D>
void QuadraticBSplineShape<D>::evaluate(const Grid<D>& grid, const Particles<D>& p, ShapeWeights<D>& w) const
{
    constexpr int nodes = power(3, D);
    w.resize(p.size(), nodes);
    const Vector h = grid.cellSize();
    const auto n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static) if (n >= minParallelWork())
    for (long q = 0; q < n; ++q) {
        const Vector u = (p.x[q] - grid.origin()).cwiseQuotient(h);
        AxisWeights<D, 3> axis;
        for (int a = 0; a < D; ++a) {
            const int cells = grid.cells(a);
            axis.first[a] = QuadraticBSpline::firstNode(u[a], cells);
            for (int k = 0; k < 3; ++k) {
                QuadraticBSpline::weight1D(axis.first[a] + k, u[a], cells, axis.S[a][k], axis.dS[a][k]);
                // One cell across an axis: its third slot has no node.
                axis.exists[a][k] = axis.first[a] + k <= cells;
            }
        }
        const std::size_t k = q * nodes;
        writeTensorProduct<D, 3, false>(grid, axis, w.node.data() + k, w.N.data() + k, w.dN.data() + k, &h);
    }
}

template class QuadraticBSplineShape<2>;
#if GPIC_WITH_3D
template class QuadraticBSplineShape<3>;
#endif

} // namespace gpic
