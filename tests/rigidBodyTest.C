// Rigid bodies driven at a prescribed velocity (constant/rigidBodies), pushing material with
// the single-field (no-slip) contact of PIC, as the seed's blades and footings do.
// Case: tests/support/PistonCase.H.
#include "support/CaseRunner.H"
#include "support/PistonCase.H"

#include <cmath>

using namespace gpic::test;

namespace piston = gpic::test::piston;

TEST(RigidBody, aPistonCompressesABlockToTheUniaxialStrainStress)
{
    ScratchDir scratch("piston");
    const fs::path dir = piston::writeCase(scratch);
    const auto simulation = runAndKeep(dir);
    const gpic::Particles<2>& p = simulation->solver().particles();

    // delta = 0.02 m keeps the piston's particles in their first cell, so the block's
    // driven face stays the node line x = L.
    for (std::size_t q = 0; q < p.size(); ++q)
        if (p.body[q] == 1) {
            // The piston moved as one rigid piece, carrying no stress.
            EXPECT_NEAR(p.x[q].x(), p.x0[q].x() - piston::v * piston::T, 1e-12);
            EXPECT_NEAR(p.x[q].y(), p.x0[q].y(), 1e-12);
            EXPECT_EQ(p.sigma[q].norm(), 0.0);
        }
    const gpic::Vector2 mean = piston::meanBlockStress(p);
    const double s11 = piston::sigma11(), s22 = piston::sigma22();
    // 3 %: the wave launched by the sudden start (rho c v = 1.4 % of sigma11) is damped out.
    EXPECT_NEAR(mean.x(), s11, 0.03 * std::abs(s11));
    EXPECT_NEAR(mean.y(), s22, 0.03 * std::abs(s22));
}

TEST(RigidBody, anUnknownBodyInRigidBodiesListsTheBodies)
{
    ScratchDir scratch("pistonBad");
    const fs::path dir = piston::writeCase(scratch);
    std::ofstream(dir / "constant/rigidBodies") << "pistn { type fixed; }\n";
    try {
        initialisedSimulation(dir);
        FAIL() << "no error";
    } catch (const gpic::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("constant/rigidBodies:1:"), std::string::npos) << what;
        EXPECT_NE(what.find("valid choices: block, piston"), std::string::npos) << what;
    }
}
