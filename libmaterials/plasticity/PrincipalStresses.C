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
    // The values in closed form; the axes by deflation, accurate near a double root too (the
    // edges of a Mohr-Coulomb pyramid, a body at rest with equal lateral stresses), where the
    // closed form's own axes lose accuracy as 1 / gap: the axis of the value farther from the
    // middle one (well separated from the other two) from S - l I, whose rows' largest cross
    // product it is, and the other two from the 2 x 2 problem in the plane normal to it.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(S, Eigen::EigenvaluesOnly);  // ascending
    const Eigen::Vector3d l = eigen.eigenvalues();
    if (!(l[2] - l[0] > 1e-12 * std::max(std::abs(l[0]), std::abs(l[2])))) {
        eigen.compute(S);  // isotropic to round-off: no axis stands out
        sigma_ = eigen.eigenvalues();
        axes_ = eigen.eigenvectors();
        return;
    }
    const bool lowPair = l[1] - l[0] < l[2] - l[1];  // the pair sigma1, sigma2; else sigma2, sigma3
    const int distinct = lowPair ? 2 : 0;
    const auto axisOf = [&S](double value) {
        const Eigen::Matrix3d T = S - value * Eigen::Matrix3d::Identity();
        const Eigen::Vector3d c01 = T.row(0).cross(T.row(1)), c02 = T.row(0).cross(T.row(2)),
                              c12 = T.row(1).cross(T.row(2));
        const double n01 = c01.squaredNorm(), n02 = c02.squaredNorm(), n12 = c12.squaredNorm();
        return Eigen::Vector3d((n01 >= n02 && n01 >= n12 ? c01 : n02 >= n12 ? c02 : c12).normalized());
    };
    const Eigen::Vector3d n = axisOf(l[distinct]);
    // An orthonormal pair (u, w) spanning the plane normal to n.
    const Eigen::Vector3d u =
        (std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY()).cross(n).normalized();
    const Eigen::Vector3d w = n.cross(u);
    const double a = u.dot(S * u), b = u.dot(S * w), d = w.dot(S * w);
    // The 2 x 2 symmetric problem [[a b] [b d]] in closed form, as the plane case: the mean,
    // the radius, and the major axis at angle theta in (u, w).
    const double mean = 0.5 * (a + d), half = 0.5 * (a - d), radius = std::sqrt(half * half + b * b);
    double ct = 1.0, st = 0.0;  // a round pair: any axes in the plane
    if (radius > 0.0) {
        if (half >= 0.0) {
            ct = std::sqrt(0.5 * (1.0 + half / radius));
            st = b / (2.0 * radius * ct);
        } else {
            st = std::copysign(std::sqrt(0.5 * (1.0 - half / radius)), b);
            ct = b / (2.0 * radius * st);
        }
    }
    const Eigen::Vector3d major = ct * u + st * w, minor = -st * u + ct * w;
    const double nValue = n.dot(S * n);
    if (lowPair) {  // ascending: the pair's smaller value on the minor axis
        sigma_ << mean - radius, mean + radius, nValue;
        axes_ << minor, major, n;
    } else {
        sigma_ << nValue, mean - radius, mean + radius;
        axes_ << n, minor, major;
    }
}

} // namespace gpic
