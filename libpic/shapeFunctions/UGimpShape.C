#include "shapeFunctions/UGimpShape.H"

#include "core/Threads.H"
#include "shapeFunctions/TensorProduct.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER_DIMS(ShapeFunction, UGimpShape, "uGIMP")

void UGimp::weight1D(double r, double h, double lp, double& S, double& dS)
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

void UGimp::weightRadial(double rp, double ri, double h, double lp, double& S, double& dS, double& T)
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

template <int D> void UGimpShape<D>::evaluate(const Grid<D>& grid, const Particles<D>& p, ShapeWeights<D>& w) const
{
    using Vector = typename Space<D>::Vector;
    constexpr int nodes = power(3, D);
    constexpr NodeOrder<D, 3> order = axisOrder<D, 3>();
    w.resize(p.size(), nodes);
    const bool rings = grid.axisymmetric();
    w.hoop.resize(rings ? w.N.size() : 0);
    const Vector h = grid.cellSize();
    const auto n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static) if (n >= minParallelWork())
    for (long q = 0; q < n; ++q) {
        const Vector& xp = p.x[q];
        const typename Grid<D>::Index cell = grid.cellOf(xp);
        const Vector local = xp - grid.nodePosition(cell);
        const Vector lp = p.halfSize[q];
        AxisWeights<D, 3> axis;
        double T[3] = {0, 0, 0};  // the hoop weights along the radius x1
        for (int a = 0; a < D; ++a) {
            // The three nodes whose support can reach the particle.
            axis.first[a] = local[a] < 0.5 * h[a] ? cell[a] - 1 : cell[a];
            for (int k = 0; k < 3; ++k) {
                const int i = axis.first[a] + k;
                axis.exists[a][k] = i >= 0 && i <= grid.cells(a);
                axis.S[a][k] = axis.dS[a][k] = 0.0;
                if (!axis.exists[a][k]) continue;
                const double xi = grid.origin()[a] + i * h[a];
                if (a == 0 && rings)
                    UGimp::weightRadial(xp[0], xi, h[0], lp[0], axis.S[0][k], axis.dS[0][k], T[k]);
                else
                    UGimp::weight1D(xp[a] - xi, h[a], lp[a], axis.S[a][k], axis.dS[a][k]);
            }
        }
        const std::size_t k = q * nodes;
        writeTensorProduct<D, 3, false>(grid, axis, w.node.data() + k, w.N.data() + k, w.dN.data() + k);
        if (rings)  // <N_i / r> = T_i(r) S_i(z): the ring average along the radius only
            for (int l = 0; l < nodes; ++l) {
                double hoop = T[order[l][0]];
                for (int a = 1; a < D; ++a) hoop *= axis.S[a][order[l][a]];
                w.hoop[k + l] = w.node[k + l] < 0 ? 0.0 : hoop;
            }
    }
}

template class UGimpShape<2>;
#if GPIC_WITH_3D
template class UGimpShape<3>;
#endif

} // namespace gpic
