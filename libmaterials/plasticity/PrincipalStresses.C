#include "plasticity/PrincipalStresses.H"

#include <utility>
#include <cmath>

namespace gpic {

PrincipalStresses::PrincipalStresses(const SymTensor& s)
{
    const double centre = 0.5 * (s[XX] + s[YY]);
    const double half = 0.5 * (s[XX] - s[YY]);
    double major, minor;
    if (s[XY] == 0.0) {
        // Already principal: keep the coordinate axes exactly.
        const bool xMajor = s[XX] >= s[YY];
        c_ = xMajor ? 1.0 : 0.0;
        s_ = xMajor ? 0.0 : 1.0;
        major = xMajor ? s[XX] : s[YY];
        minor = xMajor ? s[YY] : s[XX];
    } else {
        // Major-axis eigenvector of the in-plane 2x2 block, in whichever of its two forms
        // has no cancellation: (half + R, s12) when s11 >= s22, else (s12, R - half).
        // (sqrt rather than std::hypot: stresses are far from overflow, and hypot is slow.)
        const double radius = std::sqrt(half * half + s[XY] * s[XY]);  // Mohr circle radius
        const double vx = half >= 0 ? half + radius : s[XY];
        const double vy = half >= 0 ? s[XY] : radius - half;
        const double length = std::sqrt(vx * vx + vy * vy);
        c_ = vx / length;
        s_ = vy / length;
        major = centre + radius;
        minor = centre - radius;
    }
    // Sort three values (a stable exchange sort: equal values keep the axis order), in
    // registers and by selection, not by branches the data would mispredict.
    double v[3] = {major, minor, s[ZZ]};
    Axis a[3] = {majorInPlane, minorInPlane, outOfPlane};
    const auto order = [&v, &a](int i, int j) {
        const bool exchange = v[j] < v[i];
        const double vi = exchange ? v[j] : v[i], vj = exchange ? v[i] : v[j];
        const Axis ai = exchange ? a[j] : a[i], aj = exchange ? a[i] : a[j];
        v[i] = vi;
        v[j] = vj;
        a[i] = ai;
        a[j] = aj;
    };
    order(0, 1);
    order(1, 2);
    order(0, 1);
    sigma_ << v[0], v[1], v[2];
    axis_ = {a[0], a[1], a[2]};
    for (int i = 0; i < 3; ++i) position_[axis_[i]] = i;
}

} // namespace gpic
