// A pass is a registered kind: a library the engine does not know (here this test, as a
// user's library in `libs` would) adds one with GPIC_REGISTER_PASS, says when a scene needs
// it, and the engine assembles it, calls it at its step points after its own passes, and
// takes its step limit.
#include "core/error.H"
#include "engine/EnginePass.H"
#include "engine/MpmSolver.H"
#include "run/Simulation.H"
#include "support/CaseRunner.H"

#include <gtest/gtest.h>

using namespace gpic;
using namespace gpic::test;

namespace {

//- A body force b per unit mass on every particle, as gravity is applied (eq. 2.3.9); on
//  only while `force` is set, so the other scenes of the test programme never assemble it.
class BodyForcePass : public EnginePass<2> {
public:
    static inline const Vector2* force = nullptr;
    static inline double stepLimit = 1e300;
    static inline int calls = 0;

    explicit BodyForcePass(PassScene<2>&) {}
    static bool needed(const PassScene<2>&) { return force != nullptr; }
    std::vector<StepPoint> points() const override { return {StepPoint::afterForces}; }
    double maxDeltaT(std::size_t, double, double) const override { return stepLimit; }
    std::string stepLimitName() const override { return "body force"; }
    void at(StepPoint, EngineView<2>& e, double) override
    {
        ++calls;
        const Particles<2>& p = e.particles;
        const ShapeWeights<2>& w = e.weights;
        const Vector2 b = *force;
        e.strips.forEach([&](std::size_t q) {
            for (int a = 0; a < w.stride; ++a) {
                const int n = w.node[q * w.stride + a];
                if (n >= 0) e.grid.fExt[n] += (w.N[q * w.stride + a] * p.m[q]) * b;
            }
        });
    }
};

GPIC_REGISTER_PASS(BodyForcePass, "testBodyForce")

//- An elastic block falling freely in a 1 m box, under gravity g; 1000 steps of 1e-4 s.
fs::path fallingBlock(const fs::path& dir, const std::string& g)
{
    writeDictionary(dir / "system/controlDict",
                    "endTime 0.1; deltaT 1e-4; writeControl runTime; writeInterval 0.1;\n"
                    "stabilityGuard { maxEnergyGain 1e30; }\n");
    writeDictionary(dir / "system/mpmSchemes", "updateScheme USL; shapeFunction bilinear; transfer FLIP;\n");
    writeDictionary(dir / "constant/grid", "origin (0 0); cellSize 0.05; nCells (20 20);\n"
                                           "boundaries { left { type free; } right { type free; } "
                                           "bottom { type free; } top { type free; } }\n");
    writeDictionary(dir / "constant/materials", "rubber { type linearElastic; rho 1000; E 1e6; nu 0.3; }\n");
    writeDictionary(dir / "constant/bodies", "block { material rubber; particlesPerCell 2; "
                                             "shape { type rectangle; min (0.4 0.6); max (0.6 0.8); } }\n");
    writeDictionary(dir / "constant/g", "value " + g + ";\n");
    return dir;
}

} // namespace

TEST(UserPass, aRegisteredPassActsAtItsStepPointAsGravityWould)
{
    ScratchDir scratch("userPass");
    const auto withGravity = runAndKeep(fallingBlock(scratch.path() / "gravity", "(0 -9.81)"));
    EXPECT_EQ(withGravity->solver().find<BodyForcePass>(), nullptr) << "assembled where not needed";

    const Vector2 g(0, -9.81);
    BodyForcePass::force = &g;
    BodyForcePass::calls = 0;
    const auto withPass = runAndKeep(fallingBlock(scratch.path() / "pass", "(0 0)"));
    BodyForcePass::force = nullptr;
    ASSERT_NE(withPass->solver().find<BodyForcePass>(), nullptr);
    EXPECT_EQ(BodyForcePass::calls, 1000);

    // The same sums into f_ext in the same order: the same run to the bit.
    const Particles<2>& a = withGravity->solver().particles();
    const Particles<2>& b = withPass->solver().particles();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t q = 0; q < a.size(); ++q) {
        ASSERT_EQ(a.x[q], b.x[q]) << "particle " << q;
        ASSERT_EQ(a.v[q], b.v[q]) << "particle " << q;
    }
    // And the physics: a free fall, y = y0 - g t_n t_{n+1} / 2 with the symplectic steps of
    // FLIP (v then x), to round-off.
    const double t = 0.1, dt = 1e-4;
    EXPECT_NEAR(b.x[0].y() - b.x0[0].y(), -0.5 * 9.81 * t * (t + dt), 1e-12);
}

TEST(UserPass, aPassesStepLimitBoundsTheEnginesStep)
{
    ScratchDir scratch("userPassStep");
    const fs::path dir = fallingBlock(scratch.path() / "case", "(0 0)");
    const Vector2 none(0, 0);
    BodyForcePass::force = &none;
    BodyForcePass::stepLimit = 3e-6;
    // A fixed step above the pass's limit is refused, naming it.
    std::string refused;
    try {
        initialisedSimulation(dir);
    } catch (const InputError& e) {
        refused = e.what();
    }
    EXPECT_NE(refused.find("above the stability limit 3e-06 s"), std::string::npos) << refused;
    EXPECT_NE(refused.find("or the body force's step 3e-06 s"), std::string::npos) << refused;
    // With the step adjusted, the pass's limit is the engine's (the elastic one, 0.05 m / c,
    // is about 1e-3 s).
    setEntry(dir / "system/controlDict", "adjustTimeStep", "yes");
    const auto simulation = initialisedSimulation(dir);
    const MpmSolver<2>& solver = simulation->solver();
    EXPECT_EQ(solver.passTimeStepName(), "body force");
    EXPECT_EQ(solver.criticalTimeStep(), 3e-6);
    BodyForcePass::force = nullptr;
    BodyForcePass::stepLimit = 1e300;
}
