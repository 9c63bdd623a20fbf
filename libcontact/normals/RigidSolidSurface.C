#include "normals/RigidSolidSurface.H"

#include "dictionary/Dictionary.H"

#include <cmath>
#include <limits>

namespace gpic {

#if GPIC_WITH_3D  // TriSurface and RigidPose are built with the 3D engine only
namespace {
TriSurface surfaceOf(const Dictionary& d)
{
    const std::string type = d.getWord("type", {"box", "triSurface"});
    if (type == "box") return TriSurface::box(d.get<Space<3>::Vector>("min"), d.get<Space<3>::Vector>("max"), "box");
    return TriSurface::read(d);
}
} // namespace

RigidSolidSurface::RigidSolidSurface(const Dictionary& d) : surface_(surfaceOf(d))
{
    const auto [lo, hi] = surface_.bounds();
    scale_ = (hi - lo).norm();
    surface_.inside(lo);  // builds the search trees now, not inside the contact pass
}

bool RigidSolidSurface::onGridSide(const Vector& foot, const Vector& normal) const
{
    const Vector x = pose_.place(foot), n = pose_.turn(normal);
    const double tol = 1e-9 * scale_;
    for (int a = 0; a < 3; ++a) {
        if (n[a] < -(1 - 1e-9) && std::abs(x[a] - gridLower_[a]) <= tol) return true;
        if (n[a] > 1 - 1e-9 && std::abs(x[a] - gridUpper_[a]) <= tol) return true;
    }
    return false;
}

void RigidSolidSurface::place(const Particles<3>& p, int body, double reach, const Vector& gridLower,
                              const Vector& gridUpper, const RankReductions& ranks)
{
    gridLower_ = gridLower;
    gridUpper_ = gridUpper;
    const RigidPose pose = RigidPose::of(p, body, ranks);
    // Searches made where the body was stay true only where it still is, to the bit.
    steady_ = pose.R == pose_.R && pose.c0 == pose_.c0 && pose.c == pose_.c && reach == reach_;
    if (!steady_) searches_.clear();
    pose_ = pose;
    reach_ = reach;
}

RigidSolidSurface::NodeSearch RigidSolidSurface::search(const Vector& X) const
{
    NodeSearch s;
    s.nearest = surface_.nearest(X);
    s.near = surface_.facetsNear(X, s.nearest.distance + reach_);
    return s;
}

RigidSolidSurface::NodeSearch& RigidSolidSurface::searchAt(int node, const Vector& X) const
{
    if (!steady_) return moving_ = search(X);  // a moving tool: nothing to keep
    const auto found = searches_.find(node);
    if (found != searches_.end()) return found->second;
    return searches_.emplace(node, search(X)).first->second;
}

bool RigidSolidSurface::inside(NodeSearch& s, const Vector& X) const
{
    if (s.inside < 0) s.inside = surface_.inside(X) ? 1 : 0;
    return s.inside == 1;
}

RigidSolidSurface::Vector RigidSolidSurface::outwardNormal(const Vector& x, const Vector& hint, int node) const
{
    const Vector X = pose_.unplace(x), H = pose_.unturn(hint);
    if (node >= 0) return normalFrom(searchAt(node, X), X, H);
    NodeSearch s = search(X);
    return normalFrom(s, X, H);
}

RigidSolidSurface::Vector RigidSolidSurface::normalFrom(NodeSearch& s, const Vector& X, const Vector& H) const
{
    const double tol = 1e-12 * scale_;
    const TriSurface::FacetPoint any = s.nearest;
    const double toSurface = any.distance;
    // The nearest facets, and the nearest of those turned to the material (RigidSurface.H).
    const double facing = -std::sin(10.0 * M_PI / 180.0) * H.norm();
    Vector anyNormal = Vector::Zero(), normal = Vector::Zero(), foot = any.foot;
    double dist = std::numeric_limits<double>::max();
    for (const auto& f : s.near) {
        const Vector n = surface_.facetNormal(f.facet);
        if (f.distance <= toSurface + tol) anyNormal += n;
        if (H.isZero() || !(n.dot(H) < facing)) continue;
        if (f.distance < dist - tol) {
            dist = f.distance;
            foot = f.foot;
            normal = n;
        } else if (f.distance <= dist + tol) {
            normal += n;
        }
    }
    if (normal.isZero()) {  // no hint, or no facet turned to the material: the nearest
        dist = toSurface;
        foot = any.foot;
        normal = anyNormal.isZero() ? surface_.facetNormal(any.facet) : anyNormal;
    }
    normal.normalize();
    // Clear of the body beyond an edge or a corner: the direction from the nearest point,
    // where the material wraps round it (RigidSurface.H).
    if (toSurface > tol && !inside(s, X)) {
        const Vector fromFoot = (X - foot) / dist;
        const bool wraps = H.isZero() || fromFoot.dot(H) < normal.dot(H);
        if (fromFoot.dot(normal) > 0 && fromFoot.dot(normal) < 1 - 1e-12 && wraps) return pose_.turn(fromFoot);
    }
    return pose_.turn(normal);
}

bool RigidSolidSurface::facesNode(int node, const Vector& x) const
{
    if (!steady_) return facesNode(x);
    NodeSearch& s = searchAt(node, pose_.unplace(x));
    if (s.faces < 0) s.faces = facesNode(x) ? 1 : 0;
    return s.faces == 1;
}

bool RigidSolidSurface::facesNode(const Vector& x) const
{
    const Vector X = pose_.unplace(x);
    // The inside test last: the nodes of a contact mostly lie on the surface, where the
    // ray shooting of the inside test is at its slowest (exact arithmetic on degenerate rays).
    const TriSurface::FacetPoint near = surface_.nearest(X);
    if (near.distance <= 1e-12 * scale_) return true;
    // In front of a face: the way to the node from its nearest point is the face's normal
    // (also where that point lies on an edge between two triangles of one flat face) ...
    const Vector n = surface_.facetNormal(near.facet);
    if ((X - near.foot).dot(n) >= (1 - 1e-9) * near.distance) {
        // ... and that point is not on an edge or a corner of the body, where a face of
        // another plane meets it at the same point: the node then lies level with that face,
        // beyond the edge, as the node one cell ahead of a blade's foot does. The plane
        // RigidSurface counts the end of a side as its corner alike; counted as facing, that
        // node pushed the sand below the foot along (doc/contact.md, "Nodes beyond a corner").
        // An edge of the body is where faces meet at more than 30 degrees (a blade's foot);
        // the seams of a round wall drawn by facets (a few degrees) are not. A face that lies
        // on a side of the grid has no material beyond it (a silo's wall standing on the
        // floor): the node level with it, on that side, still faces.
        const double band = 1e-9 * scale_, edge = std::cos(30.0 * M_PI / 180.0);
        for (const auto& f : surface_.facetsNear(X, near.distance + band))
            if ((f.foot - near.foot).norm() <= band && surface_.facetNormal(f.facet).dot(n) < edge &&
                !onGridSide(f.foot, surface_.facetNormal(f.facet)))
                return false;
        return true;
    }
    return surface_.inside(X);
}

#endif

} // namespace gpic
