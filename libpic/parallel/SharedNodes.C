#include "parallel/SharedNodes.H"

#include "parallel/Decomposition.H"

#include <algorithm>
#include <cstring>
#include <map>
#include <stdexcept>

namespace gpic {

template <int D>
SharedNodes<D>::SharedNodes(const Grid<D>& grid, const std::vector<int>& cellOwner, int rank, int reach)
    : rank_(rank), reached_(static_cast<std::size_t>(grid.nNodes()), 0), nodeOwner_(static_cast<std::size_t>(grid.nNodes()))
{
    if (static_cast<int>(cellOwner.size()) != grid.nCells()) throw std::logic_error("SharedNodes: one owner per cell");
    std::map<int, std::vector<int>> byPeer;
    std::map<int, std::vector<int>> ranksOf;  // shared node -> every rank that reaches it
    std::vector<int> ranks;
    for (int n = 0; n < grid.nNodes(); ++n) {
        const auto i = grid.nodeIndex(n);
        typename Grid<D>::Index lo, hi, own;
        for (int a = 0; a < D; ++a) {
            lo[a] = std::max(i[a] - 1 - reach, 0);
            hi[a] = std::min(i[a] + reach, grid.cells(a) - 1);
            own[a] = std::min(i[a], grid.cells(a) - 1);
        }
        nodeOwner_[n] = cellOwner[cellNumber(grid, own)];
        ranks.clear();
        typename Grid<D>::Index c = lo;
        while (true) {
            ranks.push_back(cellOwner[cellNumber(grid, c)]);
            int a = 0;
            while (a < D && ++c[a] > hi[a]) c[a] = lo[a], ++a;
            if (a == D) break;
        }
        std::sort(ranks.begin(), ranks.end());
        ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
        if (!std::binary_search(ranks.begin(), ranks.end(), rank)) continue;
        reached_[n] = 1;
        if (ranks.size() == 1) continue;
        for (int r : ranks)
            if (r != rank) byPeer[r].push_back(n);
        ranksOf[n] = ranks;
    }
    for (auto& [peer, nodes] : byPeer) {
        peers_.push_back(peer);
        shared_.push_back(std::move(nodes));
    }
    for (const auto& [n, sharers] : ranksOf) {
        sharedNodes_.push_back(n);
        std::vector<Part> parts;
        for (int r : sharers) {
            if (r == rank) {
                parts.push_back({-1, 0});
                continue;
            }
            const auto k = static_cast<std::size_t>(std::lower_bound(peers_.begin(), peers_.end(), r) - peers_.begin());
            const auto& list = shared_[k];
            parts.push_back({static_cast<int>(k), static_cast<int>(std::lower_bound(list.begin(), list.end(), n) - list.begin())});
        }
        parts_.push_back(std::move(parts));
    }
}

template <int D> std::size_t SharedNodes<D>::sharedCount() const
{
    std::size_t count = 0;
    for (const auto& list : shared_) count += list.size();
    return count;
}

template <int D>
template <class T, class Add>
void SharedNodes<D>::combine(T* field, int components, const Communicator& comm, const std::function<bool(int)>& written,
                             Add add, T none) const
{
    const std::size_t width = static_cast<std::size_t>(components) * sizeof(T);
    // A node this rank did not write sends `none`: what a field holds there may be left from
    // an earlier step (XPIC's iterates are zeroed on the step's nodes only).
    const std::vector<T> nothing(static_cast<std::size_t>(components), none);
    std::vector<std::vector<char>> send(peers_.size());
    for (std::size_t k = 0; k < peers_.size(); ++k) {
        send[k].resize(shared_[k].size() * width);
        for (std::size_t m = 0; m < shared_[k].size(); ++m) {
            const int n = shared_[k][m];
            const T* value = written && !written(n) ? nothing.data() : field + static_cast<std::size_t>(n) * components;
            std::memcpy(send[k].data() + m * width, value, width);
        }
    }
    const auto received = comm.exchange(peers_, send);
    std::vector<T> own(static_cast<std::size_t>(components)), value(static_cast<std::size_t>(components));
    for (std::size_t s = 0; s < sharedNodes_.size(); ++s) {
        if (written && !written(sharedNodes_[s])) continue;
        T* node = field + static_cast<std::size_t>(sharedNodes_[s]) * components;
        std::copy(node, node + components, own.begin());
        bool first = true;
        for (const Part& part : parts_[s]) {
            const T* v = own.data();
            if (part.peer >= 0) {
                std::memcpy(value.data(), received[part.peer].data() + part.position * width, width);
                v = value.data();
            }
            for (int c = 0; c < components; ++c) node[c] = first ? v[c] : add(node[c], v[c]);
            first = false;
        }
    }
}

template <int D>
void SharedNodes<D>::complete(double* field, int components, const Communicator& comm,
                              const std::function<bool(int)>& written) const
{
    combine(field, components, comm, written, [](double a, double b) { return a + b; }, 0.0);
}

template <int D>
void SharedNodes<D>::completeMax(int* field, const Communicator& comm, const std::function<bool(int)>& written) const
{
    combine(field, 1, comm, written, [](int a, int b) { return std::max(a, b); }, -1);
}

template <int D>
void SharedNodes<D>::shareMarks(const std::function<bool(int)>& marked, const std::function<void(int)>& mark,
                                const Communicator& comm) const
{
    std::vector<std::vector<char>> send(peers_.size());
    for (std::size_t k = 0; k < peers_.size(); ++k)
        for (int n : shared_[k]) send[k].push_back(marked(n) ? 1 : 0);
    const auto received = comm.exchange(peers_, send);
    for (std::size_t s = 0; s < sharedNodes_.size(); ++s) {
        const int n = sharedNodes_[s];
        if (marked(n)) continue;
        for (const Part& part : parts_[s])
            if (part.peer >= 0 && received[part.peer][part.position] != 0) {
                mark(n);
                break;
            }
    }
}

template class SharedNodes<2>;
#if GPIC_WITH_3D
template class SharedNodes<3>;
#endif

} // namespace gpic
