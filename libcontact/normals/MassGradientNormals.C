#include "normals/MassGradientNormals.H"

#include <algorithm>
#include <cmath>

namespace gpic {

MassGradientNormals::MassGradientNormals(const Dictionary&, const ContactScene& scene) : nBodies_(scene.nBodies()) {}

void MassGradientNormals::place(const Grid<2>& grid, const Particles<2>& p, const std::vector<int>& nodes)
{
    nx_ = grid.nx();
    ny_ = grid.ny();
    h_ = grid.cellSize();
    const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    density_.assign(static_cast<std::size_t>(nBodies_) * cells, 0.0);
    // Only the box of cells around the contact nodes is summed (outward() reads no others):
    // most particles are far from contact. One thread, in particle order, so that each sum
    // is the same at any thread count.
    int iLow = nx_, iHigh = -1, jLow = ny_, jHigh = -1;
    for (int n : nodes) {
        const int i = n % (nx_ + 1), j = n / (nx_ + 1);
        iLow = std::min(iLow, std::max(i - 1, 0)), iHigh = std::max(iHigh, std::min(i, nx_ - 1));
        jLow = std::min(jLow, std::max(j - 1, 0)), jHigh = std::max(jHigh, std::min(j, ny_ - 1));
    }
    const Vector2 origin = grid.origin(), h = h_;
    // A particle reaches the centres of the cells within half a cell of its own: one beyond
    // these bounds (a cell's margin) adds to no cell of the box, and every cell of the box
    // gets all of its particles.
    const Vector2 low = origin + Vector2((iLow - 1) * h.x(), (jLow - 1) * h.y());
    const Vector2 high = origin + Vector2((iHigh + 2) * h.x(), (jHigh + 2) * h.y());
    const Vector2* x = p.x.data();
    const double* m = p.m.data();
    const int* body = p.body.data();
    for (std::size_t q = 0; q < p.size(); ++q) {
        if (x[q].x() < low.x() || x[q].x() >= high.x() || x[q].y() < low.y() || x[q].y() >= high.y()) continue;
        // Element centres within one cell of the particle, with bilinear weights S1.
        const Vector2 s = Vector2((x[q] - origin).array() / h.array()) - Vector2(0.5, 0.5);
        const int i0 = Grid<2>::floorToInt(s.x()), j0 = Grid<2>::floorToInt(s.y());
        const double fx = s.x() - i0, fy = s.y() - j0;
        double* rho = density_.data() + static_cast<std::size_t>(body[q]) * cells;
        for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) {
                const int i = i0 + a, j = j0 + b;
                if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
                const double S1 = (a ? fx : 1.0 - fx) * (b ? fy : 1.0 - fy);
                rho[i + j * nx_] += m[q] * S1;
            }
    }
}

Vector2 MassGradientNormals::outward(int body, int node) const
{
    const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    const double* rho = density_.data() + static_cast<std::size_t>(body) * cells;
    const int i = node % (nx_ + 1), j = node / (nx_ + 1);
    // c_cv of the node in each element around it points from the element centre to the
    // node (G.3): the sum of c_cv rho_c points away from the dense side.
    Vector2 g = Vector2::Zero();
    for (int b = -1; b <= 0; ++b)
        for (int a = -1; a <= 0; ++a) {
            const int ci = i + a, cj = j + b;
            if (ci < 0 || cj < 0 || ci >= nx_ || cj >= ny_) continue;
            const double r = rho[ci + cj * nx_];
            g += r * Vector2(a < 0 ? h_.y() : -h_.y(), b < 0 ? h_.x() : -h_.x());
        }
    const double len = g.norm();
    return len > 0.0 ? Vector2(g / len) : Vector2::Zero();
}

GPIC_REGISTER(ContactNormals<2>, MassGradientNormals, "massGradient")

} // namespace gpic
