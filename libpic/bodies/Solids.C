// The built-in 3D shapes (Shape.H): a box, a sphere, a cylinder between two points, a
// polygon extruded along x3 and a closed surface from CAD (STL).
#include "bodies/PolygonShape.H"
#include "bodies/TriSurface.H"

#include "dictionary/Dictionary.H"

#include <cmath>

namespace gpic {

using Vector3 = Space<3>::Vector;

// | keyword | meaning                  | units | default |
// | min     | corner of least x, y, z  | m     | required |
// | max     | corner of largest x, y, z | m    | required |
class BoxShape : public Shape<3> {
public:
    explicit BoxShape(const Dictionary& d) : min_(d.get<Vector3>("min")), max_(d.get<Vector3>("max"))
    {
        if (!(max_.array() > min_.array()).all()) d.fail("max", "max must exceed min in x, y and z");
    }
    bool inside(const Vector3& x) const override
    {
        return (x.array() >= min_.array()).all() && (x.array() <= max_.array()).all();
    }
    std::pair<Vector3, Vector3> bounds() const override { return {min_, max_}; }

private:
    Vector3 min_, max_;
};

// | keyword | meaning | units | default |
// | centre  | centre  | m     | required |
// | radius  | radius  | m     | required, > 0 |
class SphereShape : public Shape<3> {
public:
    explicit SphereShape(const Dictionary& d)
        : centre_(d.get<Vector3>("centre")),
          radius_(d.getChecked<double>("radius", [](const double& r) { return r > 0; }, "radius > 0"))
    {}
    bool inside(const Vector3& x) const override { return (x - centre_).norm() <= radius_; }
    std::pair<Vector3, Vector3> bounds() const override
    {
        return {centre_ - Vector3::Constant(radius_), centre_ + Vector3::Constant(radius_)};
    }

private:
    Vector3 centre_;
    double radius_;
};

//- The solid cylinder of radius `radius` about the segment point1 - point2 (OpenFOAM's
//  cylinderToCell names the same keywords), flat at both ends.
// | keyword | meaning                    | units | default |
// | point1  | one end of the axis        | m     | required |
// | point2  | the other end              | m     | required |
// | radius  | radius                     | m     | required, > 0 |
class CylinderShape : public Shape<3> {
public:
    explicit CylinderShape(const Dictionary& d)
        : p1_(d.get<Vector3>("point1")),
          p2_(d.get<Vector3>("point2")),
          radius_(d.getChecked<double>("radius", [](const double& r) { return r > 0; }, "radius > 0"))
    {
        if (!((p2_ - p1_).norm() > 0)) d.fail("point2", "point2 must differ from point1 (the axis' two ends)");
    }
    bool inside(const Vector3& x) const override
    {
        const Vector3 axis = p2_ - p1_;
        const double s = (x - p1_).dot(axis) / axis.squaredNorm();  // 0 at point1, 1 at point2
        if (s < 0 || s > 1) return false;
        return (x - p1_ - s * axis).norm() <= radius_;
    }
    std::pair<Vector3, Vector3> bounds() const override
    {
        // Each end disc reaches radius * sqrt(1 - a_i^2) along axis i (a: the unit axis).
        const Vector3 a = (p2_ - p1_).normalized();
        const Vector3 reach = radius_ * (Vector3::Ones() - a.cwiseProduct(a)).cwiseMax(0.0).cwiseSqrt();
        return {p1_.cwiseMin(p2_) - reach, p1_.cwiseMax(p2_) + reach};
    }

private:
    Vector3 p1_, p2_;
    double radius_;
};

//- A simple polygon in (x1, x2), extruded from x3 = zMin to zMax: a wall, a strip footing
//  or a plane-strain body given a finite width.
// | keyword | meaning                                   | units | default |
// | points  | the section ((x y) ...) in (x1, x2), at least 3 | m | required |
// | zMin    | where it starts along x3                  | m     | required |
// | zMax    | where it ends along x3                    | m     | required, > zMin |
class ExtrudedPolygonShape : public Shape<3> {
public:
    explicit ExtrudedPolygonShape(const Dictionary& d)
        : section_(d), zMin_(d.get<double>("zMin")), zMax_(d.get<double>("zMax"))
    {
        if (!(zMax_ > zMin_)) d.fail("zMax", "zMax must exceed zMin");
    }
    bool inside(const Vector3& x) const override
    {
        return x.z() >= zMin_ && x.z() <= zMax_ && section_.inside(Vector2(x.x(), x.y()));
    }
    std::pair<Vector3, Vector3> bounds() const override
    {
        const auto [lo, hi] = section_.bounds();
        return {Vector3(lo.x(), lo.y(), zMin_), Vector3(hi.x(), hi.y(), zMax_)};
    }

private:
    PolygonShape section_;
    double zMin_, zMax_;
};

//- The solid a closed STL surface bounds (bodies/TriSurface.H for the keywords).
// | keyword     | meaning                                               | units | default |
// | file        | the STL file (ASCII or binary), relative to the dictionary's file | - | required |
// | scale       | the file's unit in metres (0.001 for mm)              | m     | 1 |
// | rotation    | { axis (x y z); angle a; }: turned about the origin, after scale | -, deg | none |
// | translation | then moved by                                         | m     | (0 0 0) |
class TriSurfaceShape : public Shape<3> {
public:
    explicit TriSurfaceShape(const Dictionary& d) : surface_(TriSurface::read(d)), box_(surface_.bounds()) {}
    bool inside(const Vector3& x) const override
    {
        const bool inBox = (x.array() >= box_.first.array()).all() && (x.array() <= box_.second.array()).all();
        return inBox && surface_.inside(x);  // the box first: cheaper than a ray (the fill asks a cell beyond it)
    }
    std::pair<Vector3, Vector3> bounds() const override { return box_; }

private:
    TriSurface surface_;
    std::pair<Vector3, Vector3> box_;
};

#if GPIC_WITH_3D
GPIC_REGISTER(Shape<3>, TriSurfaceShape, "triSurface")
GPIC_REGISTER(Shape<3>, BoxShape, "box")
GPIC_REGISTER(Shape<3>, SphereShape, "sphere")
GPIC_REGISTER(Shape<3>, CylinderShape, "cylinder")
GPIC_REGISTER(Shape<3>, ExtrudedPolygonShape, "extrudedPolygon")
#endif

} // namespace gpic
