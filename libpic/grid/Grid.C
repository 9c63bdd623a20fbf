#include "grid/Grid.H"

#include "core/Threads.H"
#include "core/ByteSize.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <new>
#include <sstream>

namespace gpic {

const std::array<std::string, Space<3>::nFaces>& gridSideNames()
{
    static const std::array<std::string, Space<3>::nFaces> names{"left", "right", "bottom", "top", "back", "front"};
    return names;
}

namespace {
//- Refuse a grid whose nodes the machine cannot hold (or number).
template <int D> void checkMemory(const Dictionary& dict, const std::array<int, D>& n)
{
    // What the nodes need before anything is allocated: a grid beyond the machine (or
    // beyond an int's node numbering) is an input error, not a bad_alloc in mid-setup.
    double nodes = 1.0;
    std::string cells = "nCells: ";
    for (int a = 0; a < D; ++a) {
        nodes *= double(n[a]) + 1.0;
        cells += (a ? " x " : "") + std::to_string(n[a]);
    }
    cells += " cells";
    // The grid's own nodal arrays (Grid::allocate): mass, five vectors, the active flag and index.
    constexpr double nodeBytes =
        sizeof(double) + 5 * sizeof(typename Space<D>::Vector) + sizeof(unsigned char) + sizeof(int);
    const double need = nodes * nodeBytes;
    const double have = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    const auto size = [](double bytes) {
        std::ostringstream s;
        s << std::setprecision(3) << (bytes >= 1e9 ? bytes / 1e9 : bytes / 1e6) << (bytes >= 1e9 ? " GB" : " MB");
        return s.str();
    };
    if (nodes > double(std::numeric_limits<int>::max()))
        dict.fail("nCells", cells + " have " + std::to_string(static_cast<long long>(nodes)) +
                                " nodes, more than the " + std::to_string(std::numeric_limits<int>::max()) +
                                " a grid can number");
    if (have > 0 && need > have)
        dict.fail("nCells", cells + " need at least " + size(need) + " of memory for the nodes alone; this machine has " +
                                size(have));
}

} // namespace

template <int D> Grid<D>::Grid(const Dictionary& dict)
{
    origin_ = dict.get<Vector>("origin");
    const Entry* size = dict.findEntry("cellSize");
    if (size && size->tokens.size() == 1) {
        const double h = dict.getChecked<double>(
            "cellSize", [](const double& v) { return v > 0; }, "cellSize > 0");
        h_ = Vector::Constant(h);
    } else {
        h_ = dict.getChecked<Vector>(
            "cellSize", [](const Vector& v) { return (v.array() > 0).all(); },
            D == 2 ? "both cell sizes > 0" : "all three cell sizes > 0");
    }
    const auto n = dict.getChecked<std::vector<int>>(
        "nCells",
        [](const std::vector<int>& v) {
            return v.size() == std::size_t(D) && std::all_of(v.begin(), v.end(), [](int c) { return c > 0; });
        },
        D == 2 ? "two positive cell counts (nx ny)" : "three positive cell counts (nx ny nz)");
    std::copy(n.begin(), n.end(), n_.begin());
    checkMemory<D>(dict, n_);
    // x1 is the radius of a body of revolution: the grid may start on the axis, not across it.
    const std::string geometry = D == 2 ? dict.getWordOrDefault("geometry", {"planeStrain", "axisymmetric"}, "planeStrain")
                                        : dict.getWordOrDefault("geometry", {"threeD"}, "threeD");
    axisymmetric_ = geometry == "axisymmetric";
    if (axisymmetric_ && origin_.x() < 0) {
        std::ostringstream msg;
        msg << "keyword 'origin' in dictionary " << dict.name() << ": with geometry axisymmetric x1 is the radius "
            << "r >= 0, but the grid starts at r = " << origin_.x() << "; start it on the axis (origin (0 ...)) or beyond";
        dict.fail("origin", msg.str());
    }
    try {
        allocate();
    } catch (const RunError& e) {
        dict.fail("nCells", std::string("nCells: ") + e.what());
    }
}

template <int D>
Grid<D>::Grid(const Vector& origin, const Vector& cellSize, const Index& nCells) : origin_(origin), h_(cellSize), n_(nCells)
{
    allocate();
}

template <int D> void Grid<D>::allocate()
{
    long long count = 1;
    for (int a = 0; a < D; ++a) count *= n_[a] + 1;
    nNodes_ = static_cast<int>(count);
    for (int a = 0; a < D; ++a) upper_[a] = origin_[a] + n_[a] * h_[a];
    const auto n = static_cast<std::size_t>(nNodes_);
    try {
        mass.assign(n, 0.0);
        momentum.assign(n, Vector::Zero());
        velocity.assign(n, Vector::Zero());
        fInt.assign(n, Vector::Zero());
        fExt.assign(n, Vector::Zero());
        accel.assign(n, Vector::Zero());
        isActive_.assign(n, NodeMark::idle);
        active.reserve(n);
    } catch (const std::bad_alloc&) {
        // Beyond what this process may have (ulimit -v, a batch system's limit, other runs):
        // the machine's memory was checked already (checkMemory).
        const double need = double(n) * (sizeof(double) + 5 * sizeof(Vector) + sizeof(NodeMark) + sizeof(int));
        std::ostringstream msg;
        msg << "out of memory: the grid's node arrays (" << n << " nodes) need " << byteSize(need)
            << ", more than this process may have (ulimit -v)";
        throw RunError(msg.str());
    }
}

template <int D> void Grid<D>::resetFields()
{
    // Only nodes touched last step hold non-zero values. The arrays' pointers in locals:
    // Eigen's SSE stores may alias anything (doc/threading.md).
    const int* nodes = active.data();
    const long count = static_cast<long>(active.size());
    double* m = mass.data();
    Vector* fields[] = {momentum.data(), velocity.data(), fInt.data(), fExt.data(), accel.data()};
    Vector* contact = fContact.empty() ? nullptr : fContact.data();
    NodeMark* marks = isActive_.data();
#pragma omp parallel for schedule(static) if (count >= minParallelWork())
    for (long k = 0; k < count; ++k) {
        const int n = nodes[k];
        m[n] = 0.0;
        for (Vector* field : fields) field[n].setZero();
        if (contact) contact[n].setZero();
        marks[n] = NodeMark::idle;
    }
    active.clear();
}

template <int D> void Grid<D>::collectActive()
{
    active.clear();
    const int n = nNodes();
    for (int i = 0; i < n; ++i)
        if (isActive_[static_cast<std::size_t>(i)] == NodeMark::active) active.push_back(i);
}

template <int D> std::vector<int> Grid<D>::sideNodes(GridSide side) const
{
    const int axis = sideAxis(side);
    const int fixedIndex = lowSide(side) ? 0 : n_[axis];
    std::vector<int> nodes;
    const int n = nNodes();
    for (int k = 0; k < n; ++k)
        if (nodeIndex(k)[axis] == fixedIndex) nodes.push_back(k);
    return nodes;
}

template class Grid<2>;
#if GPIC_WITH_3D
template class Grid<3>;
#endif

} // namespace gpic
