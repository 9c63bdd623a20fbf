// Seed case 4.2 on the seed's grid (tutorials/verification/impact: 50 x 50 cells of 1.2 mm,
// 2 x 2 particles per cell, USF with uGIMP, automatic time step at maxCourant 0.25): a steel
// disk (d = 9.53 mm, elastic) hits a 6061-T6 aluminium target (von Mises, sigmaY = 300 MPa,
// no hardening) at 1160 m/s and stops in it within 80 us.
// Checks that the stiffest, fastest case of the seed runs stably on the automatic step, that
// the radial return keeps every target particle on or inside the yield surface, and the
// depth of penetration against the seed's 19 mm.
#include "io/ParticlesVtk.H"
#include "support/CaseRunner.H"

#include <cmath>

using namespace gpic;
using namespace gpic::test;

namespace {

//- von Mises stress sqrt(3 J2) with the out-of-plane component (plane strain, seed H.3.3).
double vonMises(const SymTensor& s)
{
    const double p = (s[XX] + s[YY] + s[ZZ]) / 3;
    const double J2 = 0.5 * ((s[XX] - p) * (s[XX] - p) + (s[YY] - p) * (s[YY] - p) + (s[ZZ] - p) * (s[ZZ] - p)) +
                      s[XY] * s[XY];
    return std::sqrt(3 * J2);
}

bool finite(const Vector2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

} // namespace

TEST(HighVelocityImpact, steelDiskStopsNear19mmWithTheTargetOnItsYieldSurface)
{
    const double sigmaY = 300e6, v0 = 1160;
    ScratchDir scratch("impact");
    const fs::path dir = scratch.path() / "impact";
    copyCase(tutorialPath("verification/impact"), dir);
    setEntry(dir / "system/controlDict", "writeInterval", "8e-6");  // ten states to inspect
    runCase(dir);

    // Every written state: finite positions, velocities and stresses, and the target (body 0)
    // within the yield surface. The return maps onto it exactly: the bound is round-off.
    int states = 0;
    double largest = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (!fs::exists(entry.path() / "particles.vtp")) continue;
        Particles<2> p;
        double time = 0;
        readParticles((entry.path() / "particles.vtp").string(), p, time);
        ++states;
        for (std::size_t q = 0; q < p.size(); ++q) {
            ASSERT_TRUE(finite(p.x[q]) && finite(p.v[q]) && p.sigma[q].allFinite())
                << "particle " << p.id[q] << " at t = " << time;
            if (p.body[q] == 0) largest = std::max(largest, vonMises(p.sigma[q]));
        }
    }
    EXPECT_EQ(states, 11);  // 0, 8, ..., 80 us
    EXPECT_LE(largest, sigmaY * (1 + 1e-9));
    EXPECT_GT(largest, 0.99 * sigmaY);  // the target did yield

    // Depth: the disk starts tangent to the target, so the penetration is the downward
    // displacement of its centre of mass (seed fig. 4.3).
    const auto motion = readColumns(dir / "postProcessing/motion/0/bodyMotion.dat");
    const auto& y = motion.at("disk:y");
    const double depth = (y.front() - y.back()) * 1e3;  // [mm]
    // The tutorial's ladder: 13.2, 19.0 and 22.0 mm on 25, 50 and 100 cells; on this grid the
    // update scheme and the Courant number move it between 18.3 and 19.4 mm (USF, MUSL, USL
    // with uGIMP; maxCourant 0.5 to 0.1); a yield stress 20 % off moves it by 2 to 3 mm.
    // Seed 19 mm (Sulsky & Schreyer 1993 on the same grid): within 1.5 mm. Measured 18.98 mm.
    EXPECT_NEAR(depth, 19.0, 1.5);
    // The disk has come to rest in the target (measured 1 m/s).
    EXPECT_LT(std::abs(motion.at("disk:vy").back()), 0.05 * v0);
}
