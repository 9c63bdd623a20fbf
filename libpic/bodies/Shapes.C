// The built-in shapes: small enough to share one file.
#include "bodies/PolygonShape.H"

#include "dictionary/Dictionary.H"

#include <cmath>
#include <string>
#include <vector>

namespace gpic {

// | keyword | meaning             | units | default |
// | min     | lower-left corner   | m     | required |
// | max     | upper-right corner  | m     | required |
class RectangleShape : public Shape<2> {
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

// | keyword | meaning | units | default |
// | centre  | centre  | m     | required |
// | radius  | radius  | m     | required, > 0 |
class CircleShape : public Shape<2> {
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

//- The ring between two radii, or a sector of it (angles in degrees from the x1 axis,
//  counter-clockwise from startAngle to endAngle): a pipe, a dome, a thick sphere's section.
// | keyword     | meaning                        | units | default |
// | centre      | centre                         | m     | required |
// | innerRadius | inner radius                   | m     | 0 |
// | outerRadius | outer radius                   | m     | required, > innerRadius |
// | startAngle  | first angle, from the x1 axis  | deg   | 0 |
// | endAngle    | last angle                     | deg   | startAngle + 360 |
class AnnulusShape : public Shape<2> {
public:
    explicit AnnulusShape(const Dictionary& d)
        : centre_(d.get<Vector2>("centre")),
          inner_(d.getOrDefault<double>("innerRadius", 0.0)),
          outer_(d.get<double>("outerRadius")),
          start_(d.getOrDefault<double>("startAngle", 0.0)),
          end_(d.getOrDefault<double>("endAngle", start_ + 360.0))
    {
        if (!(inner_ >= 0)) d.fail("innerRadius", "innerRadius must be >= 0");
        if (!(outer_ > inner_)) d.fail("outerRadius", "outerRadius must exceed innerRadius");
        if (!(end_ > start_ && end_ - start_ <= 360))
            d.fail("endAngle", "endAngle must exceed startAngle by at most 360 degrees");
    }
    bool inside(const Vector2& x) const override
    {
        const Vector2 r = x - centre_;
        const double rho = r.norm();
        if (rho < inner_ || rho > outer_) return false;
        if (end_ - start_ >= 360 || rho == 0) return true;
        return turnFromStart(std::atan2(r.y(), r.x()) * 180 / M_PI) <= end_ - start_ + angleSlack;
    }
    std::pair<Vector2, Vector2> bounds() const override
    {
        // The sector's ends at both radii and the outer radius at every axis direction it spans.
        const auto at = [&](double radius, double degrees) {
            const double a = degrees * M_PI / 180;
            return Vector2(centre_ + radius * Vector2(std::cos(a), std::sin(a)));
        };
        std::vector<Vector2> extreme{at(inner_, start_), at(outer_, start_), at(inner_, end_), at(outer_, end_)};
        for (int k = 0; k < 4; ++k)
            if (turnFromStart(90.0 * k) <= end_ - start_) extreme.push_back(at(outer_, 90.0 * k));
        Vector2 lo = extreme[0], hi = extreme[0];
        for (const auto& p : extreme) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        // An axis direction's cosine is not exactly 0: no 6e-18 beyond a grid line.
        const double zero = 1e-12 * outer_;
        for (int i = 0; i < PlaneSpace::dim; ++i) {
            if (std::abs(lo[i] - centre_[i]) < zero) lo[i] = centre_[i];
            if (std::abs(hi[i] - centre_[i]) < zero) hi[i] = centre_[i];
        }
        return {lo, hi};
    }

private:
    static constexpr double angleSlack = 1e-9;  //- degrees: a point on an end line is inside
    Vector2 centre_;
    double inner_, outer_, start_, end_;

    //- How far `degrees` lies counter-clockwise from startAngle, in [0, 360).
    double turnFromStart(double degrees) const
    {
        const double turn = std::fmod(degrees - start_ + angleSlack, 360.0);
        return (turn < 0 ? turn + 360.0 : turn) - angleSlack;
    }
};

GPIC_REGISTER(Shape<2>, RectangleShape, "rectangle")
GPIC_REGISTER(Shape<2>, CircleShape, "circle")
GPIC_REGISTER(Shape<2>, PolygonShape, "polygon")
GPIC_REGISTER(Shape<2>, AnnulusShape, "annulus")

} // namespace gpic
