#include "boundaryConditions/GridSides.H"

#include <cmath>

namespace gpic {

template <int D> GridSides<D>::GridSides(Conditions conditions, const Grid<D>& grid) : conditions_(std::move(conditions))
{
    refresh(grid);
}

template <int D> void GridSides<D>::refresh(const Grid<D>& grid)
{
    // An open stretch's nodes are left free, a closed one is a wall.
    hasOutlet_ = false;
    for (int s = 0; s < count; ++s) {
        const BoundaryCondition<D>& bc = *conditions_[s];
        nodes_[s].clear();
        for (int n : grid.sideNodes(static_cast<GridSide>(s)))
            if (bc.isOpen(bc.along(grid.nodePosition(n)))) hasOutlet_ = true;
            else nodes_[s].push_back(n);
        hasOutlet_ = hasOutlet_ || bc.letsOut();
    }
}

template <int D> void GridSides<D>::constrain(std::vector<Vector>& velocity) const
{
    for (int s = 0; s < count; ++s) conditions_[s]->constrain(velocity, nodes_[s]);
}

template <int D> void GridSides<D>::constrainUpdate(std::vector<Vector>& velocity, std::vector<Vector>& accel, double dt) const
{
    for (int s = 0; s < count; ++s) conditions_[s]->constrainUpdate(velocity, accel, dt, nodes_[s]);
}

template <int D> bool GridSides<D>::leftThroughOpening(const Grid<D>& grid, const Vector& x) const
{
    const Vector low = grid.origin(), high = grid.upper();
    // The cell a particle leaves through moves freely where one of its nodes on the side is
    // open: the opening widens by a cell each way along the side.
    const auto open = [&](GridSide side) {
        const BoundaryCondition<D>& bc = condition(side);
        const typename BoundaryCondition<D>::FacePoint s = bc.along(x), h = bc.along(grid.cellSize());
        if (bc.isOpen(s)) return true;
        for (int shift = 1; shift < (D == 2 ? 3 : 9); ++shift) {  // the neighbours s + (i, j) h, i, j in {-1, 0, 1}
            typename BoundaryCondition<D>::FacePoint t = s;
            for (int a = 0, code = shift; a < D - 1; ++a, code /= 3) t[a] += (code % 3 == 1 ? -h[a] : code % 3 == 2 ? h[a] : 0.0);
            if (bc.isOpen(t)) return true;
        }
        return false;
    };
    for (int s = 0; s < count; ++s) {
        const auto side = static_cast<GridSide>(s);
        const int axis = sideAxis(side);
        if ((lowSide(side) ? x[axis] < low[axis] : x[axis] > high[axis]) && open(side)) return true;
    }
    return false;
}

template <int D> bool GridSides<D>::keepInsideWalls(const Grid<D>& grid, Vector& x, Vector& v) const
{
    if (!x.allFinite()) return false;
    if (hasOutlet_ && leftThroughOpening(grid, x)) return false;  // the outflow takes it
    const Vector low = grid.origin(), high = grid.upper(), h = grid.cellSize();
    bool moved = false;
    for (int s = 0; s < count; ++s) {
        const BoundaryCondition<D>& bc = *conditions_[s];
        const int axis = sideAxis(static_cast<GridSide>(s));
        const bool isLow = lowSide(static_cast<GridSide>(s));
        const double side = isLow ? low[axis] : high[axis];
        const double past = isLow ? side - x[axis] : x[axis] - side;
        // Only a small overshoot through a closed wall: anything larger is left for the
        // stability guard to report, and an open stretch lets the particle go.
        if (!(past > 0.0) || past > 0.5 * h[axis] || !bc.isWall()) continue;
        x[axis] = side;
        if (isLow ? v[axis] < 0.0 : v[axis] > 0.0) v[axis] = 0.0;
        moved = true;
    }
    return moved;
}

template class GridSides<2>;
#if GPIC_WITH_3D
template class GridSides<3>;
#endif

} // namespace gpic
