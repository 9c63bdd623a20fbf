#include "planar/CosseratField.H"

namespace gpic {

void CosseratField::allocate(int nNodes)
{
    const auto n = static_cast<std::size_t>(nNodes);
    inertia.assign(n, 0.0);
    momentum.assign(n, 0.0);
    rate.assign(n, 0.0);
    moment.assign(n, 0.0);
    accel.assign(n, 0.0);
    fixed.assign(n, 0);
}

} // namespace gpic
