#include "shapeFunctions/QuadraticBSplineShape.H"

#include "core/Threads.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER(ShapeFunction, QuadraticBSplineShape, "quadraticBSpline")

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

int QuadraticBSplineShape::firstNode(double u, int n)
{
    return n < 2 ? 0 : std::clamp(static_cast<int>(std::floor(u - 0.5)), 0, n - 2);
}

void QuadraticBSplineShape::weight1D(int i, double u, int n, double& S, double& dS)
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

Vector2 QuadraticBSplineShape::affineCentre(const Grid& grid, int n) const
{
    const int i = n % (grid.nx() + 1), j = n / (grid.nx() + 1);
    const auto greville = [](int k, int cells) { return cells == 1 ? double(k) : 0.5 * (knot(k + 1, cells) + knot(k + 2, cells)); };
    return grid.origin() + Vector2(greville(i, grid.nx()) * grid.cellSize().x(), greville(j, grid.ny()) * grid.cellSize().y());
}

void QuadraticBSplineShape::evaluate(const Grid& grid, const Particles& p, ShapeWeights& w) const
{
    w.resize(p.size(), 9);
    const Vector2 h = grid.cellSize();
    const auto n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static) if (n >= minParallelWork())
    for (long q = 0; q < n; ++q) {
        const Vector2 u = (p.x[q] - grid.origin()).cwiseQuotient(h);
        const int i0 = firstNode(u.x(), grid.nx()), j0 = firstNode(u.y(), grid.ny());
        double Sx[3], dSx[3], Sy[3], dSy[3];
        for (int a = 0; a < 3; ++a) {
            weight1D(i0 + a, u.x(), grid.nx(), Sx[a], dSx[a]);
            weight1D(j0 + a, u.y(), grid.ny(), Sy[a], dSy[a]);
        }
        std::size_t k = q * 9;
        for (int b = 0; b < 3; ++b)
            for (int a = 0; a < 3; ++a, ++k) {
                // One cell across an axis: its third slot has no node.
                const bool exists = i0 + a <= grid.nx() && j0 + b <= grid.ny();
                w.node[k] = exists ? grid.node(i0 + a, j0 + b) : -1;
                w.N[k] = exists ? Sx[a] * Sy[b] : 0.0;
                w.dN[k] = exists ? Vector2(dSx[a] * Sy[b] / h.x(), Sx[a] * dSy[b] / h.y()) : Vector2::Zero();
            }
    }
}

} // namespace gpic
