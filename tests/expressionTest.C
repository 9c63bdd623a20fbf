// Expressions in dictionaries, evaluated by muparser (bodies/Expression.H): done as written
// (the same doubles as the arithmetic in C++), and, as a field of the position, a body's
// initial velocity (bodies/VectorField.H): each particle gets the value at its own place,
// against the formula evaluated here. A mistake is one line naming file, line and what is
// wrong. (tests/driversTest.C checks the expressions of time in the drivers.)
#include "bodies/BodyFiller.H"
#include "bodies/Expression.H"
#include "case/CaseFiles.H"
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "grid/Grid.H"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace gpic;

namespace {

const double pi = 3.14159265358979323846;

//- A 1 m x 0.5 m block on 0.1 m cells, 2 x 2 particles a cell; `velocity` is its entry.
FilledBodies<2> fill(const std::string& velocity)
{
    const Dictionary grid = Dictionary::parse(
        "origin (0 0); cellSize 0.1; nCells (12 8);\n"
        "boundaries { left { type fixed; } right { type fixed; } bottom { type fixed; } top { type fixed; } }\n",
        "constant/grid");
    const Dictionary materials =
        Dictionary::parse("m { type linearElastic; rho 1000; E 1e6; nu 0.3; }\n", "constant/materials");
    const Dictionary bodies = Dictionary::parse("block\n{\n    material m;\n    particlesPerCell 2;\n"
                                                "    shape { type rectangle; min (0.1 0.1); max (1.1 0.6); }\n"
                                                "    velocity " + velocity + ";\n}\n",
                                                "constant/bodies");
    return fillBodies<2>(bodies, Grid<2>(grid), readMaterials<2>(materials), Space<2>::Vector(0, -9.81));
}

//- The one-line message of the InputError that filling with `velocity` throws.
std::string refusal(const std::string& velocity)
{
    try {
        fill(velocity);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

} // namespace

TEST(Expressions, theValueIsTheArithmeticAsWritten)
{
    // muparser's optimizer would fold 0.1*t/3 into t*(0.1/3): 0.16999999999999998 at t = 5.1.
    const double t = 5.1;
    EXPECT_EQ(Expression("0.1*t/3", "f", 1)(t), (0.1 * t) / 3);
    EXPECT_EQ(Expression("2*pi*t + t^2", "f", 1)(t), 2 * pi * t + std::pow(t, 2));
    EXPECT_EQ(Expression("abs(-0*t)", "f", 1)(t), 0.0);
    EXPECT_FALSE(std::signbit(Expression("abs(-0*t)", "f", 1)(t)));  // +0, as std::abs gives
    // muparser's functions of several arguments and its comparisons.
    EXPECT_EQ(Expression("min(t, 1) + max(t, 1)", "f", 1)(t), 1 + t);
    EXPECT_EQ(Expression("t < 1 ? 0 : 2*t", "f", 1)(t), 2 * t);
}

TEST(Expressions, anAssignmentIsRefused)
{
    try {
        Expression("t = 1", "constant/rigidBodies", 3);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "constant/rigidBodies:3: expression \"t = 1\": '=' assigns")) << e.what();
    }
    EXPECT_EQ(Expression("t == 1", "f", 1)(1.0), 1.0);
}

TEST(Expressions, eachParticleTakesTheInitialVelocityAtItsPlace)
{
    // The elastic bar's first mode, v1 = v0 sin(beta x), and a shear v2 = -0.5 y.
    const auto filled = fill("(\"0.1*sin(pi/(2*25)*x)\" \"-0.5*y\")");
    const auto& p = filled.particles;
    ASSERT_EQ(p.size(), 200u);
    for (std::size_t q = 0; q < p.size(); ++q) {
        const double x = p.x[q].x(), y = p.x[q].y();
        EXPECT_DOUBLE_EQ(p.v[q].x(), 0.1 * std::sin(pi / (2 * 25) * x)) << "at (" << x << ", " << y << ")";
        EXPECT_DOUBLE_EQ(p.v[q].y(), -0.5 * y) << "at (" << x << ", " << y << ")";
    }
    // The particles really differ: the field is not one value.
    EXPECT_GT(std::abs(p.v[0].x() - p.v[p.size() - 1].x()), 1e-3);
}

TEST(Expressions, aNumberBesideAnExpressionAndNumbersAloneStayExact)
{
    const auto mixed = fill("(2.5 \"x*y\")");
    const auto plain = fill("(2.5 -1)");
    for (std::size_t q = 0; q < mixed.particles.size(); ++q) {
        EXPECT_EQ(mixed.particles.v[q].x(), 2.5);
        EXPECT_DOUBLE_EQ(mixed.particles.v[q].y(), mixed.particles.x[q].x() * mixed.particles.x[q].y());
        EXPECT_EQ(plain.particles.v[q], Space<2>::Vector(2.5, -1));
    }
}

TEST(Expressions, anUnknownVariableIsOneLineWithFileAndLine)
{
    // t has no meaning before the run: a body's velocity is a field of x and y.
    const std::string e = refusal("(\"0.1*sin(2*pi*t)\" 0)");
    EXPECT_TRUE(contains(e, "constant/bodies:6: expression \"0.1*sin(2*pi*t)\": unknown name 't'")) << e;
    EXPECT_TRUE(contains(e, "valid names: x, y, pi, sin")) << e;
    EXPECT_FALSE(contains(e, "\n")) << e;
    const std::string z = refusal("(0 \"z\")");  // z only in a 3D case
    EXPECT_TRUE(contains(z, "constant/bodies:6: expression \"z\": unknown name 'z'")) << z;
}

TEST(Expressions, aSyntaxErrorIsOneLineWithFileAndLine)
{
    for (const std::string bad : {"0.1*(x", "x*", "2 x", "sin x", "x = 1", ""}) {
        const std::string e = refusal("(\"" + bad + "\" 0)");
        EXPECT_TRUE(contains(e, "constant/bodies:6: expression \"" + bad + "\": ")) << e;
        EXPECT_TRUE(contains(e, " at character ")) << e;
        EXPECT_FALSE(contains(e, "\n")) << e;
    }
    EXPECT_TRUE(contains(refusal("(\"0.1*(x\" 0)"), "missing ')'"));
    EXPECT_TRUE(contains(refusal("(\"sin x\" 0)"), "'sin' needs an argument in ( )"));
    // A malformed vector around the expressions names the form.
    const std::string form = refusal("(\"x\" 0 0)");
    EXPECT_TRUE(contains(form, "constant/bodies:6: keyword 'velocity'")) << form;
    EXPECT_TRUE(contains(form, "expected (x y) with numbers or \"expressions of x, y\"")) << form;
}

TEST(Expressions, aValueThatIsNotFiniteIsRefusedNamingTheExpressionAndThePlace)
{
    // sqrt(x - 1) is NaN left of x = 1, where the block has particles.
    const std::string e = refusal("(\"sqrt(x - 1)\" 0)");
    EXPECT_TRUE(contains(e, "constant/bodies:6: expression \"sqrt(x - 1)\" is nan at (")) << e;
}

#if GPIC_WITH_3D
TEST(Expressions, aThreeDimensionalBodyTakesItsVelocityAsAFieldOfXYZ)
{
    const Dictionary grid = Dictionary::parse(
        "origin (0 0 0); cellSize 0.1; nCells (4 4 4);\n"
        "boundaries { left { type fixed; } right { type fixed; } bottom { type fixed; } top { type fixed; }"
        " back { type fixed; } front { type fixed; } }\n",
        "constant/grid");
    const Dictionary materials =
        Dictionary::parse("m { type linearElastic; rho 1000; E 1e6; nu 0.3; }\n", "constant/materials");
    const Dictionary bodies = Dictionary::parse(
        "cube { material m; particlesPerCell 2; shape { type box; min (0.1 0.1 0.1); max (0.3 0.3 0.3); }\n"
        "       velocity (\"z\" 0 \"x - y\"); }\n",
        "constant/bodies");
    const auto filled = fillBodies<3>(bodies, Grid<3>(grid), readMaterials<3>(materials), Space<3>::Vector(0, 0, -9.81));
    ASSERT_EQ(filled.particles.size(), 64u);
    for (std::size_t q = 0; q < filled.particles.size(); ++q) {
        const auto& x = filled.particles.x[q];
        EXPECT_EQ(filled.particles.v[q], Space<3>::Vector(x.z(), 0, x.x() - x.y()));
    }
}
#endif
