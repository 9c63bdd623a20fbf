#include "normals/RigidSurface.H"

#include "dictionary/Dictionary.H"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gpic {

RigidSurface::RigidSurface(const Dictionary& d)
{
    const std::string type = d.getWord("type", {"circle", "rectangle", "polygon"});
    if (type == "circle") {
        circle_ = true;
        centre_ = d.get<Vector2>("centre");
        return;
    }
    if (type == "rectangle") {
        const Vector2 lo = d.get<Vector2>("min"), hi = d.get<Vector2>("max");
        points_ = {lo, Vector2(hi.x(), lo.y()), hi, Vector2(lo.x(), hi.y())};
        return;
    }
    points_ = d.get<std::vector<Vector2>>("points");
    if (points_.size() < 3) d.fail("points", "a polygon needs at least 3 points");
    double area2 = 0;
    for (std::size_t i = 0, j = points_.size() - 1; i < points_.size(); j = i++)
        area2 += points_[j].x() * points_[i].y() - points_[i].x() * points_[j].y();
    if (area2 < 0) std::reverse(points_.begin(), points_.end());  // counter-clockwise
}

void RigidSurface::place(const Particles<2>& p, int body, const RankReductions& ranks)
{
    double mass = 0;
    Vector2 c = Vector2::Zero(), c0 = Vector2::Zero();
    // The body's particles lie in one block of its material: the second sum runs over the
    // range they span, not over the whole scene again.
    std::size_t first = p.size(), last = 0;
    for (std::size_t q = 0; q < p.size(); ++q)
        if (p.body[q] == body) {
            first = std::min(first, q);
            last = q;
            mass += p.m[q];
            c += p.m[q] * p.x[q];
            c0 += p.m[q] * p.x0[q];
        }
    if (ranks.parallel()) {  // every rank's particles of the body
        std::vector<double> sums{mass, c.x(), c.y(), c0.x(), c0.y()};
        ranks.sumOver(sums);
        mass = sums[0], c = Vector2(sums[1], sums[2]), c0 = Vector2(sums[3], sums[4]);
    }
    if (mass <= 0) return;
    c /= mass;
    c0 /= mass;
    // The rotation of the polar decomposition of A = sum m (x - c)(x0 - c0)^T (2-D closed form).
    Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
    for (std::size_t q = first; q <= last; ++q)
        if (p.body[q] == body) A.noalias() += p.m[q] * (p.x[q] - c) * (p.x0[q] - c0).transpose();
    if (ranks.parallel()) {
        std::vector<double> sums(A.data(), A.data() + 4);
        ranks.sumOver(sums);
        A = Eigen::Map<const Eigen::Matrix2d>(sums.data());
    }
    angle_ = std::atan2(A(1, 0) - A(0, 1), A(0, 0) + A(1, 1));
    cos_ = std::cos(angle_);
    sin_ = std::sin(angle_);
    c_ = c;
    c0_ = c0;
    translation_ = c - c0;
}

// To the shape's own frame: X = R^T (x - c) + c0.
Vector2 RigidSurface::toShapeFrame(const Vector2& x) const
{
    const Vector2 d = x - c_;
    return c0_ + Vector2(cos_ * d.x() + sin_ * d.y(), -sin_ * d.x() + cos_ * d.y());
}

Vector2 RigidSurface::outwardNormal(const Vector2& x, const Vector2& hint) const
{
    const Vector2 X = toShapeFrame(x);
    const Vector2 H(cos_ * hint.x() + sin_ * hint.y(), -sin_ * hint.x() + cos_ * hint.y());
    const Vector2 N = normalInShapeFrame(X, H);
    return Vector2(cos_ * N.x() - sin_ * N.y(), sin_ * N.x() + cos_ * N.y());
}

bool RigidSurface::insidePolygon(const Vector2& X) const
{
    bool in = false;
    for (std::size_t i = 0, j = points_.size() - 1; i < points_.size(); j = i++) {
        const Vector2 &a = points_[i], &b = points_[j];
        if ((a.y() > X.y()) != (b.y() > X.y()) &&
            X.x() < (b.x() - a.x()) * (X.y() - a.y()) / (b.y() - a.y()) + a.x())
            in = !in;
    }
    return in;
}

bool RigidSurface::facesNode(const Vector2& x) const
{
    const Vector2 X = toShapeFrame(x);
    if (circle_ || insidePolygon(X)) return true;
    const double scale = (points_[1] - points_[0]).norm();
    double best = std::numeric_limits<double>::max();
    bool corner = false;
    for (std::size_t i = 0; i < points_.size(); ++i) {
        const Vector2& a = points_[i];
        const Vector2 e = points_[(i + 1) % points_.size()] - a;
        const double t = (X - a).dot(e) / e.squaredNorm();
        const Vector2 f = a + std::clamp(t, 0.0, 1.0) * e;
        const double d = (X - f).norm();
        if (d < best - 1e-12 * scale) {
            best = d;
            corner = t <= 0.0 || t >= 1.0;
        } else if (d <= best + 1e-12 * scale) {
            corner = corner && (t <= 0.0 || t >= 1.0);
        }
    }
    return best <= 1e-12 * scale || !corner;
}

Vector2 RigidSurface::normalInShapeFrame(const Vector2& X, const Vector2& hint) const
{
    if (circle_) {
        const Vector2 r = X - centre_;
        const double len = r.norm();
        return len > 0 ? Vector2(r / len) : Vector2(0, 1);
    }
    // Nearest face among those that face the material (outward normal against the hint):
    // a node on the line of a face the material cannot touch (a rigid body lying on a grid
    // side) must not take that face. Equally near faces (a corner) share the normal.
    // A face at right angles to the material's surface does not face it either, even where
    // round-off or a slight tilt of that surface turns it a little: the node level with a
    // footing's base just beyond its edge would otherwise take the side face, and the soil
    // surface there would be held sideways (see doc/contact.md).
    const double facing = -std::sin(10.0 * M_PI / 180.0) * hint.norm();
    const double scale = (points_[1] - points_[0]).norm();
    const auto nearestFace = [&](bool facingOnly, Vector2& foot, Vector2& normal) {
        double best = std::numeric_limits<double>::max();
        for (std::size_t i = 0; i < points_.size(); ++i) {
            const Vector2& a = points_[i];
            const Vector2 e = points_[(i + 1) % points_.size()] - a;
            const Vector2 outward = Vector2(e.y(), -e.x()).normalized();  // counter-clockwise
            if (facingOnly && !(outward.dot(hint) < facing)) continue;
            const Vector2 f = a + std::clamp((X - a).dot(e) / e.squaredNorm(), 0.0, 1.0) * e;
            const double dist = (X - f).norm();
            if (dist < best - 1e-12 * scale) {
                best = dist;
                foot = f;
                normal = outward;
            } else if (dist <= best + 1e-12 * scale) {
                normal += outward;
            }
        }
        return best;
    };
    Vector2 foot = X, normal = Vector2::Zero(), anyFoot = X, anyNormal = Vector2::Zero();
    const double toSurface = nearestFace(false, anyFoot, anyNormal);
    double dist = hint.isZero() ? -1.0 : nearestFace(true, foot, normal);
    if (normal.isZero()) {  // no hint, or no face turned to the material: the nearest face
        dist = toSurface;
        foot = anyFoot;
        normal = anyNormal;
    }
    // Clear of the body, beyond the end of the chosen face (round a corner): the direction
    // from that corner to the node, where the material wraps round the corner. Where the
    // material lies across the face instead (its surface normal opposes the face's better
    // than the corner's direction does: soil under a footing's edge), the face's normal: a
    // node just beside the corner stands for material under the face, not beside the body.
    normal.normalize();
    if (toSurface > 1e-12 * scale && !insidePolygon(X)) {
        const Vector2 fromFoot = (X - foot) / dist;
        const bool wraps = hint.isZero() || fromFoot.dot(hint) < normal.dot(hint);
        if (fromFoot.dot(normal) > 0 && fromFoot.dot(normal) < 1 - 1e-12 && wraps) return fromFoot;
    }
    return normal;
}

} // namespace gpic
