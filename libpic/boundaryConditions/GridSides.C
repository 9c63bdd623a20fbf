#include "boundaryConditions/GridSides.H"

#include <cmath>

namespace gpic {

GridSides::GridSides(Conditions conditions, const Grid& grid) : conditions_(std::move(conditions))
{
    refresh(grid);
}

void GridSides::refresh(const Grid& grid)
{
    // An open stretch's nodes are left free, a closed one is a wall.
    hasOutlet_ = false;
    for (int s = 0; s < count; ++s) {
        const BoundaryCondition& bc = *conditions_[s];
        nodes_[s].clear();
        for (int n : grid.sideNodes(static_cast<GridSide>(s)))
            if (bc.isOpen(bc.along(grid.nodePosition(n)))) hasOutlet_ = true;
            else nodes_[s].push_back(n);
        hasOutlet_ = hasOutlet_ || bc.letsOut();
    }
}

void GridSides::constrain(std::vector<Vector2>& velocity) const
{
    for (int s = 0; s < count; ++s) conditions_[s]->constrain(velocity, nodes_[s]);
}

void GridSides::constrainUpdate(std::vector<Vector2>& velocity, std::vector<Vector2>& accel, double dt) const
{
    for (int s = 0; s < count; ++s) conditions_[s]->constrainUpdate(velocity, accel, dt, nodes_[s]);
}

bool GridSides::leftThroughOpening(const Grid& grid, const Vector2& x) const
{
    const Vector2 low = grid.origin(), high = grid.upper();
    // The cell a particle leaves through moves freely where one of its nodes on the side is
    // open: the stretch of the opening widens by a cell on each side.
    const auto open = [&](GridSide side) {
        const BoundaryCondition& bc = condition(side);
        const double s = bc.along(x);
        const double h = side == GridSide::left || side == GridSide::right ? grid.cellSize().y() : grid.cellSize().x();
        return bc.isOpen(s) || bc.isOpen(s - h) || bc.isOpen(s + h);
    };
    return (x.x() < low.x() && open(GridSide::left)) || (x.x() > high.x() && open(GridSide::right)) ||
           (x.y() < low.y() && open(GridSide::bottom)) || (x.y() > high.y() && open(GridSide::top));
}

bool GridSides::keepInsideWalls(const Grid& grid, Vector2& x, Vector2& v) const
{
    if (!std::isfinite(x.x()) || !std::isfinite(x.y())) return false;
    if (hasOutlet_ && leftThroughOpening(grid, x)) return false;  // the outflow takes it
    const Vector2 low = grid.origin(), high = grid.upper(), h = grid.cellSize();
    bool moved = false;
    for (int s = 0; s < count; ++s) {
        const BoundaryCondition& bc = *conditions_[s];
        const int axis = s == static_cast<int>(GridSide::left) || s == static_cast<int>(GridSide::right) ? 0 : 1;
        const bool lowSide = s == static_cast<int>(GridSide::left) || s == static_cast<int>(GridSide::bottom);
        const double side = lowSide ? low[axis] : high[axis];
        const double past = lowSide ? side - x[axis] : x[axis] - side;
        // Only a small overshoot through a closed wall: anything larger is left for the
        // stability guard to report, and an open stretch lets the particle go.
        if (!(past > 0.0) || past > 0.5 * h[axis] || !bc.isWall()) continue;
        x[axis] = side;
        if (lowSide ? v[axis] < 0.0 : v[axis] > 0.0) v[axis] = 0.0;
        moved = true;
    }
    return moved;
}

} // namespace gpic
