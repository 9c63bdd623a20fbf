#include "boundaryConditions/GuidedBoundary.H"

namespace gpic {

GPIC_REGISTER_DIMS(BoundaryCondition, GuidedBoundary, "guided")

template <int D>
void GuidedBoundary<D>::constrain(std::vector<typename Space<D>::Vector>& field, const std::vector<int>& nodes) const
{
    // The components along the side: every axis but its normal one.
    const int normal = sideAxis(this->side());
    for (int n : nodes)
        for (int a = 0; a < D; ++a)
            if (a != normal) field[n][a] = 0.0;
}

template class GuidedBoundary<2>;
#if GPIC_WITH_3D
template class GuidedBoundary<3>;
#endif

} // namespace gpic
