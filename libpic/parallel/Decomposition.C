#include "parallel/Decomposition.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <numeric>

namespace gpic {

namespace {

//- `n (2 2)` of a coefficients dictionary: one count >= 1 per axis, their product the
//  number of subdomains.
std::array<int, 3> readCounts(const Dictionary& coeffs, int dimension, int subdomains)
{
    const auto n = coeffs.get<std::vector<int>>("n");
    if (static_cast<int>(n.size()) != dimension)
        coeffs.fail("n", "keyword 'n' in " + coeffs.name() + ": expected " + std::to_string(dimension) + " counts, one per axis of the grid, got " +
                             std::to_string(n.size()));
    std::array<int, 3> counts{1, 1, 1};
    long product = 1;
    for (int a = 0; a < dimension; ++a) {
        if (n[a] < 1) coeffs.fail("n", "keyword 'n' in " + coeffs.name() + ": every count must be >= 1");
        counts[a] = n[a];
        product *= n[a];
    }
    if (product != subdomains)
        coeffs.fail("n", "keyword 'n' in " + coeffs.name() + ": the counts multiply to " + std::to_string(product) + ", not numberOfSubdomains " +
                             std::to_string(subdomains));
    return counts;
}

//- `order xyz`: each axis of the grid once.
std::array<int, 3> readOrder(const Dictionary& coeffs, int dimension)
{
    const std::string deflt = dimension == 2 ? "xy" : "xyz";
    const std::string order = coeffs.getOrDefault<std::string>("order", deflt);
    std::array<int, 3> axes{0, 1, 2};
    std::array<bool, 3> seen{false, false, false};
    bool valid = static_cast<int>(order.size()) == dimension;
    for (int k = 0; valid && k < dimension; ++k) {
        const int a = order[k] - 'x';
        valid = a >= 0 && a < dimension && !seen[a];
        if (valid) seen[a] = true, axes[k] = a;
    }
    if (!valid)
        coeffs.fail("order", "keyword 'order' in " + coeffs.name() + ": expected each of the axes " + deflt + " once, in the order they are cut, got '" +
                                 order + "'");
    return axes;
}

//- Cuts of the layers [lo, hi) into `pieces` runs of about equal weight (each at least one
//  layer): the first layer of each run after the first.
std::vector<int> balancedCuts(const std::vector<double>& layerWeight, int lo, int hi, int pieces)
{
    double total = 0;
    for (int i = lo; i < hi; ++i) total += layerWeight[i];
    std::vector<int> cuts;
    double before = 0;
    int i = lo;
    for (int k = 1; k < pieces; ++k) {
        const int least = (cuts.empty() ? lo : cuts.back()) + 1;
        const int most = hi - (pieces - k);
        int cut;
        if (total <= 0) {
            cut = lo + static_cast<int>(static_cast<long>(hi - lo) * k / pieces);
        } else {
            // The layer boundary nearest to the share k / pieces of the weight.
            const double target = total * k / pieces;
            while (i < hi && before + layerWeight[i] < target) before += layerWeight[i++];
            cut = (i < hi && target - before > before + layerWeight[i] - target) ? i + 1 : i;
        }
        cuts.push_back(std::clamp(cut, least, most));
    }
    return cuts;
}

template <int D> struct Box {
    std::array<int, D> lo, hi;   //- cell index ranges [lo, hi)
    std::array<int, D> piece{};  //- the piece's index along each axis cut so far
};

} // namespace

DecompositionSettings readDecomposeParDict(const Dictionary& dict, int dimension)
{
    DecompositionSettings s;
    s.subdomains = dict.getChecked<int>("numberOfSubdomains", [](int n) { return n >= 1; }, "numberOfSubdomains >= 1");
    const std::string method = dict.getWord("method", {"simple", "hierarchical", "scotch"});
    s.byParticles = dict.getWordOrDefault("weights", {"particles", "cells"}, "particles") == "particles";
    if (dict.found("redecomposeInterval"))
        s.redecomposeInterval = dict.getChecked<long>("redecomposeInterval", [](long n) { return n >= 0; },
                                                      "redecomposeInterval >= 0 (steps; 0: never)");
    if (dict.found("maxImbalance"))
        s.maxImbalance = dict.getChecked<double>("maxImbalance", [](double r) { return r > 1; }, "maxImbalance > 1");
    if (method == "simple") {
        s.method = DecompositionSettings::Method::simple;
        s.n = readCounts(dict.subDict("simpleCoeffs"), dimension, s.subdomains);
    } else if (method == "hierarchical") {
        s.method = DecompositionSettings::Method::hierarchical;
        const Dictionary& coeffs = dict.subDict("hierarchicalCoeffs");
        s.n = readCounts(coeffs, dimension, s.subdomains);
        s.order = readOrder(coeffs, dimension);
    } else {
        if (!scotchAvailable())
            dict.fail("method", "method scotch: this build has no Scotch (libscotch-dev was not found when it was configured): "
                                "use simple or hierarchical");
        s.method = DecompositionSettings::Method::scotch;
    }
    return s;
}

template <int D>
std::vector<int> decomposeCells(const Grid<D>& grid, const std::vector<int>& particlesPerCell,
                                const DecompositionSettings& s)
{
    const int nCells = grid.nCells();
    if (static_cast<int>(particlesPerCell.size()) != nCells)
        throw std::logic_error("decomposeCells: one particle count per cell expected");
    std::vector<double> weight(static_cast<std::size_t>(nCells), 1.0);
    if (s.byParticles)
        for (int c = 0; c < nCells; ++c) weight[c] = particlesPerCell[c];
    if (s.method == DecompositionSettings::Method::scotch) {
        // Scotch balances positive integer loads: an empty cell weighs 1, a particle 64, so
        // that the particles are what is balanced and the empty cells still go somewhere.
        std::vector<long> load(static_cast<std::size_t>(nCells));
        for (int c = 0; c < nCells; ++c) load[c] = 1 + (s.byParticles ? 64L * particlesPerCell[c] : 0L);
        return s.subdomains == 1 ? std::vector<int>(nCells, 0) : scotchPartition(grid, load, s.subdomains);
    }
    for (int a = 0; a < D; ++a)
        if (s.n[a] > grid.cells(a))
            throw InputError("system/decomposeParDict", 0,
                             std::to_string(s.n[a]) + " subdomains along axis " + std::string(1, char('x' + a)) +
                                 " of a grid of " + std::to_string(grid.cells(a)) + " cells: at most one per cell layer");
    // Each cell's piece index along each axis; the owner numbers them x fastest.
    std::vector<std::array<int, D>> piece(static_cast<std::size_t>(nCells));
    auto forEachCell = [&](const std::array<int, D>& lo, const std::array<int, D>& hi, auto&& f) {
        std::array<int, D> c = lo;
        if constexpr (D == 2) {
            for (c[1] = lo[1]; c[1] < hi[1]; ++c[1])
                for (c[0] = lo[0]; c[0] < hi[0]; ++c[0]) f(c);
        } else {
            for (c[2] = lo[2]; c[2] < hi[2]; ++c[2])
                for (c[1] = lo[1]; c[1] < hi[1]; ++c[1])
                    for (c[0] = lo[0]; c[0] < hi[0]; ++c[0]) f(c);
        }
    };
    std::array<int, D> all{};
    for (int a = 0; a < D; ++a) all[a] = grid.cells(a);
    if (s.method == DecompositionSettings::Method::simple) {
        forEachCell({}, all, [&](const std::array<int, D>& c) {
            auto& p = piece[cellNumber(grid, c)];
            for (int a = 0; a < D; ++a)
                p[a] = static_cast<int>(static_cast<long>(c[a]) * s.n[a] / grid.cells(a));
        });
    } else {
        // hierarchical: every box of the previous axis cut along the next, by weight.
        std::vector<Box<D>> boxes{Box<D>{{}, all, {}}};
        for (int k = 0; k < D; ++k) {
            const int a = s.order[k];
            std::vector<Box<D>> next;
            for (const Box<D>& box : boxes) {
                std::vector<double> layer(static_cast<std::size_t>(grid.cells(a)), 0.0);
                forEachCell(box.lo, box.hi, [&](const std::array<int, D>& c) { layer[c[a]] += weight[cellNumber(grid, c)]; });
                std::vector<int> edges{box.lo[a]};
                for (int cut : balancedCuts(layer, box.lo[a], box.hi[a], s.n[a])) edges.push_back(cut);
                edges.push_back(box.hi[a]);
                for (int m = 0; m < s.n[a]; ++m) {
                    Box<D> part = box;
                    part.lo[a] = edges[m];
                    part.hi[a] = edges[m + 1];
                    part.piece[a] = m;
                    next.push_back(part);
                }
            }
            boxes = std::move(next);
        }
        for (const Box<D>& box : boxes)
            forEachCell(box.lo, box.hi, [&](const std::array<int, D>& c) { piece[cellNumber(grid, c)] = box.piece; });
    }
    std::vector<int> owner(static_cast<std::size_t>(nCells));
    for (int c = 0; c < nCells; ++c) {
        int o = piece[c][D - 1];
        for (int a = D - 2; a >= 0; --a) o = piece[c][a] + s.n[a] * o;
        owner[c] = o;
    }
    return owner;
}

template std::vector<int> decomposeCells<2>(const Grid<2>&, const std::vector<int>&, const DecompositionSettings&);
#if GPIC_WITH_3D
template std::vector<int> decomposeCells<3>(const Grid<3>&, const std::vector<int>&, const DecompositionSettings&);
#endif

} // namespace gpic
