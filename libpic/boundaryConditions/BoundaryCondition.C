#include "boundaryConditions/BoundaryCondition.H"

#include "dictionary/Dictionary.H"

namespace gpic {

GPIC_REGISTER_DIMS(BoundaryCondition, FixedBoundary, "fixed")
GPIC_REGISTER_DIMS(BoundaryCondition, SlipBoundary, "slip")
GPIC_REGISTER_DIMS(BoundaryCondition, SymmetryBoundary, "symmetry")
GPIC_REGISTER_DIMS(BoundaryCondition, FreeBoundary, "free")
GPIC_REGISTER_DIMS(BoundaryCondition, OutflowBoundary, "outflow")

template <int D> BoundaryCondition<D>::BoundaryCondition(const Dictionary& dict, GridSide side) : side_(side), opening_(dict) {}

template <int D>
void FixedBoundary<D>::constrain(std::vector<typename Space<D>::Vector>& field, const std::vector<int>& nodes) const
{
    for (int n : nodes) field[n].setZero();
}

template <int D>
void SlipBoundary<D>::constrain(std::vector<typename Space<D>::Vector>& field, const std::vector<int>& nodes) const
{
    const int axis = sideAxis(this->side());
    for (int n : nodes) field[n][axis] = 0.0;
}

template class BoundaryCondition<2>;
#if GPIC_WITH_3D
template class BoundaryCondition<3>;
#endif
template class FixedBoundary<2>;
#if GPIC_WITH_3D
template class FixedBoundary<3>;
#endif
template class SlipBoundary<2>;
#if GPIC_WITH_3D
template class SlipBoundary<3>;
#endif

} // namespace gpic
