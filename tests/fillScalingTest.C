// picInit's work grows with the bodies, not with their square: each body is filled over the
// cells of its own box, and checked for overlaps against the bodies near it only. Counted, not
// timed: the calls of Shape::inside for 400 and for 1600 small square bodies on a lattice
// (the grid grows with them). Filling every body over the whole grid, or checking it against
// every earlier body, made the count grow 16-fold (1e4 bodies 3 s, 4e4 bodies 42 s).
#include "bodies/BodyFiller.H"
#include "bodies/Shape.H"
#include "case/CaseFiles.H"
#include "core/Registry.H"
#include "dictionary/Dictionary.H"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace {

long insideCalls = 0;

//- A square that counts the calls of inside().
class CountedSquare : public gpic::Shape<2> {
public:
    explicit CountedSquare(const gpic::Dictionary& d) : min_(d.get<Vector>("min")), max_(d.get<Vector>("max")) {}
    bool inside(const Vector& x) const override
    {
        ++insideCalls;
        return (x.array() >= min_.array()).all() && (x.array() <= max_.array()).all();
    }
    std::pair<Vector, Vector> bounds() const override { return {min_, max_}; }

private:
    Vector min_, max_;
};

} // namespace

GPIC_REGISTER(gpic::Shape<2>, CountedSquare, "countedSquare")

namespace {

//- Fill `side` x `side` squares of 2 x 2 cells, a cell apart; the calls of inside() it took.
long fillLattice(int side)
{
    const double h = 0.01;
    std::ostringstream grid, bodies;
    grid << "origin (0 0); cellSize " << h << "; nCells (" << 3 * side << ' ' << 3 * side << ");\n"
         << "boundaries { left { type free; } right { type free; } bottom { type free; } top { type free; } }\n";
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
            bodies << "b" << i << '_' << j << " { material m; particlesPerCell 2; shape { type countedSquare; min ("
                   << (3 * i + 0.5) * h << ' ' << (3 * j + 0.5) * h << "); max (" << (3 * i + 2.5) * h << ' '
                   << (3 * j + 2.5) * h << "); } }\n";
    const gpic::Dictionary gridDict = gpic::Dictionary::parse(grid.str(), "constant/grid");
    const gpic::Dictionary materialsDict =
        gpic::Dictionary::parse("m { type linearElastic; rho 1000; E 1e6; nu 0.3; }\n", "constant/materials");
    const gpic::Dictionary bodiesDict = gpic::Dictionary::parse(bodies.str(), "constant/bodies");
    const gpic::Grid<2> g(gridDict);
    const auto materials = gpic::readMaterials<2>(materialsDict);
    insideCalls = 0;
    const auto filled = gpic::fillBodies<2>(bodiesDict, g, materials, gpic::Space<2>::Vector::Zero());
    // Each square: 2 x 2 cells, 2 x 2 particles in each.
    EXPECT_EQ(filled.particles.size(), static_cast<std::size_t>(16 * side * side));
    EXPECT_EQ(filled.bodyNames.size(), static_cast<std::size_t>(side * side));
    return insideCalls;
}

} // namespace

TEST(FillBodies, theWorkGrowsWithTheBodiesNotWithTheirSquare)
{
    const long small = fillLattice(20), large = fillLattice(40);  // 400 and 1600 bodies
    ASSERT_GT(small, 0);
    const double ratio = static_cast<double>(large) / static_cast<double>(small);
    // Four times the bodies: four times the work (16 times were it quadratic).
    EXPECT_LT(ratio, 5.0) << small << " calls for 400 bodies, " << large << " for 1600";
    EXPECT_GT(ratio, 3.0) << small << " calls for 400 bodies, " << large << " for 1600";
}
