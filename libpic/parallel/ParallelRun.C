#include "parallel/ParallelRun.H"

#include "core/error.H"
#include "parallel/Decomposition.H"
#include "parallel/ParticlePacking.H"

#include <algorithm>

namespace gpic {

template <int D>
ParallelRun<D>::ParallelRun(const Communicator& comm, const Grid<D>& grid, CellDecomposition decomposition, int reach)
    : comm_(comm), decomposition_(std::move(decomposition)),
      shared_(grid, decomposition_.owner, comm.rank(), reach)
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

template <int D> void ParallelRun<D>::complete(Grid<D>& grid, double* field, int components) const
{
    shared_.complete(field, components, comm_, [&grid](int n) { return grid.isActive(n); });
    nodalBytes_ += static_cast<double>(shared_.sharedCount() * components * sizeof(double));
    ++exchanges_;
}

template <int D> void ParallelRun<D>::completeMassAndMomentum(Grid<D>& grid) const
{
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

template <int D> bool ParallelRun<D>::migrate(MpmSolver<D>& solver)
{
    const Grid<D>& grid = solver.grid();
    const Particles<D>& p = solver.particles();
    const auto& peers = shared_.peers();
    std::vector<std::vector<std::size_t>> leaving(peers.size());
    std::vector<std::size_t> staying;
    staying.reserve(p.size());
    for (std::size_t q = 0; q < p.size(); ++q) {
        const int owner = decomposition_.owner[static_cast<std::size_t>(cellNumber(grid, grid.cellOf(p.x[q])))];
        if (owner == comm_.rank()) {
            staying.push_back(q);
            continue;
        }
        // A particle moves less than a cell in a step (the Courant limit): into a neighbour's cells.
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
    if (staying.size() == p.size() &&
        std::all_of(arrived.begin(), arrived.end(), [](const std::vector<char>& b) { return b.size() <= 16; }))
        return false;  // nothing left or came: the particles stay as they are, in their order
    Particles<D> next = p;
    next.reorder(staying);
    for (const auto& bytes : arrived) received_ += static_cast<long>(unpackParticles(bytes, next));
    solver.replaceParticles(std::move(next));
    return true;
}

template class ParallelRun<2>;
#if GPIC_WITH_3D
template class ParallelRun<3>;
#endif

} // namespace gpic
