#include "normals/MassGradientNormals.H"

#include <cmath>

namespace gpic {

MassGradientNormals::MassGradientNormals(const Dictionary&, const ContactScene& scene) : nBodies_(scene.nBodies()) {}

void MassGradientNormals::place(const Grid& grid, const Particles& p)
{
    nx_ = grid.nx();
    ny_ = grid.ny();
    h_ = grid.cellSize();
    const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    density_.assign(static_cast<std::size_t>(nBodies_) * cells, 0.0);
    for (std::size_t q = 0; q < p.size(); ++q) {
        // Element centres within one cell of the particle, with bilinear weights S1.
        const Vector2 s = Vector2((p.x[q] - grid.origin()).array() / h_.array()) - Vector2(0.5, 0.5);
        const int i0 = static_cast<int>(std::floor(s.x())), j0 = static_cast<int>(std::floor(s.y()));
        const double fx = s.x() - i0, fy = s.y() - j0;
        double* rho = density_.data() + static_cast<std::size_t>(p.body[q]) * cells;
        for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) {
                const int i = i0 + a, j = j0 + b;
                if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
                const double S1 = (a ? fx : 1.0 - fx) * (b ? fy : 1.0 - fy);
                rho[i + j * nx_] += p.m[q] * S1;
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

GPIC_REGISTER(ContactNormals, MassGradientNormals, "massGradient")

} // namespace gpic
