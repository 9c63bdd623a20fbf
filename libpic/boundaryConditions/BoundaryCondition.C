#include "boundaryConditions/BoundaryCondition.H"

#include "dictionary/Dictionary.H"

namespace gpic {

GPIC_REGISTER(BoundaryCondition, FixedBoundary, "fixed")
GPIC_REGISTER(BoundaryCondition, SlipBoundary, "slip")
GPIC_REGISTER(BoundaryCondition, SymmetryBoundary, "symmetry")
GPIC_REGISTER(BoundaryCondition, FreeBoundary, "free")
GPIC_REGISTER(BoundaryCondition, OutflowBoundary, "outflow")

BoundaryCondition::BoundaryCondition(const Dictionary& dict, GridSide side) : side_(side)
{
    if (!dict.found("opening")) return;
    const auto ab = dict.getChecked<std::vector<double>>(
        "opening", [](const std::vector<double>& v) { return v.size() == 2 && v[0] < v[1]; },
        "two coordinates along the side (a b) with a < b");
    hasOpening_ = true;
    opening_[0] = ab[0];
    opening_[1] = ab[1];
}

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
