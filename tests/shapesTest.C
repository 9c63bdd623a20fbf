// The body shapes of constant/bodies that need more than a one-line test: the annulus (a
// ring or a sector of it) holds exactly the points between its radii and angles, its
// bounding box is the sector's, and impossible rings are refused with the keyword.
#include "bodies/Shape.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace gpic;

namespace {

std::unique_ptr<Shape<2>> shape(const std::string& text)
{
    const Dictionary d = Dictionary::parse("shape { " + text + " }", "constant/bodies");
    return Shape<2>::New(d.subDict("shape"));
}

std::string refusal(const std::string& text)
{
    try {
        shape(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

Vector2 polar(double r, double degrees)
{
    return Vector2(r * std::cos(degrees * M_PI / 180), r * std::sin(degrees * M_PI / 180));
}

} // namespace

TEST(AnnulusShape, aQuarterRingHoldsThePointsBetweenItsRadiiAndAngles)
{
    const auto quarter = shape("type annulus; centre (0 0); innerRadius 0.1; outerRadius 0.2; startAngle 0; endAngle 90;");
    EXPECT_TRUE(quarter->inside(polar(0.15, 45)));
    EXPECT_TRUE(quarter->inside(Vector2(0.1, 0)));      // on the inner radius and the start line
    EXPECT_TRUE(quarter->inside(Vector2(0, 0.2)));      // on the outer radius and the end line
    EXPECT_FALSE(quarter->inside(polar(0.099, 45)));
    EXPECT_FALSE(quarter->inside(polar(0.201, 45)));
    EXPECT_FALSE(quarter->inside(polar(0.15, 91)));
    EXPECT_FALSE(quarter->inside(polar(0.15, -1)));
    const auto [lo, hi] = quarter->bounds();
    EXPECT_EQ(lo, Vector2(0, 0));                       // exactly: a grid may start on the axis
    EXPECT_NEAR((hi - Vector2(0.2, 0.2)).norm(), 0, 1e-15);
}

TEST(AnnulusShape, aSectorAcrossTheX1AxisAndAFullRingHaveTheirBounds)
{
    const auto across = shape("type annulus; centre (1 1); innerRadius 0.5; outerRadius 1; startAngle -30; endAngle 30;");
    EXPECT_TRUE(across->inside(Vector2(1.9, 1)));
    EXPECT_TRUE(across->inside(Vector2(1, 1) + polar(0.7, 345)));
    EXPECT_FALSE(across->inside(Vector2(1, 1) + polar(0.7, 35)));
    const auto [lo, hi] = across->bounds();
    EXPECT_NEAR(lo.x(), 1 + 0.5 * std::cos(M_PI / 6), 1e-14);
    EXPECT_NEAR(lo.y(), 0.5, 1e-14);
    EXPECT_NEAR(hi.x(), 2.0, 1e-14);
    EXPECT_NEAR(hi.y(), 1.5, 1e-14);

    const auto ring = shape("type annulus; centre (0 0); innerRadius 1; outerRadius 2;");
    EXPECT_TRUE(ring->inside(polar(1.5, 200)));
    EXPECT_FALSE(ring->inside(Vector2(0.5, 0)));
    const auto [rlo, rhi] = ring->bounds();
    EXPECT_NEAR((rlo - Vector2(-2, -2)).norm(), 0, 1e-14);
    EXPECT_NEAR((rhi - Vector2(2, 2)).norm(), 0, 1e-14);

    const auto disc = shape("type annulus; centre (0 0); outerRadius 1; startAngle 0; endAngle 90;");
    EXPECT_TRUE(disc->inside(Vector2(0, 0)));
    EXPECT_TRUE(disc->inside(polar(0.5, 30)));
}

TEST(AnnulusShape, impossibleRingsAreRefused)
{
    EXPECT_NE(refusal("type annulus; centre (0 0); innerRadius 0.2; outerRadius 0.1;").find("outerRadius must exceed"),
              std::string::npos);
    EXPECT_NE(refusal("type annulus; centre (0 0); innerRadius -1; outerRadius 0.1;").find("innerRadius"),
              std::string::npos);
    const std::string angles = refusal("type annulus; centre (0 0); outerRadius 1; startAngle 90; endAngle 0;");
    EXPECT_NE(angles.find("endAngle"), std::string::npos) << angles;
    EXPECT_NE(angles.find("constant/bodies:1"), std::string::npos) << angles;
}
