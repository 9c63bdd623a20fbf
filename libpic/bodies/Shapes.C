// The built-in shapes: small enough to share one file.
#include "bodies/Shape.H"

#include "dictionary/Dictionary.H"

#include <string>
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
        checkSimple(d);
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

    //- A self-intersecting outline (a bow-tie) has no inside the user meant: the even-odd
    //  test fills only part of it. Two edges that are not neighbours may touch (a thin wall
    //  closing on itself) but not cross.
    void checkSimple(const Dictionary& d) const
    {
        const std::size_t n = points_.size();
        const auto [lo, hi] = bounds();
        const double zero = 1e-12 * (hi - lo).squaredNorm();  // orientation round-off
        const auto side = [&](const Vector2& a, const Vector2& b, const Vector2& c) {
            const double o = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
            return o > zero ? 1 : o < -zero ? -1 : 0;
        };
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 2; j < n; ++j) {
                if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
                const Vector2 &a = points_[i], &b = points_[(i + 1) % n], &c = points_[j], &e = points_[(j + 1) % n];
                if (side(a, b, c) * side(a, b, e) < 0 && side(c, e, a) * side(c, e, b) < 0)
                    d.fail("points", "keyword 'points' in dictionary " + d.name() + ": the polygon's edges " +
                                         std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                                         " cross (a self-intersecting outline has no inside): list the corners "
                                         "in order around the shape");
            }
    }
};

GPIC_REGISTER(Shape, RectangleShape, "rectangle")
GPIC_REGISTER(Shape, CircleShape, "circle")
GPIC_REGISTER(Shape, PolygonShape, "polygon")

} // namespace gpic
