// A rigid smooth footing held on an elastic half-space (seed case 4.8 as the seed loads it:
// tutorials/verification/elasticFooting, `./Allrun -rigid`, 40 x 42 cells of 0.625 m). The
// footing (half-width b = 1 m, one cell thick) is pushed down at 0.1 mm/s until the soil
// carries Q/2 = P b = 100 kN/m on the half model, then held while damping brings it to rest.
// The footing's edge (x1 = 1 m) lies inside a cell, so the node beyond it on the ground line
// (x1 = 1.25 m) is a contact node. The footing is smooth and its base flat: the contact may
// only push the soil down there. Closed form of a rigid smooth strip (Sadowsky's contact
// pressure p(s) = Q / (pi sqrt(b^2 - s^2)), Johnson 1985 "Contact Mechanics" eq. 2.64, each
// strip p ds a Flamant line load, eq. 2.15): with s = b sin(theta), p ds = Q dtheta / pi and
//     sigma22 = 2 q z^3 / (pi r^4),  sigma11 = 2 q (x1 - s)^2 z / (pi r^4),
//     sigma12 = 2 q (x1 - s) z^2 / (pi r^4),  r^2 = (x1 - s)^2 + z^2,  q = Q dtheta / pi.
// Near the surface these differ from the uniform pressure of Poulos & Davis (sigma1 at
// z = 0.5 m: 68 against 96 kPa); below z = 3 m the two agree within 1.3 % of P.
#include "normals/RigidSurface.H"
#include "dictionary/Dictionary.H"
#include "support/CaseRunner.H"

#include <cmath>
#include <map>

using namespace gpic;
using namespace gpic::test;

namespace {

const double P = 100e3, b = 1.0, surface = 25.0;

//- Closed-form (sigma1, sigma3) [Pa], compression positive, of the rigid smooth strip.
std::array<double, 2> rigidStrip(double x1, double z)
{
    const int n = 4000;  // midpoint rule in theta: smooth integrand for z > 0
    const double Q = 2 * b * P;
    double s11 = 0, s22 = 0, s12 = 0;
    for (int k = 0; k < n; ++k) {
        const double s = b * std::sin(-M_PI / 2 + (k + 0.5) * M_PI / n), q = Q / n;
        const double dx = x1 - s, r2 = dx * dx + z * z, c = 2 * q / (M_PI * r2 * r2);
        s22 += c * z * z * z;
        s11 += c * dx * dx * z;
        s12 += c * dx * z * z;
    }
    const double centre = 0.5 * (s11 + s22), radius = std::hypot(0.5 * (s11 - s22), s12);
    return {centre + radius, centre - radius};
}

//- The tutorial's -rigid set-up (its Allrun, make_rigid) on 40 cells.
fs::path writeRigidFootingCase(const ScratchDir& scratch)
{
    const fs::path dir = scratch.path() / "heldFooting";
    copyCase(tutorialPath("verification/elasticFooting"), dir);
    fs::remove(dir / "constant/loads");
    setEntry(dir / "constant/grid", "nCells", "(40 42)");
    std::ofstream(dir / "constant/materials", std::ios::app)
        << "steel { type linearElastic; rho 7850; E 200e9; nu 0.3; }\n";
    std::ofstream(dir / "constant/bodies", std::ios::app)
        << "footing { material steel; particlesPerCell 2; shape { type rectangle; min (0 25); max (1 25.625); } }\n";
    std::ofstream(dir / "constant/rigidBodies")
        << "footing { type prescribedVelocity; velocity (0 -1e-4); targetForce (0 100e3); }\n";
    std::ofstream(dir / "constant/contactProperties") << "law coulombFriction;\nnormals rigidSurface;\nmu 0;\n";
    setEntry(dir / "system/controlDict", "endTime", "0.3");
    setEntry(dir / "system/controlDict", "writeInterval", "0.3");
    replaceText(dir / "system/controlDict", "motion {", "forces { type forces; writeInterval 1; }\n    motion {");
    return dir;
}

} // namespace

// The node level with the footing's base just beyond its edge, soil below: the base's normal,
// whichever side of the base line the node lies (the footing pushed in by 1e-8 m or lifted)
// and however slightly the soil surface tilts. Where the soil wraps round the corner (its
// normal points at the corner) the corner's direction stays.
TEST(HeldFooting, aNodeBesideTheFootingEdgeTakesTheBaseNormal)
{
    RigidSurface footing(Dictionary::parse("type rectangle; min (0 -1e-8); max (1 0.625);", "constant/bodies"));
    const Vector2 base(0, -1);
    for (const double tilt : {0.0, -1e-9, -4e-6, -0.05, 0.05})
        for (const double y : {0.0, -2e-8}) {
            const Vector2 hint = Vector2(tilt, 1).normalized();  // the soil's outward normal
            EXPECT_NEAR((footing.outwardNormal(Vector2(1.25, y), hint) - base).norm(), 0, 1e-12)
                << "tilt " << tilt << ", node at y = " << y;
        }
    // Under the base itself: the base, with or without a hint.
    EXPECT_NEAR((footing.outwardNormal(Vector2(0.625, 0.0), Vector2(0, 1)) - base).norm(), 0, 1e-12);
    // Round the corner: soil below and beside the corner, its normal towards the corner.
    const Vector2 node(1.5, -0.25), corner = (node - Vector2(1, -1e-8)).normalized();
    EXPECT_NEAR((footing.outwardNormal(node, -corner) - corner).norm(), 0, 1e-12);
    // Beside the side face, soil beside it: the side face.
    EXPECT_NEAR((footing.outwardNormal(Vector2(1.25, 0.3), Vector2(-1, 0)) - Vector2(1, 0)).norm(), 0, 1e-12);
}

TEST(HeldFooting, aHeldSmoothFootingCarriesItsLoadSteadilyAndVertically)
{
    ScratchDir scratch("heldFooting");
    const fs::path dir = writeRigidFootingCase(scratch);
    const auto simulation = runAndKeep(dir);
    const Particles<2>& p = simulation->solver().particles();

    // The force on the footing, every step: once held (at 0.19 s) it stays at the target.
    auto forces = readColumns(dir / "postProcessing/forces/0/forces.dat");
    const auto& t = forces["time"];
    const auto& Fx = forces["footing:Fx"];
    const auto& Fy = forces["footing:Fy"];
    ASSERT_GT(t.size(), 1000u);
    ASSERT_NEAR(t.back(), 0.3, 1e-9);
    double fMin = Fy.back(), fMax = Fy.back(), sideways = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        sideways = std::max(sideways, std::abs(Fx[k]));
        if (t[k] < 0.25) continue;
        fMin = std::min(fMin, Fy[k]);
        fMax = std::max(fMax, Fy[k]);
    }
    // Measured 100 050.9 ... 100 051.0 N/m over the last 0.05 s.
    EXPECT_NEAR(fMin, P * b, 0.01 * P * b);
    EXPECT_NEAR(fMax, P * b, 0.01 * P * b);
    // Smooth (mu 0) and flat: no horizontal force at all. Measured 0; the node beyond the
    // edge holding the soil sideways gave 34.8 kN/m.
    EXPECT_LT(sideways, 1e-9 * P * b);

    // The soil carries what the footing reports: sigma22 summed across each particle row.
    std::map<long, double> rows;
    for (std::size_t q = 0; q < p.size(); ++q)
        if (p.body[q] == 0) rows[std::lround(p.x0[q].y() * 1e6)] -= p.sigma[q][YY] * 2 * p.halfSize[q].x();
    ASSERT_EQ(rows.size(), 80u);
    for (const auto& [y, load] : rows) EXPECT_NEAR(load, Fy.back(), 1e-3 * P * b) << "row y = " << y * 1e-6;

    // Principal stresses of the first particle column against the rigid strip, z = 0.5 ... 6 m.
    double x1 = surface;
    for (std::size_t q = 0; q < p.size(); ++q) x1 = std::min(x1, p.x0[q].x());
    double error1 = 0, error3 = 0, errorDeep = 0;
    int compared = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        const double z = surface - p.x0[q].y();
        if (p.body[q] != 0 || std::abs(p.x0[q].x() - x1) > 1e-9 || z < 0.5 || z > 6.0) continue;
        const SymTensor& s = p.sigma[q];
        const double centre = -0.5 * (s[XX] + s[YY]), radius = std::hypot(0.5 * (s[XX] - s[YY]), s[XY]);
        const auto exact = rigidStrip(p.x0[q].x(), z);
        error1 = std::max(error1, std::abs(centre + radius - exact[0]));
        error3 = std::max(error3, std::abs(centre - radius - exact[1]));
        if (z >= 3.0) errorDeep = std::max(errorDeep, std::abs(centre + radius - exact[0]));
        ++compared;
    }
    ASSERT_EQ(compared, 17);  // z = 0.78 ... 5.78 m
    // sigma3 (horizontal on the centre line): measured 2.7 % of P; with the soil held
    // sideways at the footing's edge it was 32 % (tension all down the centre line).
    EXPECT_LT(error3 / P, 0.05);
    // sigma1 below z = 3 m, where only the load counts: measured 3.5 %.
    EXPECT_LT(errorDeep / P, 0.05);
    // sigma1 near the footing: the nodes spread the contact over the cell beyond the edge
    // (the soil node at x1 = 1.25 m follows the footing), a footing about 1.5 m wide on
    // this grid: 18 % of P here, 2.8 % on the seed's 80 cells (tutorial README).
    EXPECT_LT(error1 / P, 0.25);
    EXPECT_LT(simulation->solver().maxParticleSpeed(), 1e-6);  // at rest
}
