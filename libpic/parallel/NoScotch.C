// A build without Scotch: method scotch is refused where decomposeParDict names it.
#include "parallel/Decomposition.H"

#include <stdexcept>

namespace gpic {

bool scotchAvailable() { return false; }

template <int D> std::vector<int> scotchPartition(const Grid<D>&, const std::vector<long>&, int)
{
    throw std::logic_error("scotchPartition: this build has no Scotch");
}

template std::vector<int> scotchPartition<2>(const Grid<2>&, const std::vector<long>&, int);
#if GPIC_WITH_3D
template std::vector<int> scotchPartition<3>(const Grid<3>&, const std::vector<long>&, int);
#endif

} // namespace gpic
