#include "normals/MassGradientNormals.H"

#include <algorithm>
#include <cmath>

namespace gpic {

template <int D>
MassGradientNormals<D>::MassGradientNormals(const Dictionary&, const ContactScene& scene)
    : nBodies_(scene.nBodies()), ranks_(scene.ranks)
{
    if constexpr (D == 3)
        for (std::size_t s = 0; s < mirror_.size() && s < scene.mirror.size(); ++s) mirror_[s] = scene.mirror[s];
}

template <int D> int MassGradientNormals<D>::folded(int a, int c) const
{
    if (c < 0) return mirror_[2 * a] ? -1 - c : -1;
    if (c >= n_[a]) return mirror_[2 * a + 1] ? 2 * n_[a] - 1 - c : -1;
    return c;
}

template <int D> std::size_t MassGradientNormals<D>::cellCount() const
{
    std::size_t cells = 1;
    for (int a = 0; a < D; ++a) cells *= static_cast<std::size_t>(n_[a]);
    return cells;
}

template <int D>
void MassGradientNormals<D>::place(const Grid<D>& grid, const Particles<D>& p, const std::vector<int>& nodes)
{
    for (int a = 0; a < D; ++a) n_[a] = grid.cells(a);
    h_ = grid.cellSize();
    const std::size_t cells = cellCount();
    density_.assign(static_cast<std::size_t>(nBodies_) * cells, 0.0);
    // Only the box of cells around the contact nodes is summed (outward() reads no others):
    // most particles are far from contact. One thread, in particle order, so that each sum
    // is the same at any thread count.
    std::array<int, D> lowCell = n_, highCell;
    highCell.fill(-1);
    for (int n : nodes) {
        const auto i = grid.nodeIndex(n);
        for (int a = 0; a < D; ++a) {
            lowCell[a] = std::min(lowCell[a], std::max(i[a] - 1, 0));
            highCell[a] = std::max(highCell[a], std::min(i[a], n_[a] - 1));
        }
    }
    if (ranks_.parallel()) {  // the box around every rank's contact nodes
        std::vector<double> bounds;
        for (int a = 0; a < D; ++a) bounds.insert(bounds.end(), {double(lowCell[a]), -double(highCell[a])});
        ranks_.minOver(bounds);
        for (int a = 0; a < D; ++a) lowCell[a] = int(bounds[2 * a]), highCell[a] = -int(bounds[2 * a + 1]);
    }
    const Vector origin = grid.origin(), h = h_;
    // A particle reaches the centres of the cells within half a cell of its own: one beyond
    // these bounds (a cell's margin) adds to no cell of the box, and every cell of the box
    // gets all of its particles.
    Vector low, high;
    for (int a = 0; a < D; ++a) {
        low[a] = origin[a] + (lowCell[a] - 1) * h[a];
        high[a] = origin[a] + (highCell[a] + 2) * h[a];
    }
    const Vector* x = p.x.data();
    const double* m = p.m.data();
    const int* body = p.body.data();
    for (std::size_t q = 0; q < p.size(); ++q) {
        bool outside = false;
        for (int a = 0; a < D; ++a) outside = outside || x[q][a] < low[a] || x[q][a] >= high[a];
        if (outside) continue;
        // Element centres within one cell of the particle, with the weights S1 of the cell.
        const Vector s = Vector((x[q] - origin).array() / h.array()) - Vector::Constant(0.5);
        std::array<int, D> c0;
        Vector f;
        for (int a = 0; a < D; ++a) {
            c0[a] = Grid<D>::floorToInt(s[a]);
            f[a] = s[a] - c0[a];
        }
        double* rho = density_.data() + static_cast<std::size_t>(body[q]) * cells;
        if constexpr (D == 2) {
            for (int b = 0; b < 2; ++b)
                for (int a = 0; a < 2; ++a) {
                    const int i = c0[0] + a, j = c0[1] + b;
                    if (i < 0 || j < 0 || i >= n_[0] || j >= n_[1]) continue;
                    const double S1 = (a ? f[0] : 1.0 - f[0]) * (b ? f[1] : 1.0 - f[1]);
                    rho[i + j * n_[0]] += m[q] * S1;
                }
        } else {
            for (int c = 0; c < 2; ++c)
                for (int b = 0; b < 2; ++b)
                    for (int a = 0; a < 2; ++a) {
                        // A weight beyond a mirror side is the mirror particle's in the cell before it.
                        const int i = folded(0, c0[0] + a), j = folded(1, c0[1] + b), k = folded(2, c0[2] + c);
                        if (i < 0 || j < 0 || k < 0) continue;
                        const double S1 = (a ? f[0] : 1.0 - f[0]) * (b ? f[1] : 1.0 - f[1]) * (c ? f[2] : 1.0 - f[2]);
                        rho[i + n_[0] * (j + n_[1] * k)] += m[q] * S1;
                    }
        }
    }
    if (ranks_.parallel()) sumBoxOverRanks(lowCell, highCell);
}

template <int D>
void MassGradientNormals<D>::sumBoxOverRanks(const std::array<int, D>& lowCell, const std::array<int, D>& highCell)
{
    // The box's cells of every body, in one sum; the cells a mirror folds back into the box
    // lie in it already (a fold maps onto the cells beside the side).
    std::vector<std::size_t> cells;
    std::array<int, D> c = lowCell;
    for (int a = 0; a < D; ++a)
        if (highCell[a] < lowCell[a]) return;  // no rank has contact
    while (true) {
        std::size_t index = 0, stride = 1;
        for (int a = 0; a < D; ++a) index += stride * static_cast<std::size_t>(c[a]), stride *= static_cast<std::size_t>(n_[a]);
        cells.push_back(index);
        int a = 0;
        while (a < D && ++c[a] > highCell[a]) c[a] = lowCell[a], ++a;
        if (a == D) break;
    }
    const std::size_t all = cellCount();
    std::vector<double> values;
    values.reserve(cells.size() * static_cast<std::size_t>(nBodies_));
    for (int b = 0; b < nBodies_; ++b)
        for (std::size_t k : cells) values.push_back(density_[static_cast<std::size_t>(b) * all + k]);
    ranks_.sumOver(values);
    std::size_t v = 0;
    for (int b = 0; b < nBodies_; ++b)
        for (std::size_t k : cells) density_[static_cast<std::size_t>(b) * all + k] = values[v++];
}

template <int D> typename MassGradientNormals<D>::Vector MassGradientNormals<D>::outward(int body, int node) const
{
    const double* rho = density_.data() + static_cast<std::size_t>(body) * cellCount();
    const int i = node % (n_[0] + 1);
    // c_cv of the node in each element around it points from the element centre to the
    // node (G.3): the sum of c_cv rho_c points away from the dense side.
    Vector g = Vector::Zero();
    if constexpr (D == 2) {
        const int j = node / (n_[0] + 1);
        for (int b = -1; b <= 0; ++b)
            for (int a = -1; a <= 0; ++a) {
                const int ci = i + a, cj = j + b;
                if (ci < 0 || cj < 0 || ci >= n_[0] || cj >= n_[1]) continue;
                const double r = rho[ci + cj * n_[0]];
                g += r * Vector(a < 0 ? h_.y() : -h_.y(), b < 0 ? h_.x() : -h_.x());
            }
    } else {
        const int j = (node / (n_[0] + 1)) % (n_[1] + 1), k = node / ((n_[0] + 1) * (n_[1] + 1));
        // The faces of a cell normal to each axis, their areas up to the common factor.
        const Vector face(h_[1] * h_[2], h_[0] * h_[2], h_[0] * h_[1]);
        for (int c = -1; c <= 0; ++c)
            for (int b = -1; b <= 0; ++b)
                for (int a = -1; a <= 0; ++a) {
                    const int ci = folded(0, i + a), cj = folded(1, j + b), ck = folded(2, k + c);
                    if (ci < 0 || cj < 0 || ck < 0) continue;
                    const double r = rho[ci + n_[0] * (cj + n_[1] * ck)];
                    g += r * Vector(a < 0 ? face[0] : -face[0], b < 0 ? face[1] : -face[1], c < 0 ? face[2] : -face[2]);
                }
    }
    const double len = g.norm();
    return len > 0.0 ? Vector(g / len) : Vector::Zero();
}

template class MassGradientNormals<2>;
#if GPIC_WITH_3D
template class MassGradientNormals<3>;
#endif

GPIC_REGISTER_DIMS(ContactNormals, MassGradientNormals, "massGradient")

} // namespace gpic
