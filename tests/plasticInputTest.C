// Bad input to the plastic models: every mistake gives one InputError line that names the
// file and line of the offending keyword, the keyword itself and what would be valid. Also
// the Drucker-Prager report line and the two ways of giving elastic constants.
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "druckerPrager/DruckerPrager.H"
#include "materials/Material.H"
#include "plasticity/HardeningTable.H"
#include "support/MaterialInput.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace gpic;

namespace {

const char* const file = gpic::test::materialsFile;

std::unique_ptr<Material<2>> build(const std::string& entries) { return gpic::test::buildMaterial("sand", entries); }

void expectInputError(const std::string& entries, int line, const std::vector<std::string>& words)
{
    gpic::test::expectMaterialRefused("sand", entries, line, words);
}

const std::string elastic = "type mohrCoulomb; rho 2000; K 2e7; G 1e7;\n";  // line 4

} // namespace

TEST(PlasticInput, mohrCoulombAnglesOutOfRange)
{
    expectInputError(elastic + "c 0;\nphi 95;", 6, {"'phi'", "0 <= phi < 90"});
    expectInputError(elastic + "c 0; phi 10;\npsi 15;", 6, {"'psi'", "psi <= phi"});
    expectInputError(elastic + "c 0; phi 10;\npsi -1;", 6, {"'psi'"});
    expectInputError(elastic + "phi 10;\nc -5;", 6, {"'c'", "c >= 0"});
    expectInputError(elastic + "phi 30;", 2, {"'c'", "cTable"});  // missing: at the dictionary
    expectInputError(elastic + "phi 30; c 1e4;\nsigmaT 2e4;", 6, {"'sigmaT'", "c/tan(phi)", "17320.5"});
}

TEST(PlasticInput, mohrCoulombTables)
{
    expectInputError(elastic + "phi 30;\nc 1e4; cTable ((0 1e4) (0.1 0));", 6, {"'cTable'", "not both"});
    expectInputError(elastic + "phi 30;\ncTable ((0 1e4) (0 5e3));", 6, {"'cTable'", "increase"});
    expectInputError(elastic + "phi 30;\ncTable ((0 1e4 3));", 6, {"'cTable'", "pairs"});
    expectInputError(elastic + "c 0;\nphiTable ((0 30) (0.1 95));", 6, {"'phiTable'", "0 <= phi < 90"});
    expectInputError(elastic + "c 0; phiTable ((0 30) (0.1 20));\npsi 25;", 6, {"'psi'", "exceeds phi", "epsPs"});
    // Accepted: tables for all four.
    EXPECT_NO_THROW(build(elastic + "phiTable ((0 30) (0.1 25)); psiTable ((0 5) (0.1 0));\n"
                                    "cTable ((0 1e4) (0.05 0)); sigmaTTable ((0 1e3) (1e-3 0));"));
}

TEST(PlasticInput, elasticConstants)
{
    const std::string mc = "type mohrCoulomb; rho 2000; phi 30; c 0;\n";  // line 4
    expectInputError(mc + "E 1e7;\nnu 0.5;", 6, {"'nu'", "-1 < nu < 0.5"});
    expectInputError(mc + "E 1e7; nu 0.3;\nK 2e7;", 6, {"'K'", "E and nu, or K and G"});
    expectInputError(mc + "E 1e7;\nG 2e7;", 6, {"'G'", "not both"});
    expectInputError(mc, 2, {"'E'", "K and G"});
    expectInputError(mc + "K 2e7;\nG 0;", 6, {"'G'", "G > 0"});
    // E = 9KG/(3K + G), nu = (3K - 2G)/(2(3K + G)) give the same wave speed as K and G.
    const double K = 2e7, G = 1e7, E = 9 * K * G / (3 * K + G), nu = (3 * K - 2 * G) / (2 * (3 * K + G));
    std::ostringstream eNu;
    eNu << std::setprecision(17) << "E " << E << "; nu " << nu << ";";
    const auto a = build(mc + "K 2e7; G 1e7;"), b = build(mc + eNu.str());
    EXPECT_NEAR(a->waveSpeed(), std::sqrt((K + 4 * G / 3) / 2000), 1e-9);
    EXPECT_NEAR(b->waveSpeed(), a->waveSpeed(), 1e-9);
}

TEST(PlasticInput, druckerPragerAndVonMises)
{
    const std::string dp = "type druckerPrager; rho 2000; K 2e7; G 1e7;\n";  // line 4
    expectInputError(dp + "phi 30; c 0;\nfit circumscribed;", 6, {"'fit'", "outer, inner, planeStrain"});
    expectInputError(dp + "phi 30;\nc 0;", 2, {"'fit'", "outer, inner, planeStrain"});
    expectInputError(dp + "qPhi 0.5; kPhi 1e4;\nphi 30;", 6, {"'phi'", "not both"});
    expectInputError(dp, 2, {"'qPhi'", "phi, c and fit"});
    expectInputError(dp + "qPhi 0.5; kPhi 1e4;\nqPsi 0.6;", 6, {"'qPsi'", "qPsi <= qPhi"});
    expectInputError(dp + "qPhi 0.5; kPhi 1e4;\nsigmaT 3e4;", 6, {"'sigmaT'", "kPhi/qPhi", "20000"});
    expectInputError(dp + "phi 30; c 0; fit outer;\npsi 35;", 6, {"'psi'", "psi <= phi"});
    const std::string vm = "type vonMises; rho 2000; K 2e7; G 1e7;\n";
    expectInputError(vm + "sigmaY 1e5;\nH -1;", 6, {"'H'", "H >= 0"});
    expectInputError(vm + "H 1;", 2, {"'sigmaY'"});
}

TEST(PlasticInput, druckerPragerReportsItsFitOnOneLine)
{
    // Outer fit for phi = 30, c = 0: qPhi = 6 sin30 / (sqrt(3) (3 - sin30)) = 0.6928 (eq. H.6.1).
    ::testing::internal::CaptureStdout();
    const auto m = build("type druckerPrager; rho 2000; K 2e7; G 1e7; phi 30; c 0; fit outer;");
    const std::string out = ::testing::internal::GetCapturedStdout();
    EXPECT_NE(out.find("druckerPrager sand: outer fit to Mohr-Coulomb (phi 30, psi 0, c 0): "
                       "qPhi 0.6928 kPhi 0 qPsi 0\n"),
              std::string::npos) << out;
    const auto& dp = dynamic_cast<const DruckerPrager<2>&>(*m);
    EXPECT_NEAR(dp.qPhi(), 6 * 0.5 / (std::sqrt(3.0) * 2.5), 1e-15);
    EXPECT_EQ(dp.sigmaT(), 0.0);  // the apex kPhi/qPhi
}

TEST(PlasticInput, hardeningTableInterpolatesAndHoldsItsEnds)
{
    const Dictionary d = Dictionary::parse("t ((0.01 5) (0.03 1) (0.05 2));", file);
    const HardeningTable t(d, "t", [](double) { return true; }, "");
    EXPECT_EQ(t(-1), 5.0);
    EXPECT_EQ(t(0.01), 5.0);
    EXPECT_NEAR(t(0.02), 3.0, 1e-12);
    EXPECT_NEAR(t(0.04), 1.5, 1e-12);
    EXPECT_EQ(t(0.05), 2.0);
    EXPECT_EQ(t(9), 2.0);
}

TEST(PlasticInput, documentedExamplesBuild)
{
    // The dictionary examples of the model headers and doc/materials.md.
    for (const char* entries :
         {"type vonMises; rho 7850; E 200e9; nu 0.3; sigmaY 250e6; H 1e9;",
          "type druckerPrager; rho 1600; E 10e6; nu 0.3; phi 30; psi 0; c 0; fit inner;",
          "type druckerPrager; rho 1800; K 8e6; G 3e6; qPhi 0.2; kPhi 5e3; qPsi 0; sigmaT 1e3;",
          "type mohrCoulomb; rho 2000; K 200e6; G 200e6; phi 10; psi 10; c 1e6; sigmaT 5.67e6;",
          "type mohrCoulomb; rho 1800; E 20e6; nu 0.3; phi 30; cTable ((0 30e3) (0.05 10e3));"})
        EXPECT_NO_THROW(build(entries)) << entries;
}

TEST(PlasticInput, rhoDisconnectedBelowTheDensity)
{
    const std::string dp = "type druckerPrager; rho 2000; K 2e7; G 1e7; phi 30; c 0; fit planeStrain;\n";
    const std::string polar = "type cosseratDruckerPrager; rho 2000; G 1e7; nu 0.2; l 0.01; phi 30;\n";
    const std::string mc = "type mohrCoulomb; rho 2000; K 2e7; G 1e7; phi 30; c 0;\n";
    for (const std::string& model : {mc, dp, polar}) {
        expectInputError(model + "rhoDisconnected 2000;", 5, {"'rhoDisconnected'", "0 <= rhoDisconnected < rho (2000"});
        expectInputError(model + "rhoDisconnected -1;", 5, {"'rhoDisconnected'", "0 keeps the grains in contact"});
        EXPECT_NO_THROW(build(model + "rhoDisconnected 0;"));
    }
}
