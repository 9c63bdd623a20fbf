// Rigid bodies driven at a prescribed velocity (constant/rigidBodies), pushing material with
// the single-field (no-slip) contact of PIC, as the seed's blades and footings do.
// Case: an elastic block (L = 1 m, plane strain) in a smooth channel against a fixed wall,
// compressed by a rigid piston moving at v = 0.01 m/s. Slowly (v << c = 37 m/s) the block
// is in uniaxial strain eps11 = -delta/L with delta = v t, so (eq. H.2.1)
//     sigma11 = -(K + 4G/3) delta / L,   sigma22 = sigma33 = (K - 2G/3) / (K + 4G/3) sigma11.
#include "support/CaseRunner.H"

#include <cmath>

using namespace gpic::test;

namespace {

const double E = 1e6, nu = 0.3, L = 1.0, v = 0.01, T = 2.0;

fs::path writePistonCase(const ScratchDir& scratch)
{
    const fs::path dir = scratch.path() / "piston";
    fs::create_directories(dir / "system");
    fs::create_directories(dir / "constant");
    std::ofstream(dir / "system/controlDict")
        << "endTime " << T << ";\ndeltaT 1;\nadjustTimeStep yes;\nmaxCourant 0.5;\n"
        << "writeControl adjustableRunTime;\nwriteInterval 1;\ndamping 0.5;\n";
    std::ofstream(dir / "constant/grid")
        << "origin (0 0);\ncellSize 0.1;\nnCells (14 2);\n"
        << "boundaries { left { type fixed; } right { type free; } bottom { type slip; } top { type slip; } }\n";
    std::ofstream(dir / "constant/materials")
        << "soil { type linearElastic; rho 1000; E " << E << "; nu " << nu << "; }\n"
        << "steel { type linearElastic; rho 7850; E 2e11; nu 0.3; }\n";
    std::ofstream(dir / "constant/bodies")
        << "block { material soil; particlesPerCell 2; shape { type rectangle; min (0 0); max (" << L << " 0.2); } }\n"
        << "piston { material steel; particlesPerCell 2; shape { type rectangle; min (" << L
        << " 0); max (1.2 0.2); } }\n";
    std::ofstream(dir / "constant/rigidBodies") << "piston { type prescribedVelocity; velocity (" << -v << " 0); }\n";
    return dir;
}

} // namespace

TEST(RigidBody, aPistonCompressesABlockToTheUniaxialStrainStress)
{
    ScratchDir scratch("piston");
    const fs::path dir = writePistonCase(scratch);
    const auto simulation = runAndKeep(dir);
    const gpic::Particles& p = simulation->solver().particles();

    // delta = 0.02 m keeps the piston's particles in their first cell, so the block's
    // driven face stays the node line x = L.
    const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
    const double s11 = -(K + 4 * G / 3) * v * T / L, s22 = (K - 2 * G / 3) / (K + 4 * G / 3) * s11;
    double mean11 = 0, mean22 = 0;
    int nBlock = 0;
    for (std::size_t q = 0; q < p.size(); ++q) {
        if (p.body[q] == 1) {
            // The piston moved as one rigid piece, carrying no stress.
            EXPECT_NEAR(p.x[q].x(), p.x0[q].x() - v * T, 1e-12);
            EXPECT_NEAR(p.x[q].y(), p.x0[q].y(), 1e-12);
            EXPECT_EQ(p.sigma[q].norm(), 0.0);
            continue;
        }
        mean11 += p.sigma[q][gpic::XX];
        mean22 += p.sigma[q][gpic::YY];
        ++nBlock;
    }
    mean11 /= nBlock;
    mean22 /= nBlock;
    // 3 %: the wave launched by the sudden start (rho c v = 1.4 % of sigma11) is damped out.
    EXPECT_NEAR(mean11, s11, 0.03 * std::abs(s11));
    EXPECT_NEAR(mean22, s22, 0.03 * std::abs(s22));
}

TEST(RigidBody, anUnknownBodyInRigidBodiesListsTheBodies)
{
    ScratchDir scratch("pistonBad");
    const fs::path dir = writePistonCase(scratch);
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
