#include "shapeFunctions/UGimpShape.H"

#include "core/Threads.H"
#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER(ShapeFunction, UGimpShape, "uGIMP")

void UGimpShape::weight1D(double r, double h, double lp, double& S, double& dS)
{
    const double a = std::abs(r), sign = r < 0 ? -1.0 : 1.0;
    if (a < lp) {
        S = 1.0 - (r * r + lp * lp) / (2.0 * h * lp);
        dS = -r / (h * lp);
    } else if (a < h - lp) {
        S = 1.0 - a / h;
        dS = -sign / h;
    } else if (a < h + lp) {
        const double d = h + lp - a;
        S = d * d / (4.0 * h * lp);
        dS = -sign * d / (2.0 * h * lp);
    } else {
        S = 0.0;
        dS = 0.0;
    }
}

void UGimpShape::weightRadial(double rp, double ri, double h, double lp, double& S, double& dS, double& T)
{
    const double r1 = std::max(rp - lp, 0.0), r2 = rp + lp;
    const double ringArea = 0.5 * (r2 * r2 - r1 * r1);  // int r dr over the domain
    const auto N = [&](double r) { return std::max(0.0, 1.0 - std::abs(r - ri) / h); };
    // The pieces of [r1, r2] on which N_i is linear: cut at ri - h, ri, ri + h.
    double cuts[5] = {r1, ri - h, ri, ri + h, r2};
    std::sort(cuts + 1, cuts + 4);
    double NrSum = 0, dNrSum = 0, NSum = 0;
    double a = r1;
    for (int k = 1; k < 5; ++k) {
        const double b = std::min(std::max(cuts[k], r1), r2);
        if (b > a) {
            const double m = 0.5 * (a + b), Na = N(a), Nb = N(b);
            NrSum += (b - a) / 6.0 * (Na * a + 4.0 * N(m) * m + Nb * b);
            NSum += 0.5 * (b - a) * (Na + Nb);
            dNrSum += (Nb - Na) / (b - a) * 0.5 * (b * b - a * a);  // N' constant on the piece
            a = b;
        }
    }
    S = NrSum / ringArea;
    dS = dNrSum / ringArea;
    T = NSum / ringArea;
}

void UGimpShape::evaluate(const Grid& grid, const Particles& p, ShapeWeights& w) const
{
    w.resize(p.size(), 9);
    const bool rings = grid.axisymmetric();
    w.hoop.resize(rings ? w.N.size() : 0);
    const Vector2 h = grid.cellSize();
    const auto n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static) if (n >= minParallelWork())
    for (long q = 0; q < n; ++q) {
        int i, j;
        grid.cellOf(p.x[q], i, j);
        const Vector2 local = p.x[q] - grid.nodePosition(i, j);
        // The three nodes whose support can reach the particle in each direction.
        const int i0 = local.x() < 0.5 * h.x() ? i - 1 : i;
        const int j0 = local.y() < 0.5 * h.y() ? j - 1 : j;
        const Vector2 lp = p.halfSize[q];
        std::size_t k = q * 9;
        for (int b = 0; b < 3; ++b) {
            const int jn = j0 + b;
            double Sy = 0, dSy = 0;
            if (jn >= 0 && jn <= grid.ny())
                weight1D(p.x[q].y() - (grid.origin().y() + jn * h.y()), h.y(), lp.y(), Sy, dSy);
            for (int a = 0; a < 3; ++a, ++k) {
                const int in = i0 + a;
                double Sx = 0, dSx = 0, Tx = 0;
                if (in >= 0 && in <= grid.nx()) {
                    const double xi = grid.origin().x() + in * h.x();
                    if (rings)
                        weightRadial(p.x[q].x(), xi, h.x(), lp.x(), Sx, dSx, Tx);
                    else
                        weight1D(p.x[q].x() - xi, h.x(), lp.x(), Sx, dSx);
                }
                const bool inside = in >= 0 && in <= grid.nx() && jn >= 0 && jn <= grid.ny();
                w.node[k] = inside ? grid.node(in, jn) : -1;
                w.N[k] = inside ? Sx * Sy : 0.0;
                w.dN[k] = inside ? Vector2(dSx * Sy, Sx * dSy) : Vector2::Zero();
                if (rings) w.hoop[k] = inside ? Tx * Sy : 0.0;
            }
        }
    }
}

} // namespace gpic
