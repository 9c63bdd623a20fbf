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

namespace {

//- cos(acos(x)/3) on [0, 1] (the largest root of the depressed cubic as a share of its
//  bound), least-squares quartic, within 1e-5: a start from which two Newton steps reach
//  round-off (the error squares, times at most 1.5, each step).
inline double cosThirdOfArcCos(double x)
{
    return 0.8660344308373332 +
           x * (0.16637630239747223 + x * (-0.04585719330771227 + x * (0.01750433351833614 + x * -0.00406467435786341)));
}

} // namespace

PrincipalStresses<3>::PrincipalStresses(const Space<3>::SymTensor& s)
{
    compute(&s, 1, this);
}

void PrincipalStresses<3>::special(const Space<3>::SymTensor& s)
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
    // Isotropic to round-off (or not finite): no axis stands out.
    Eigen::Matrix3d S;
    S << s[XX], s[XY], s[XZ], s[XY], s[YY], s[YZ], s[XZ], s[YZ], s[ZZ];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(S);
    sigma_ = eigen.eigenvalues();
    axes_ = eigen.eigenvectors();
}

void PrincipalStresses<3>::compute(const Space<3>::SymTensor* s, std::size_t n, PrincipalStresses<3>* out)
{
    // Each stage runs over every point before the next: a point's stages are one long chain
    // of square roots and divisions, and the chains of different points then overlap.
    constexpr std::size_t N = batch;
    for (std::size_t b = 0; b < n; b += N) {
        const std::size_t m = std::min(N, n - b);
        const Space<3>::SymTensor* sb = s + b;
        PrincipalStresses<3>* ob = out + b;
        double p[N], dxx[N], dyy[N], dzz[N], dxy[N], dyz[N], dxz[N], J2[N], lt[N];
        bool general[N];
        // The deviator d = sigma - p I and its invariants: its values are the roots of
        // t^3 - J2 t - J3 = 0. The value farthest from the middle one is the largest when
        // J3 >= 0 (the other two are then both negative, at least its size away) and the
        // smallest otherwise: a simple root, well apart from the pair. Its size t is the
        // largest root of t^3 - J2 t - |J3|, in closed form 2 r cos(acos(x)/3) with
        // r = sqrt(J2/3), x = |J3| / (2 r^3) in [0, 1]: here from a polynomial start and two
        // Newton steps instead of an arc cosine and a cosine.
        for (std::size_t i = 0; i < m; ++i) {
            const Space<3>::SymTensor& t = sb[i];
            p[i] = (t[XX] + t[YY] + t[ZZ]) / 3.0;
            dxx[i] = t[XX] - p[i];
            dyy[i] = t[YY] - p[i];
            dzz[i] = t[ZZ] - p[i];
            dxy[i] = t[XY];
            dyz[i] = t[YZ];
            dxz[i] = t[XZ];
            J2[i] = 0.5 * (dxx[i] * dxx[i] + dyy[i] * dyy[i] + dzz[i] * dzz[i]) + dxy[i] * dxy[i] +
                    dyz[i] * dyz[i] + dxz[i] * dxz[i];
        }
        for (std::size_t i = 0; i < m; ++i) {
            const double J3 = dxx[i] * (dyy[i] * dzz[i] - dyz[i] * dyz[i]) - dxy[i] * (dxy[i] * dzz[i] - dyz[i] * dxz[i]) +
                              dxz[i] * (dxy[i] * dyz[i] - dyy[i] * dxz[i]);
            const double r = std::sqrt(J2[i] / 3.0);  // the roots lie in [-2r, 2r]
            // A diagonal stress keeps its axes exactly; an isotropic one to round-off has none.
            general[i] = !(dxy[i] == 0.0 && dyz[i] == 0.0 && dxz[i] == 0.0) && r > 1e-13 * std::abs(p[i]);
            const double rr = general[i] ? r : 1.0, q = std::abs(J3);
            double t = 2.0 * rr * cosThirdOfArcCos(std::min(q / (2.0 * rr * rr * rr), 1.0));
            const double j2 = general[i] ? J2[i] : 1.0;
            for (int k = 0; k < 2; ++k) t -= (t * (t * t - j2) - q) / (3.0 * t * t - j2);
            lt[i] = J3 >= 0.0 ? t : -t;
        }
        for (std::size_t i = 0; i < m; ++i) {
            // The axis of lt: the largest cross product of two rows of d - lt I (rank 2).
            const double r0x = dxx[i] - lt[i], r1y = dyy[i] - lt[i], r2z = dzz[i] - lt[i];
            const double xy = dxy[i], yz = dyz[i], xz = dxz[i];
            const double c01x = xy * yz - xz * r1y, c01y = xz * xy - r0x * yz, c01z = r0x * r1y - xy * xy;
            const double c02x = xy * r2z - xz * yz, c02y = xz * xz - r0x * r2z, c02z = r0x * yz - xy * xz;
            const double c12x = r1y * r2z - yz * yz, c12y = yz * xz - xy * r2z, c12z = xy * yz - r1y * xz;
            const double n01 = c01x * c01x + c01y * c01y + c01z * c01z,
                         n02 = c02x * c02x + c02y * c02y + c02z * c02z,
                         n12 = c12x * c12x + c12y * c12y + c12z * c12z;
            const bool first = n01 >= n02 && n01 >= n12, second = !first && n02 >= n12;
            const double cx = first ? c01x : second ? c02x : c12x, cy = first ? c01y : second ? c02y : c12y,
                         cz = first ? c01z : second ? c02z : c12z, nn = first ? n01 : second ? n02 : n12;
            const double inverse = 1.0 / std::sqrt(general[i] ? nn : 1.0);
            const double nx = cx * inverse, ny = cy * inverse, nz = cz * inverse;
            // An orthonormal pair (u, w) spanning the plane normal to n: u = e x n / |e x n|
            // with e the axis x1, or x2 when n lies near x1; w = n x u.
            const bool nearX = !(std::abs(nx) < 0.9);
            const double ux = nearX ? nz : 0.0, uy = nearX ? 0.0 : -nz, uz = nearX ? -nx : ny;
            const double length2 = ux * ux + uy * uy + uz * uz;
            const double l = 1.0 / std::sqrt(general[i] ? length2 : 1.0);
            const double Ux = ux * l, Uy = uy * l, Uz = uz * l;
            const double wx = ny * Uz - nz * Uy, wy = nz * Ux - nx * Uz, wz = nx * Uy - ny * Ux;
            // The deviator in the plane: [[a b] [b e]] on (u, w).
            const double dux = dxx[i] * Ux + xy * Uy + xz * Uz, duy = xy * Ux + dyy[i] * Uy + yz * Uz,
                         duz = xz * Ux + yz * Uy + dzz[i] * Uz;
            const double dwx = dxx[i] * wx + xy * wy + xz * wz, dwy = xy * wx + dyy[i] * wy + yz * wz,
                         dwz = xz * wx + yz * wy + dzz[i] * wz;
            const double a = Ux * dux + Uy * duy + Uz * duz, bb = wx * dux + wy * duy + wz * duz,
                         e = wx * dwx + wy * dwy + wz * dwz;
            // The 2 x 2 problem in closed form, as the plane case: the mean, the radius, and
            // the major axis at angle theta in (u, w), from half-angle forms free of
            // cancellation; a round pair (radius 0) takes any axes in the plane.
            const double mean = 0.5 * (a + e), half = 0.5 * (a - e), radius = std::sqrt(half * half + bb * bb);
            const bool round = !(radius > 0.0);
            const double rad = round ? 1.0 : radius;
            const double big = std::sqrt(0.5 * (1.0 + std::abs(half) / rad));  // the larger of |cos|, |sin|
            const double small = bb / (2.0 * rad * big);
            // half < 0: sin theta takes the sign of b and cos theta = b / (2 R sin theta) = |small|.
            const double ctFixed = round ? 1.0 : half >= 0.0 ? big : std::abs(small),
                         st = round ? 0.0 : half >= 0.0 ? small : std::copysign(big, bb);
            const double majx = ctFixed * Ux + st * wx, majy = ctFixed * Uy + st * wy, majz = ctFixed * Uz + st * wz;
            const double minx = -st * Ux + ctFixed * wx, miny = -st * Uy + ctFixed * wy, minz = -st * Uz + ctFixed * wz;
            PrincipalStresses<3>& o = ob[i];
            if (lt[i] >= 0.0) {  // the distinct value is the largest; ascending, the pair's smaller first
                o.sigma_ << p[i] + (mean - radius), p[i] + (mean + radius), p[i] + lt[i];
                o.axes_ << minx, majx, nx, miny, majy, ny, minz, majz, nz;
            } else {
                o.sigma_ << p[i] + lt[i], p[i] + (mean - radius), p[i] + (mean + radius);
                o.axes_ << nx, minx, majx, ny, miny, majy, nz, minz, majz;
            }
        }
        for (std::size_t i = 0; i < m; ++i)
            if (!general[i]) ob[i].special(sb[i]);
    }
}

} // namespace gpic
