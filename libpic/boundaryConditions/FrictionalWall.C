#include "boundaryConditions/FrictionalWall.H"

#include "dictionary/Dictionary.H"

#include <algorithm>
#include <cmath>

namespace gpic {

GPIC_REGISTER_DIMS(BoundaryCondition, FrictionalWall, "frictionalWall")

template <int D>
FrictionalWall<D>::FrictionalWall(const Dictionary& dict, GridSide side)
    : BoundaryCondition<D>(dict, side),
      mu_(dict.getChecked<double>("mu", [](const double& m) { return m >= 0; }, "mu >= 0"))
{}

template <int D> typename Space<D>::Vector FrictionalWall<D>::corrected(const Vector& v) const
{
    const Vector n = this->normal();
    const double vn = v.dot(n);
    if (vn <= 0.0) return v;  // at rest on the wall or moving away: no impulse
    const Vector vt = v - vn * n;
    const double speed = vt.norm();
    // Coulomb: the tangential change is at most mu times the normal one (G.2.18).
    const double slip = std::max(0.0, speed - mu_ * vn);
    return speed > 0.0 ? Vector((slip / speed) * vt) : Vector::Zero();
}

template <int D>
void FrictionalWall<D>::constrainUpdate(std::vector<Vector>& velocity, std::vector<Vector>& accel, double dt,
                                        const std::vector<int>& nodes) const
{
    for (int n : nodes) {
        const Vector v = corrected(velocity[n]);
        accel[n] += (v - velocity[n]) / dt;  // seed G.4.1: the particles see the same impulse
        velocity[n] = v;
    }
}

template class FrictionalWall<2>;
#if GPIC_WITH_3D
template class FrictionalWall<3>;
#endif

} // namespace gpic
