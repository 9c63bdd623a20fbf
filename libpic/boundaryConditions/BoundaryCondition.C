#include "boundaryConditions/BoundaryCondition.H"

namespace gpic {

GPIC_REGISTER(BoundaryCondition, FixedBoundary, "fixed")
GPIC_REGISTER(BoundaryCondition, SlipBoundary, "slip")
GPIC_REGISTER(BoundaryCondition, SymmetryBoundary, "symmetry")
GPIC_REGISTER(BoundaryCondition, FreeBoundary, "free")

Vector2 BoundaryCondition::normal() const
{
    switch (side_) {
    case GridSide::left: return Vector2(-1, 0);
    case GridSide::right: return Vector2(1, 0);
    case GridSide::bottom: return Vector2(0, -1);
    case GridSide::top: break;
    }
    return Vector2(0, 1);
}

void FixedBoundary::constrain(std::vector<Vector2>& field, const std::vector<int>& nodes) const
{
    for (int n : nodes) field[n].setZero();
}

void SlipBoundary::constrain(std::vector<Vector2>& field, const std::vector<int>& nodes) const
{
    const int axis = (side() == GridSide::left || side() == GridSide::right) ? 0 : 1;
    for (int n : nodes) field[n][axis] = 0.0;
}

} // namespace gpic
