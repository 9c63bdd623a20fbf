#include "boundaryConditions/FrictionalWall.H"

#include "dictionary/Dictionary.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER(BoundaryCondition, FrictionalWall, "frictionalWall")

FrictionalWall::FrictionalWall(const Dictionary& dict, GridSide side)
    : BoundaryCondition(dict, side),
      mu_(dict.getChecked<double>("mu", [](const double& m) { return m >= 0; }, "mu >= 0"))
{}

Vector2 FrictionalWall::corrected(const Vector2& v) const
{
    const Vector2 n = normal();
    const double vn = v.dot(n);
    if (vn <= 0.0) return v;  // at rest on the wall or moving away: no impulse
    const Vector2 vt = v - vn * n;
    const double speed = vt.norm();
    // Coulomb: the tangential change is at most mu times the normal one (G.2.18).
    const double slip = std::max(0.0, speed - mu_ * vn);
    return speed > 0.0 ? Vector2((slip / speed) * vt) : Vector2::Zero();
}

void FrictionalWall::constrainUpdate(std::vector<Vector2>& velocity, std::vector<Vector2>& accel,
                                     double dt, const std::vector<int>& nodes) const
{
    for (int n : nodes) {
        const Vector2 v = corrected(velocity[n]);
        accel[n] += (v - velocity[n]) / dt;  // seed G.4.1: the particles see the same impulse
        velocity[n] = v;
    }
}

} // namespace gpic
