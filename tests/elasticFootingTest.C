// Seed case 4.8 on the coarse grid of tutorials/verification/elasticFooting (40 x 40 cells of
// 0.625 m over the 25 m half model): a smooth strip footing, P = 100 kPa on the half-width
// b = 1 m (a surfacePressure load), on a weightless elastic half-space, damped to rest.
// Poulos & Davis (seed eqs. 4.8.1-4.8.2), compression positive, at a point that sees the
// strip under beta = atan((x1 + b)/z) - atan((x1 - b)/z), delta = atan((x1 - b)/z):
//     sigma11 = P/pi [beta - sin(beta) cos(beta + 2 delta)]
//     sigma22 = P/pi [beta + sin(beta) cos(beta + 2 delta)]
//     sigma1,3 = P/pi (beta +- sin(beta))
// The stresses do not depend on E or nu; the strain does, so the compression of the
// centre column, int eps22 dz with plane-strain eps22 = [(1 - nu^2) sigma22 - nu (1 + nu)
// sigma11] / E, checks the elasticity.
#include "support/CaseRunner.H"

#include <cmath>

using namespace gpic;
using namespace gpic::test;

namespace {

const double P = 100e3, b = 1.0, E = 20e9, nu = 0.2, surface = 25.0;

//- Closed-form (sigma11, sigma22, sigma1, sigma3) [Pa], compression positive, at depth z.
std::array<double, 4> poulosDavis(double x1, double z)
{
    const double delta = std::atan2(x1 - b, z), beta = std::atan2(x1 + b, z) - delta;
    const double c = std::sin(beta) * std::cos(beta + 2 * delta);
    return {P / M_PI * (beta - c), P / M_PI * (beta + c), P / M_PI * (beta + std::sin(beta)),
            P / M_PI * (beta - std::sin(beta))};
}

//- Compression of the half-space between depths z1 < z2 along x1 (midpoint rule, 4000 panels).
double closedFormCompression(double x1, double z1, double z2)
{
    const int n = 4000;
    double sum = 0;
    for (int k = 0; k < n; ++k) {
        const auto s = poulosDavis(x1, z1 + (k + 0.5) * (z2 - z1) / n);
        sum += ((1 - nu * nu) * s[1] - nu * (1 + nu) * s[0]) / E;
    }
    return sum * (z2 - z1) / n;
}

} // namespace

TEST(ElasticFooting, principalStressesUnderTheFootingMatchPoulosAndDavis)
{
    ScratchDir scratch("elasticFooting");
    const fs::path dir = scratch.path() / "elasticFooting";
    copyCase(tutorialPath("verification/elasticFooting"), dir);
    setEntry(dir / "system/controlDict", "writeInterval", "0.1");
    const auto simulation = runAndKeep(dir);
    const Particles<2>& p = simulation->solver().particles();

    // The first column of particles, next to the symmetry plane, compared at its own x1.
    double x1 = surface;
    for (std::size_t q = 0; q < p.size(); ++q) x1 = std::min(x1, p.x0[q].x());
    double error = 0;
    std::size_t compared = 0, upper = 0, lower = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const double z = surface - p.x0[q].y();
        if (std::abs(p.x0[q].x() - x1) > 1e-9 || z < 0.5 || z > 6.0) continue;
        const SymTensor& s = p.sigma[q];
        const double centre = -0.5 * (s[XX] + s[YY]);
        const double radius = std::hypot(0.5 * (s[XX] - s[YY]), s[XY]);
        const auto exact = poulosDavis(p.x0[q].x(), z);
        error = std::max({error, std::abs(centre + radius - exact[2]), std::abs(centre - radius - exact[3])});
        if (compared == 0 || z < surface - p.x0[upper].y()) upper = q;
        if (compared == 0 || z > surface - p.x0[lower].y()) lower = q;
        ++compared;
    }
    ASSERT_EQ(compared, 17u);  // z = 0.78 ... 5.78 m in steps of 0.3125 m
    // Ladder of the tutorial (20, 40, 80, 160 cells): 22.9, 5.2, 3.8, ... % of P. On this grid
    // the error has two parts: the truncation of the half-space at 25 m, which shifts sigma3
    // by about -2.4 kPa at every depth (halved on a 50 m model), and the vertical strain that
    // bilinear cells hold constant over a cell height (sigma1 off by up to 4 % near z = 1 m).
    // The seed reports its results within 6 % of the closed form: so must this grid. A
    // pressure 3 % too high already fails it (sigma1 at z = 1.1 m would be off by 6.5 %).
    EXPECT_LT(error / P, 0.06);

    // The elasticity: the compression of the first column between the shallowest and the
    // deepest compared particles (z = 0.78 and 5.78 m). Measured 0.2 % off.
    const double settled = p.x[upper].y() - p.x0[upper].y() - (p.x[lower].y() - p.x0[lower].y());
    const double exact = closedFormCompression(x1, surface - p.x0[upper].y(), surface - p.x0[lower].y());
    EXPECT_NEAR(-settled / exact, 1.0, 0.03) << "compression " << -settled << " m, closed form " << exact;
    EXPECT_LT(simulation->solver().maxParticleSpeed(), 1e-6);  // at rest
}
