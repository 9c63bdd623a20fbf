#include "grid/Grid.H"

#include "core/Threads.H"
#include "dictionary/Dictionary.H"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace gpic {

const std::array<std::string, PlaneSpace::nFaces>& gridSideNames()
{
    static const std::array<std::string, PlaneSpace::nFaces> names{"left", "right", "bottom", "top"};
    return names;
}

namespace {
//- Refuse a grid of nx x ny cells whose nodes the machine cannot hold (or number).
void checkMemory(const Dictionary& dict, long nx, long ny)
{
    // What the nodes need before anything is allocated: a grid beyond the machine (or
    // beyond an int's node numbering) is an input error, not a bad_alloc in mid-setup.
    const double nodes = double(nx + 1) * double(ny + 1);
    // The grid's own nodal arrays (Grid::allocate): mass, five vectors, the active flag and index.
    constexpr double nodeBytes = sizeof(double) + 5 * sizeof(Vector2) + sizeof(unsigned char) + sizeof(int);
    const double need = nodes * nodeBytes;
    const double have = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    const auto size = [](double bytes) {
        std::ostringstream s;
        s << std::setprecision(3) << (bytes >= 1e9 ? bytes / 1e9 : bytes / 1e6) << (bytes >= 1e9 ? " GB" : " MB");
        return s.str();
    };
    const std::string cells = "nCells: " + std::to_string(nx) + " x " + std::to_string(ny) + " cells";
    if (nodes > double(std::numeric_limits<int>::max()))
        dict.fail("nCells", cells + " have " + std::to_string(static_cast<long long>(nodes)) +
                                " nodes, more than the " + std::to_string(std::numeric_limits<int>::max()) +
                                " a grid can number");
    if (have > 0 && need > have)
        dict.fail("nCells", cells + " need at least " + size(need) + " of memory for the nodes alone; this machine has " +
                                size(have));
}

} // namespace

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
    checkMemory(dict, n[0], n[1]);
    nx_ = n[0];
    ny_ = n[1];
    // x1 is the radius of a body of revolution: the grid may start on the axis, not across it.
    axisymmetric_ = dict.getWordOrDefault("geometry", {"planeStrain", "axisymmetric"}, "planeStrain") == "axisymmetric";
    if (axisymmetric_ && origin_.x() < 0) {
        std::ostringstream msg;
        msg << "keyword 'origin' in dictionary " << dict.name() << ": with geometry axisymmetric x1 is the radius "
            << "r >= 0, but the grid starts at r = " << origin_.x() << "; start it on the axis (origin (0 ...)) or beyond";
        dict.fail("origin", msg.str());
    }
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
    isActive_.assign(n, NodeMark::idle);
    active.reserve(n);
}

void Grid::resetFields()
{
    // Only nodes touched last step hold non-zero values. The arrays' pointers in locals:
    // Eigen's SSE stores may alias anything (doc/threading.md).
    const int* nodes = active.data();
    const long count = static_cast<long>(active.size());
    double* m = mass.data();
    Vector2* fields[] = {momentum.data(), velocity.data(), fInt.data(), fExt.data(), accel.data()};
    Vector2* contact = fContact.empty() ? nullptr : fContact.data();
    NodeMark* marks = isActive_.data();
#pragma omp parallel for schedule(static) if (count >= minParallelWork())
    for (long k = 0; k < count; ++k) {
        const int n = nodes[k];
        m[n] = 0.0;
        for (Vector2* field : fields) field[n].setZero();
        if (contact) contact[n].setZero();
        marks[n] = NodeMark::idle;
    }
    active.clear();
}

void Grid::collectActive()
{
    active.clear();
    const int n = nNodes();
    for (int i = 0; i < n; ++i)
        if (isActive_[static_cast<std::size_t>(i)] == NodeMark::active) active.push_back(i);
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
