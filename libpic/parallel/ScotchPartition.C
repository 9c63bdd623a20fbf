// The cells' graph partition by Scotch 7 (Debian's libscotch-dev): compiled only where the
// build found it (libpic/CMakeLists.txt), else scotchAvailable() is false.
#include "parallel/Decomposition.H"

#include "core/error.H"

#include <cstdint>
#include <cstdio>
#include <string>
// scotch.h uses FILE and the fixed-width integers without including their headers.
#include <scotch.h>

namespace gpic {

bool scotchAvailable() { return true; }

template <int D>
std::vector<int> scotchPartition(const Grid<D>& grid, const std::vector<long>& load, int parts)
{
    // The graph: a vertex per cell, an edge to each face neighbour (compressed rows).
    const int nCells = grid.nCells();
    std::vector<SCOTCH_Num> vertices(static_cast<std::size_t>(nCells) + 1), edges, loads(load.begin(), load.end());
    edges.reserve(static_cast<std::size_t>(2 * D) * nCells);
    std::array<int, D> stride{};
    stride[0] = 1;
    for (int a = 1; a < D; ++a) stride[a] = stride[a - 1] * grid.cells(a - 1);
    for (int c = 0; c < nCells; ++c) {
        vertices[c] = static_cast<SCOTCH_Num>(edges.size());
        int rest = c;
        for (int a = 0; a < D; ++a) {
            const int i = rest % grid.cells(a);
            rest /= grid.cells(a);
            if (i > 0) edges.push_back(c - stride[a]);
            if (i + 1 < grid.cells(a)) edges.push_back(c + stride[a]);
        }
    }
    vertices[nCells] = static_cast<SCOTCH_Num>(edges.size());
    SCOTCH_Graph graph, bound;
    SCOTCH_Strat strategy;
    SCOTCH_Context context;
    if (SCOTCH_graphInit(&graph) != 0 || SCOTCH_graphInit(&bound) != 0 || SCOTCH_contextInit(&context) != 0)
        throw RunError("Scotch: cannot set up a graph");
    SCOTCH_stratInit(&strategy);
    // Debian's Scotch partitions with threads: a context that asks for the same result on
    // every run (a fixed seed, a deterministic order of the threads' work).
    SCOTCH_contextOptionSetNum(&context, SCOTCH_OPTIONNUMDETERMINISTIC, 1);
    SCOTCH_contextOptionSetNum(&context, SCOTCH_OPTIONNUMRANDOMFIXEDSEED, 1);
    SCOTCH_contextRandomClone(&context);
    std::vector<SCOTCH_Num> part(static_cast<std::size_t>(nCells));
    const bool ok = SCOTCH_graphBuild(&graph, 0, nCells, vertices.data(), vertices.data() + 1, loads.data(), nullptr,
                                      static_cast<SCOTCH_Num>(edges.size()), edges.data(), nullptr) == 0 &&
                    SCOTCH_graphCheck(&graph) == 0 && SCOTCH_contextBindGraph(&context, &graph, &bound) == 0 &&
                    SCOTCH_graphPart(&bound, parts, &strategy, part.data()) == 0;
    SCOTCH_stratExit(&strategy);
    SCOTCH_graphExit(&bound);
    SCOTCH_contextExit(&context);
    SCOTCH_graphExit(&graph);
    if (!ok) throw RunError("Scotch could not partition the " + std::to_string(nCells) + " cells into " +
                            std::to_string(parts) + " subdomains");
    return std::vector<int>(part.begin(), part.end());
}

template std::vector<int> scotchPartition<2>(const Grid<2>&, const std::vector<long>&, int);
#if GPIC_WITH_3D
template std::vector<int> scotchPartition<3>(const Grid<3>&, const std::vector<long>&, int);
#endif

} // namespace gpic
