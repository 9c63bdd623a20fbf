// Objectivity of the plastic models: a rigid rotation must turn the stress without changing
// it. A material point is spun by a quarter turn in 100 steps (d eps = 0, d omega = pi/200
// per step, seed A1) so that sigma' = R sigma R^T: sigma11 and sigma22 swap, sigma12 changes
// sign, and p, q = sqrt(J2) and sigma33 stay (to 1e-6 relative, the project's objectivity
// requirement). For a point that starts outside the yield surface the first step also
// returns it; the return mapping is isotropic, so the end state must be the returned state
// of a point that was not spun, turned by the quarter turn.
#include "dictionary/Dictionary.H"
#include "materials/JaumannRate.H"
#include "materials/Material.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace gpic;

namespace {

struct Point {
    std::unique_ptr<Material<2>> m;
    Particles<2> p;

    Point(const std::string& entries, const SymTensor& sigma0)
        : m(Material<2>::New(Dictionary::parse(entries, "constant/materials/soil")))
    {
        p.add(Vector2::Zero(), m->rho(), 1.0, Vector2::Constant(0.5), 0, 0);  // packed: m = rho V
        m->declareFields(p);
        p.sigma[0] = sigma0;
    }
    void step(double dOmega)
    {
        p.dEps[0].setZero();
        p.dOmega[0] = dOmega;
        m->updateStress(p, {0, 1, 0}, 1e-6);
    }
};

double meanOf(const SymTensor& s) { return (s[XX] + s[YY] + s[ZZ]) / 3; }
double qOf(const SymTensor& s)
{
    const double a = s[XX] - s[YY], b = s[YY] - s[ZZ], c = s[XX] - s[ZZ];
    return std::sqrt((a * a + b * b + c * c) / 6 + s[XY] * s[XY]);
}

enum class Start { inside, onSurface, outside };

//- Spin `entries` material from sigma0 by a quarter turn; compare with the stress an unspun
//  point reaches (sigma0 itself unless it yields) turned by the quarter turn. Returns the
//  yield state of the unspun point.
double quarterTurn(const std::string& entries, const SymTensor& sigma0, Start start)
{
    SCOPED_TRACE(entries);
    Point still(entries, sigma0);
    still.step(0.0);  // the unspun return (nothing happens when sigma0 is admissible)
    const SymTensor expected = still.p.sigma[0];
    if (start != Start::onSurface) {  // on it, round-off may or may not call for a return
        EXPECT_EQ(still.p.history("yieldState")[0] > 0, start == Start::outside);
    }

    Point spun(entries, sigma0);
    for (int k = 0; k < 100; ++k) spun.step(M_PI / 200);
    const SymTensor& s = spun.p.sigma[0];
    const double scale = expected.cwiseAbs().maxCoeff();
    EXPECT_NEAR(s[XX], expected[YY], 1e-6 * scale);
    EXPECT_NEAR(s[YY], expected[XX], 1e-6 * scale);
    EXPECT_NEAR(s[XY], -expected[XY], 1e-6 * scale);
    // Relative to each invariant; round-off of the stress size where an invariant is zero.
    const auto tol = [&](double v) { return std::max(1e-6 * std::abs(v), 1e-12 * scale); };
    EXPECT_NEAR(s[ZZ], expected[ZZ], tol(expected[ZZ]));
    EXPECT_NEAR(meanOf(s), meanOf(expected), tol(meanOf(expected)));
    EXPECT_NEAR(qOf(s), qOf(expected), tol(qOf(expected)));
    // The plastic strain is accumulated, not spun (as the total strain is): that of the spun
    // point is the unspun one turned by the first step only, the step in which it arose.
    SymTensor e0 = still.p.epsP[0];
    rotateJaumann(e0, M_PI / 200);
    const SymTensor& e = spun.p.epsP[0];
    // (A point on the surface may see round-off returns: strains of 1e-12 and below.)
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(e[i], e0[i], std::max(1e-6 * e0.norm(), 1e-12)) << i;
    return still.p.history("yieldState")[0];
}

const char* const vonMises = "type vonMises; rho 2000; K 2e7; G 1e7; sigmaY 2e5;";
const char* const druckerPrager =
    "type druckerPrager; rho 2000; K 2e7; G 1e7; phi 30; psi 10; c 2e4; fit planeStrain;";
const char* const mohrCoulomb = "type mohrCoulomb; rho 2000; K 2e7; G 1e7; phi 30; psi 10; c 2e4;";

} // namespace

TEST(Objectivity, stressInsideTheSurfaceTurnsWithTheBody)
{
    const SymTensor s0(-1.0e5, -1.6e5, -1.2e5, 2.0e4);
    for (const char* m : {vonMises, druckerPrager, mohrCoulomb}) quarterTurn(m, s0, Start::inside);
}

TEST(Objectivity, stressOnTheSurfaceStaysOnItWhileTurning)
{
    // Return once without spin, then spin the returned (yield-surface) state.
    for (const char* m : {vonMises, druckerPrager, mohrCoulomb}) {
        Point onSurface(m, SymTensor(-1.0e5, -4.5e5, -2.0e5, 1.2e5));
        onSurface.step(0.0);
        ASSERT_GT(onSurface.p.history("yieldState")[0], 0.0) << m;
        quarterTurn(m, onSurface.p.sigma[0], Start::onSurface);
    }
}

TEST(Objectivity, stressThatYieldsInTheFirstStepEndsAsTheTurnedReturn)
{
    // Far outside every surface: the first step of the spin returns it.
    const SymTensor s0(-1.0e5, -6.0e5, -2.0e5, 1.5e5);
    for (const char* m : {vonMises, druckerPrager, mohrCoulomb}) quarterTurn(m, s0, Start::outside);
    // Onto a Mohr-Coulomb edge (4) and apex (3), and the Drucker-Prager apex.
    EXPECT_EQ(quarterTurn(mohrCoulomb, SymTensor(-3.0e5, -3.1e5, 0, 2.0e4), Start::outside), 4.0);
    EXPECT_EQ(quarterTurn(mohrCoulomb, SymTensor(8.0e4, 6.0e4, 7.0e4, 1.0e4), Start::outside), 3.0);
    EXPECT_EQ(quarterTurn(druckerPrager, SymTensor(8.0e4, 6.0e4, 7.0e4, 1.0e4), Start::outside), 3.0);
}
