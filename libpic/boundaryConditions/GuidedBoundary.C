#include "boundaryConditions/GuidedBoundary.H"

namespace gpic {

GPIC_REGISTER(BoundaryCondition, GuidedBoundary, "guided")

void GuidedBoundary::constrain(std::vector<Vector2>& field, const std::vector<int>& nodes) const
{
    // The component along the side: x2 on left and right, x1 on bottom and top.
    const int axis = (side() == GridSide::left || side() == GridSide::right) ? 1 : 0;
    for (int n : nodes) field[n][axis] = 0.0;
}

} // namespace gpic
