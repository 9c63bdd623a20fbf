// Seed case 4.4 (after Sulsky et al. 1994): two elastic disks (rho 1000, E 1000 Pa, nu 0.3,
// diameter 0.4 m) collide without gravity on a 25 x 25 grid with 2 x 2 particles per cell.
// Exact statements checked: momentum of a freely translating disk is constant (no error
// from uniform translation through the grid, seed fig. 4.18); the total momentum of the
// pair is conserved; total energy (kinetic + stress work) stays within the seed's table 4.3
// bounds for each time step.
#include "support/CaseRunner.H"

#include <algorithm>
#include <cmath>

using namespace gpic::test;

namespace {

struct DiskRun {
    std::map<std::string, std::vector<double>> col;
};

DiskRun runDisks(const std::string& deltaT, const std::string& scheme, double endTime = 4,
                 const std::string& volumetricStrain = "particle")
{
    ScratchDir scratch("disks");
    const fs::path dir = scratch.path() / "twoDisks";
    copyCase(tutorialPath("verification/twoDisks"), dir);
    setEntry(dir / "system/controlDict", "deltaT", deltaT);
    setEntry(dir / "system/controlDict", "endTime", std::to_string(endTime));
    setEntry(dir / "system/controlDict", "writeInterval", "1");
    // Energy every 0.01 s whatever the step: enough to catch the extremes of the impact.
    const double dt = std::stod(deltaT);
    const auto every = std::max(1L, std::lround(0.01 / dt));
    replaceText(dir / "system/controlDict", "bodyMotion; writeInterval 10;",
                "bodyMotion; writeInterval " + std::to_string(every) + ";");
    setEntry(dir / "system/mpmSchemes", "updateScheme", scheme);
    setEntry(dir / "system/mpmSchemes", "volumetricStrain", volumetricStrain);
    runCase(dir);
    return {readColumns(dir / "postProcessing/motion/0/bodyMotion.dat")};
}

//- Largest |E(t) - E(0)| / E(0).
double energyError(const DiskRun& r)
{
    const auto& E = r.col.at("E");
    double worst = 0;
    for (double e : E) worst = std::max(worst, std::abs(e - E.front()) / E.front());
    return worst;
}

} // namespace

TEST(TwoDisks, momentumIsExactBeforeContactAndConservedInTotal)
{
    const DiskRun r = runDisks("1e-3", "USF");
    const auto& t = r.col.at("time");
    const double p0 = r.col.at("upperLeft:px").front();
    EXPECT_NEAR(p0, 0.1 * 316 * 0.02 * 0.02 * 1000, 1e-9);  // 316 particles of 0.4 kg/m
    for (std::size_t k = 0; k < t.size(); ++k) {
        // Total momentum of the pair: exactly zero (equal and opposite) at all times.
        EXPECT_NEAR(r.col.at("upperLeft:px")[k] + r.col.at("lowerRight:px")[k], 0.0, 1e-9 * p0) << "t = " << t[k];
        // Seed fig. 4.18: no change before contact at t = 1.30 s.
        if (t[k] < 1.25) {
            EXPECT_NEAR(r.col.at("upperLeft:px")[k], p0, 1e-9 * p0);
        }
        // The motion stays on the 45 degree line: px = -py.
        EXPECT_NEAR(r.col.at("upperLeft:px")[k], -r.col.at("upperLeft:py")[k], 1e-6 * p0);
    }
    // After separation the disk moves back with constant momentum, below its start value
    // (energy went into vibration) and reversed.
    const double pEnd = r.col.at("upperLeft:px").back();
    EXPECT_LT(pEnd, -0.9 * p0);
    EXPECT_GT(pEnd, -p0);
    for (std::size_t k = 0; k < t.size(); ++k)
        if (t[k] > 3.0) {
            EXPECT_NEAR(r.col.at("upperLeft:px")[k], pEnd, 1e-6 * p0);
        }
}

TEST(TwoDisks, energyErrorWithinSeedTable43AtDt1em3)
{
    EXPECT_LT(energyError(runDisks("1e-3", "USF")), 0.00208);  // seed: 0.208 %
}

TEST(TwoDisks, energyErrorWithinSeedTable43AtDt1em4)
{
    EXPECT_LT(energyError(runDisks("1e-4", "USF")), 0.00021);  // seed: 0.021 %
}

TEST(TwoDisks, energyErrorWithinSeedTable43AtDt1em5)
{
    EXPECT_LT(energyError(runDisks("1e-5", "USF")), 0.00002);  // seed: 0.002 %
}

TEST(TwoDisks, energyErrorFallsWithTheTimeStep)
{
    // First order in dt: the dissipation per step is dt^2 sum F^2/m (see the tutorial).
    const double e3 = energyError(runDisks("2e-3", "MUSL", 2.5));
    const double e4 = energyError(runDisks("2e-4", "MUSL", 2.5));
    EXPECT_LT(e4, 0.2 * e3);
}

// The cell's mean pressure in the nodal forces is the conjugate of its mean dilatation in the
// strain (schemes/CellMeanDilatation.H): the stress work then balances the kinetic energy as
// closely as without the means, and the error falls with dt. Had only the strain been
// averaged, energy would be made or lost at a rate that no time step removes.
TEST(TwoDisks, cellMeanDilatationConservesEnergyAsWell)
{
    const double e3 = energyError(runDisks("1e-3", "USF", 4, "cellMean"));
    EXPECT_LT(e3, 0.00208);  // seed table 4.3: 0.208 %
    const double coarse = energyError(runDisks("2e-3", "MUSL", 2.5, "cellMean"));
    const double fine = energyError(runDisks("2e-4", "MUSL", 2.5, "cellMean"));
    EXPECT_LT(fine, 0.2 * coarse);
}
