#include "grid/Grid.H"

#include "core/Threads.H"
#include "dictionary/Dictionary.H"

#include <algorithm>
#include <cmath>

namespace gpic {

const std::array<std::string, 4>& gridSideNames()
{
    static const std::array<std::string, 4> names{"left", "right", "bottom", "top"};
    return names;
}

Grid::Grid(const Dictionary& dict)
{
    origin_ = dict.get<Vector2>("origin");
    const Entry* size = dict.findEntry("cellSize");
    if (size && size->tokens.size() == 1) {
        const double h = dict.getChecked<double>(
            "cellSize", [](const double& v) { return v > 0; }, "cellSize > 0");
        h_ = Vector2(h, h);
    } else {
        h_ = dict.getChecked<Vector2>(
            "cellSize", [](const Vector2& v) { return v.x() > 0 && v.y() > 0; },
            "both cell sizes > 0");
    }
    const auto n = dict.getChecked<std::vector<int>>(
        "nCells", [](const std::vector<int>& v) { return v.size() == 2 && v[0] > 0 && v[1] > 0; },
        "two positive cell counts (nx ny)");
    nx_ = n[0];
    ny_ = n[1];
    allocate();
}

Grid::Grid(const Vector2& origin, const Vector2& cellSize, int nx, int ny)
    : origin_(origin), h_(cellSize), nx_(nx), ny_(ny)
{
    allocate();
}

void Grid::allocate()
{
    const auto n = static_cast<std::size_t>(nNodes());
    mass.assign(n, 0.0);
    momentum.assign(n, Vector2::Zero());
    velocity.assign(n, Vector2::Zero());
    fInt.assign(n, Vector2::Zero());
    fExt.assign(n, Vector2::Zero());
    accel.assign(n, Vector2::Zero());
    isActive_.assign(n, 0);
    active.reserve(n);
}

void Grid::resetFields()
{
    // Only nodes touched last step hold non-zero values.
#pragma omp parallel for schedule(static) if (static_cast<long>(active.size()) >= minParallelWork())
    for (std::size_t k = 0; k < active.size(); ++k) {
        const int n = active[k];
        mass[n] = 0.0;
        momentum[n].setZero();
        velocity[n].setZero();
        fInt[n].setZero();
        fExt[n].setZero();
        accel[n].setZero();
        if (!fContact.empty()) fContact[n].setZero();
        isActive_[n] = 0;
    }
    active.clear();
}

void Grid::collectActive()
{
    active.clear();
    const int n = nNodes();
    for (int i = 0; i < n; ++i)
        if (isActive_[static_cast<std::size_t>(i)]) active.push_back(i);
}

bool Grid::contains(const Vector2& x) const
{
    const Vector2 top = upper();
    return x.x() >= origin_.x() && x.y() >= origin_.y() && x.x() <= top.x() && x.y() <= top.y();
}

void Grid::cellOf(const Vector2& x, int& i, int& j) const
{
    i = std::clamp(static_cast<int>(std::floor((x.x() - origin_.x()) / h_.x())), 0, nx_ - 1);
    j = std::clamp(static_cast<int>(std::floor((x.y() - origin_.y()) / h_.y())), 0, ny_ - 1);
}

std::vector<int> Grid::sideNodes(GridSide side) const
{
    std::vector<int> nodes;
    switch (side) {
    case GridSide::left: for (int j = 0; j <= ny_; ++j) nodes.push_back(node(0, j)); break;
    case GridSide::right: for (int j = 0; j <= ny_; ++j) nodes.push_back(node(nx_, j)); break;
    case GridSide::bottom: for (int i = 0; i <= nx_; ++i) nodes.push_back(node(i, 0)); break;
    case GridSide::top: for (int i = 0; i <= nx_; ++i) nodes.push_back(node(i, ny_)); break;
    }
    return nodes;
}

} // namespace gpic
