// The polar continuum reduces to the nonpolar one: with Gc = 0 and l = 0 the Cosserat stress
// is symmetric, no moment acts on the micro-rotation, and cosseratElastic (G, nu) must give
// the motion and stress of linearElastic (E = 2G(1 + nu)) to round-off; with small Gc and l
// the difference is small (seed 2.6, A11; de Borst 1991). A nonpolar scene holds no rotation
// array at all (its bytes per particle do not grow).
#include "planar/CosseratRotation.H"
#include "support/CaseRunner.H"

#include <algorithm>
#include <cmath>

using namespace gpic;
using namespace gpic::test;

namespace {

//- An elastic block on a rough base under gravity and a strip load at its left (symmetry)
//  edge: a non-uniform shear field. Fixed dt so that both models take the same steps.
void footingCase(const fs::path& dir, const std::string& material)
{
    writeDictionary(dir / "system/controlDict", "endTime 0.04; deltaT 2e-4; writeControl timeStep; writeInterval 100000;\n");
    writeDictionary(dir / "constant/grid", "origin (0 0); cellSize 0.02; nCells (20 12);\n"
                                           "boundaries { left { type symmetry; } right { type slip; } bottom { type fixed; } top { type free; } }\n");
    writeDictionary(dir / "constant/materials", "soil { " + material + " }\n");
    writeDictionary(dir / "constant/bodies", "soil { material soil; shape { type rectangle; min (0 0); max (0.4 0.2); } particlesPerCell 2; }\n");
    writeDictionary(dir / "constant/loads", "strip { type surfacePressure; body soil; from (0 0.2); to (0.1 0.2); pressure 20e3; rampTime 0.01; }\n");
    writeDictionary(dir / "constant/g", "value (0 -9.81);\n");
}

struct RunResult {
    Particles<2> particles;
    bool hasRotation = false;
    double bytesPerParticle = 0;
};

RunResult run(const std::string& material)
{
    ScratchDir scratch("cosseratReduction");
    const fs::path dir = scratch.path() / "case";
    footingCase(dir, material);
    auto simulation = runAndKeep(dir);
    return {simulation->solver().particles(), simulation->solver().find<CosseratRotation>() != nullptr,
            simulation->solver().bytesPerParticle()};
}

const char* const nonpolar = "type linearElastic; rho 2000; E 2.6e6; nu 0.3;";  // G = 1e6

//- Largest difference of position and stress, relative to the largest displacement and stress.
std::pair<double, double> difference(const Particles<2>& a, const Particles<2>& b)
{
    EXPECT_EQ(a.size(), b.size());
    double dx = 0, u = 0, ds = 0, s = 0;
    for (std::size_t q = 0; q < a.size(); ++q) {
        EXPECT_EQ(a.id[q], b.id[q]);
        dx = std::max(dx, (a.x[q] - b.x[q]).norm());
        u = std::max(u, (a.x[q] - a.x0[q]).norm());
        ds = std::max(ds, (a.sigma[q] - b.sigma[q]).cwiseAbs().maxCoeff());
        s = std::max(s, a.sigma[q].cwiseAbs().maxCoeff());
    }
    return {dx / u, ds / s};
}

} // namespace

TEST(CosseratReduction, aNonpolarSceneHasNoRotationArrays)
{
    const RunResult r = run(nonpolar);
    EXPECT_FALSE(r.hasRotation);
    EXPECT_FALSE(r.particles.carries(FieldGroup::polar));
    const CosseratParticles& c = r.particles.polar;
    EXPECT_EQ(c.w.capacity() + c.omega.capacity() + c.sigma21.capacity() + c.mu.capacity() + c.kappa.capacity() +
                  c.dRotation.capacity() + c.dKappa.capacity(),
              0u);
    const RunResult polar = run("type cosseratElastic; rho 2000; G 1e6; nu 0.3; Gc 0; l 0;");
    EXPECT_TRUE(polar.hasRotation);
    // The polar arrays are the only difference in memory: 3 doubles, 3 vectors and dRotation.
    EXPECT_NEAR(polar.bytesPerParticle - r.bytesPerParticle, 4 * sizeof(double) + 3 * sizeof(Eigen::Vector2d), 1.0);
}

TEST(CosseratReduction, zeroGcAndLengthGiveTheNonpolarElasticResult)
{
    const RunResult reference = run(nonpolar);
    const RunResult polar = run("type cosseratElastic; rho 2000; G 1e6; nu 0.3; Gc 0; l 0;");
    const auto [dx, ds] = difference(reference.particles, polar.particles);
    // Only the order of floating-point operations differs (G, nu against E, nu).
    EXPECT_LT(dx, 1e-9);
    EXPECT_LT(ds, 1e-9);
    for (std::size_t q = 0; q < polar.particles.size(); ++q) {
        EXPECT_EQ(polar.particles.polar.w[q], 0.0) << "no moment acts: the micro-rotation stays zero";
        EXPECT_NEAR(polar.particles.polar.sigma21[q], polar.particles.sigma[q][XY], 1e-9 * 2e4);
    }
}

TEST(CosseratReduction, smallGcAndLengthStayCloseToTheNonpolarResult)
{
    // Gc = 1e-4 G and l = 1 mm (cells of 20 mm): the polar terms change the response by a
    // fraction of order Gc/G; J33 is given (l^2/8 would make the rotation stiff in time).
    const RunResult reference = run(nonpolar);
    const RunResult polar = run("type cosseratElastic; rho 2000; G 1e6; nu 0.3; Gc 100; l 0.001; J33 1e-4;");
    const auto [dx, ds] = difference(reference.particles, polar.particles);
    std::printf("small Gc, l: position %.3e, stress %.3e of the response\n", dx, ds);
    EXPECT_LT(dx, 1e-3);
    EXPECT_LT(ds, 1e-3);
    // ... and the rotation is there: the polar terms are not switched off.
    double wMax = 0;
    for (double w : polar.particles.polar.w) wMax = std::max(wMax, std::abs(w));
    EXPECT_GT(wMax, 0.0);
}
