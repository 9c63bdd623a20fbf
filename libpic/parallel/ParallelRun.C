#include "parallel/ParallelRun.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "parallel/Decomposition.H"
#include "parallel/ParticlePacking.H"

#include <algorithm>
#include <numeric>
#include <cstdio>

namespace gpic {

template <int D>
ParallelRun<D>::ParallelRun(const Communicator& comm, const Grid<D>& grid, const std::string& caseDir, int reach)
    : comm_(comm), file_(caseDir + "/constant/cellDecomposition"),
      settings_(readDecomposeParDict(Dictionary::readFile(caseDir + "/system/decomposeParDict", "system/decomposeParDict"), D)),
      decomposition_(readCellDecomposition(file_, grid.nCells())), reach_(reach),
      shared_(std::make_unique<SharedNodes<D>>(grid, decomposition_.owner, comm.rank(), reach))
{
    if (decomposition_.subdomains != comm.size())
        throw InputError("constant/cellDecomposition", 0,
                         "the case is decomposed into " + std::to_string(decomposition_.subdomains) +
                             " subdomains, the run has " + std::to_string(comm.size()) +
                             " ranks: run mpirun -np " + std::to_string(decomposition_.subdomains) +
                             ", or picDecompose -force again");
}

namespace {

template <class T> double* values(std::vector<T>& field) { return reinterpret_cast<double*>(field.data()); }

} // namespace

template <int D> void ParallelRun<D>::complete(const Grid<D>& grid, double* field, int components) const
{
    shared_->complete(field, components, comm_, [&grid](int n) { return grid.isActive(n); });
    nodalBytes_ += static_cast<double>(shared_->sharedCount() * components * sizeof(double));
    ++exchanges_;
}

template <int D> void ParallelRun<D>::shareActiveNodes(Grid<D>& grid) const
{
    bool added = false;
    shared_->shareMarks([&grid](int n) { return grid.isActive(n); },
                        [&grid, &added](int n) { grid.markActive(n), added = true; }, comm_);
    nodalBytes_ += static_cast<double>(shared_->sharedCount());
    ++exchanges_;
    if (added) grid.collectActive();
}

template <int D> void ParallelRun<D>::complete(const Grid<D>& grid, std::vector<double>& field) const
{
    complete(grid, field.data(), 1);
}

template <int D>
void ParallelRun<D>::complete(const Grid<D>& grid, std::vector<typename Space<D>::Vector>& field) const
{
    complete(grid, values(field), D);
}

template <int D> void ParallelRun<D>::completeMax(const Grid<D>& grid, std::vector<int>& field) const
{
    shared_->completeMax(field.data(), comm_, [&grid](int n) { return grid.isActive(n); });
    nodalBytes_ += static_cast<double>(shared_->sharedCount() * sizeof(int));
    ++exchanges_;
}

template <int D> void ParallelRun<D>::completeMassAndMomentum(Grid<D>& grid, bool shareNodes) const
{
    if (shareNodes || shareAlways_) shareActiveNodes(grid);
    complete(grid, values(grid.mass), 1);
    complete(grid, values(grid.momentum), D);
}

template <int D> void ParallelRun<D>::completeMomentum(Grid<D>& grid) const
{
    complete(grid, values(grid.momentum), D);
}

template <int D> void ParallelRun<D>::completeForces(Grid<D>& grid) const
{
    complete(grid, values(grid.fInt), D);
    complete(grid, values(grid.fExt), D);
}

template <int D> std::vector<int> ParallelRun<D>::allPeers() const
{
    std::vector<int> peers;
    for (int r = 0; r < comm_.size(); ++r)
        if (r != comm_.rank()) peers.push_back(r);
    return peers;
}

template <int D> void ParallelRun<D>::place(MpmSolver<D>& solver, Particles<D>* dormant)
{
    handOver(solver, allPeers());
    if (!dormant) return;
    if (auto next = handOver(solver.grid(), *dormant, allPeers())) {
        std::vector<std::size_t> byId(next->size());
        std::iota(byId.begin(), byId.end(), std::size_t(0));
        std::stable_sort(byId.begin(), byId.end(), [&](std::size_t a, std::size_t b) { return next->id[a] < next->id[b]; });
        next->reorder(byId);
        *dormant = std::move(*next);
    }
}

template <int D> void ParallelRun<D>::handOver(MpmSolver<D>& solver, const std::vector<int>& peers)
{
    if (auto next = handOver(solver.grid(), solver.particles(), peers)) solver.replaceParticles(std::move(*next));
}

template <int D>
std::optional<Particles<D>> ParallelRun<D>::handOver(const Grid<D>& grid, const Particles<D>& p, const std::vector<int>& peers)
{
    std::vector<std::vector<std::size_t>> leaving(peers.size());
    std::vector<std::size_t> staying;
    staying.reserve(p.size());
    for (std::size_t q = 0; q < p.size(); ++q) {
        const int owner = decomposition_.owner[static_cast<std::size_t>(cellNumber(grid, grid.cellOf(p.x[q])))];
        if (owner == comm_.rank()) {
            staying.push_back(q);
            continue;
        }
        const auto k = std::lower_bound(peers.begin(), peers.end(), owner) - peers.begin();
        if (k == static_cast<long>(peers.size()) || peers[static_cast<std::size_t>(k)] != owner)
            throw RunError("particle " + std::to_string(p.id[q]) + " moved into the cells of rank " +
                           std::to_string(owner) + ", which is not a neighbour of rank " +
                           std::to_string(comm_.rank()) + ": more than a cell in one step");
        leaving[static_cast<std::size_t>(k)].push_back(q);
    }
    std::vector<std::vector<char>> send(peers.size());
    for (std::size_t k = 0; k < peers.size(); ++k) {
        send[k] = packParticles(p, leaving[k]);
        sent_ += static_cast<long>(leaving[k].size());
    }
    const auto arrived = comm_.exchange(peers, send);
    // A package of no particles is its header alone.
    const std::size_t header = packParticles(p, {}).size();
    if (staying.size() == p.size() &&
        std::all_of(arrived.begin(), arrived.end(), [header](const std::vector<char>& b) { return b.size() == header; }))
        return std::nullopt;  // nothing left or came: the particles stay as they are, in their order
    Particles<D> next = p;
    next.reorder(staying);
    for (const auto& bytes : arrived) received_ += static_cast<long>(unpackParticles(bytes, next));
    return next;
}

template <int D> std::string ParallelRun<D>::rebalance(MpmSolver<D>& solver, long step, Particles<D>* dormant)
{
    if (settings_.redecomposeInterval <= 0 || step % settings_.redecomposeInterval != 0) return "";
    const int ranks = comm_.size();
    const auto imbalance = [&](std::size_t here) {
        std::vector<double> count(static_cast<std::size_t>(ranks), 0.0);
        count[static_cast<std::size_t>(comm_.rank())] = static_cast<double>(here);
        comm_.sumInRankOrder(count);
        double total = 0, largest = 0;
        for (double c : count) total += c, largest = std::max(largest, c);
        return total > 0 ? largest * ranks / total : 1.0;
    };
    const double before = imbalance(solver.particles().size());
    if (!(before > settings_.maxImbalance)) return "";
    // The particles per cell over every rank, then the same decomposition on each.
    const Grid<D>& grid = solver.grid();
    std::vector<double> perCell(static_cast<std::size_t>(grid.nCells()), 0.0);
    for (const auto& x : solver.particles().x) perCell[static_cast<std::size_t>(cellNumber(grid, grid.cellOf(x)))] += 1;
    comm_.sumInRankOrder(perCell);
    const std::vector<int> counts(perCell.begin(), perCell.end());
    std::vector<int> owner = decomposeCells(grid, counts, settings_);
    if (owner == decomposition_.owner) return "";  // the cell layers allow no better split
    decomposition_.owner = std::move(owner);
    writeCellDecomposition(file_, decomposition_);
    shared_ = std::make_unique<SharedNodes<D>>(grid, decomposition_.owner, comm_.rank(), reach_);
    const long sentBefore = sent_;
    place(solver, dormant);
    std::vector<double> moved{static_cast<double>(sent_ - sentBefore)};
    comm_.sumInRankOrder(moved);
    const double after = imbalance(solver.particles().size());
    char line[200];
    std::snprintf(line, sizeof line, "decomposed again at step %ld: largest subdomain over the mean %.3f -> %.3f, %.0f particles moved",
                  step, before, after, moved[0]);
    return line;
}

template class ParallelRun<2>;
#if GPIC_WITH_3D
template class ParallelRun<3>;
#endif

} // namespace gpic
