#include "plasticity/PrincipalStresses.H"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <utility>

namespace gpic {

PrincipalStresses<2>::PrincipalStresses(const Space<2>::SymTensor& s)
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

PrincipalStresses<3>::PrincipalStresses(const Space<3>::SymTensor& s)
{
    if (s[XY] == 0.0 && s[YZ] == 0.0 && s[XZ] == 0.0) {
        // Already principal: keep the coordinate axes exactly, equal values in axis order.
        std::array<int, 3> order{0, 1, 2};
        const auto exchange = [&](int i, int j) {
            if (s[order[j]] < s[order[i]]) std::swap(order[i], order[j]);
        };
        exchange(0, 1);
        exchange(1, 2);
        exchange(0, 1);
        axes_.setZero();
        for (int i = 0; i < 3; ++i) {
            sigma_[i] = s[order[i]];
            axes_(order[i], i) = 1.0;
        }
        return;
    }
    Eigen::Matrix3d S;
    S << s[XX], s[XY], s[XZ], s[XY], s[YY], s[YZ], s[XZ], s[YZ], s[ZZ];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(S);  // ascending values, orthonormal vectors
    // The closed form loses accuracy near a double root (to about 1e-8 of the stress: the
    // edges of a Mohr-Coulomb pyramid, an oedometer's equal lateral stresses), where the
    // iterative solver keeps it to round-off; it costs a few times more, so only there.
    const Eigen::Vector3d& l = eigen.eigenvalues();
    const double near = 1e-4 * std::max(std::abs(l[0]), std::abs(l[2]));
    if (l[1] - l[0] <= near || l[2] - l[1] <= near) eigen.compute(S);
    sigma_ = eigen.eigenvalues();
    axes_ = eigen.eigenvectors();
}

} // namespace gpic
