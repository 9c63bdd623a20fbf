// The built-in shapes: small enough to share one file.
#include "bodies/Shape.H"

#include "dictionary/Dictionary.H"

#include <vector>

namespace gpic {

class RectangleShape : public Shape {
public:
    explicit RectangleShape(const Dictionary& d) : min_(d.get<Vector2>("min")), max_(d.get<Vector2>("max"))
    {
        if (!(max_.array() > min_.array()).all()) d.fail("max", "max must exceed min in x and y");
    }
    bool inside(const Vector2& x) const override
    {
        return (x.array() >= min_.array()).all() && (x.array() <= max_.array()).all();
    }
    std::pair<Vector2, Vector2> bounds() const override { return {min_, max_}; }

private:
    Vector2 min_, max_;
};

class CircleShape : public Shape {
public:
    explicit CircleShape(const Dictionary& d)
        : centre_(d.get<Vector2>("centre")),
          radius_(d.getChecked<double>("radius", [](const double& r) { return r > 0; }, "radius > 0"))
    {}
    bool inside(const Vector2& x) const override { return (x - centre_).norm() <= radius_; }
    std::pair<Vector2, Vector2> bounds() const override
    {
        return {centre_ - Vector2::Constant(radius_), centre_ + Vector2::Constant(radius_)};
    }

private:
    Vector2 centre_;
    double radius_;
};

class PolygonShape : public Shape {
public:
    explicit PolygonShape(const Dictionary& d) : points_(d.get<std::vector<Vector2>>("points"))
    {
        if (points_.size() < 3) d.fail("points", "a polygon needs at least 3 points");
    }
    //- Even-odd ray crossing test.
    bool inside(const Vector2& x) const override
    {
        bool in = false;
        for (std::size_t i = 0, j = points_.size() - 1; i < points_.size(); j = i++) {
            const Vector2 &a = points_[i], &b = points_[j];
            if ((a.y() > x.y()) != (b.y() > x.y()) &&
                x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x())
                in = !in;
        }
        return in;
    }
    std::pair<Vector2, Vector2> bounds() const override
    {
        Vector2 lo = points_[0], hi = points_[0];
        for (const auto& p : points_) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        return {lo, hi};
    }

private:
    std::vector<Vector2> points_;
};

GPIC_REGISTER(Shape, RectangleShape, "rectangle")
GPIC_REGISTER(Shape, CircleShape, "circle")
GPIC_REGISTER(Shape, PolygonShape, "polygon")

} // namespace gpic
