// picMaterialTest, the single material-point driver, run as a user runs it (a process on a
// scratch case): linear elasticity along each path against its closed form, objectivity of
// a rigid rotation, the files it writes, and one-line errors for bad input.
#include "support/Applications.H"
#include "support/CaseRunner.H"

#include <cmath>
#include <fstream>
#include <functional>

using namespace gpic::test;

namespace {

// The linear elastic material of these tests, E = 1e7 Pa, nu = 0.3 (seed eq. H.2.1, H.2.2).
const double E = 1e7, nu = 0.3;
const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
const double alpha1 = K + 4 * G / 3, alpha2 = K - 2 * G / 3;
const char* const elasticMaterials =
    "FoamFile { version 2.0; format ascii; class dictionary; object materials; }\n"
    "sand { type linearElastic; rho 2000; E 1e7; nu 0.3; }\n";

using Table = std::map<std::string, std::vector<double>>;

//- Columns of a picMaterialTest CSV by the names of its header row.
Table readCsv(const fs::path& file)
{
    std::ifstream in(file);
    EXPECT_TRUE(in.good()) << "cannot read " << file;
    std::vector<std::string> names;
    Table table;
    std::string line;
    for (bool header = true; std::getline(in, line); header = false) {
        std::istringstream cells(line);
        std::string cell;
        for (std::size_t c = 0; std::getline(cells, cell, ','); ++c) {
            if (header)
                names.push_back(cell);
            else if (c < names.size())
                table[names[c]].push_back(std::stod(cell));
        }
    }
    return table;
}

class MaterialDriver : public ::testing::Test {
protected:
    ScratchDir scratch{"materialDriver"};
    fs::path dir = scratch.path() / "point";

    void SetUp() override
    {
        fs::create_directories(dir / "system");
        fs::create_directories(dir / "constant");
        std::ofstream(dir / "constant/materials") << elasticMaterials;
    }

    //- Write system/materialTestDict with `tests` as the body of `tests { }`.
    void writeDict(const std::string& tests, const std::string& top = "material sand;\n")
    {
        std::ofstream(dir / "system/materialTestDict")
            << "FoamFile { version 2.0; format ascii; class dictionary; object materialTestDict; }\n"
            << top << "tests\n{\n" << tests << "}\n";
    }

    //- Run the driver; it must succeed.
    AppResult run()
    {
        const AppResult r = runApplication("picMaterialTest", dir);
        EXPECT_FALSE(r.signalled) << r.command;
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r;
    }

    Table result(const std::string& test) const
    {
        return readCsv(dir / "postProcessing/picMaterialTest" / (test + ".csv"));
    }

    //- The driver must refuse the dictionary: exit 1, one error line holding each of `mentions`.
    void expectRejected(const std::vector<std::string>& mentions)
    {
        const AppResult r = runApplication("picMaterialTest", dir);
        EXPECT_FALSE(r.signalled) << "crashed: " << r.command;
        EXPECT_EQ(r.exitCode, 1) << r.err;
        ASSERT_EQ(r.errorLines.size(), 1u) << "stderr should be one error line:\n" << r.err;
        const std::string& line = r.errorLines.front();
        EXPECT_EQ(line.rfind("Error: system/materialTestDict:", 0), 0u) << line;
        for (const auto& m : mentions)
            EXPECT_NE(line.find(m), std::string::npos) << "'" << m << "' is not in\n" << line;
    }
};

//- Largest |computed - exact| over the rows.
double maxDeviation(const std::vector<double>& computed, const std::function<double(std::size_t)>& exact)
{
    double worst = 0;
    for (std::size_t i = 0; i < computed.size(); ++i)
        worst = std::max(worst, std::abs(computed[i] - exact(i)));
    return worst;
}

} // namespace

TEST_F(MaterialDriver, linearElasticOedometerFollowsTheConstrainedModulus)
{
    // Only eps22 changes: sigma22 = (K + 4G/3) eps22, sigma11 = sigma33 = (K - 2G/3) eps22
    // (eq. H.2.1). Exact arithmetic but for rounding, so 1e-10 of the final stress.
    writeDict("oedometer { path oedometer; strain -0.03; steps 3000; }\n");
    run();
    Table t = result("oedometer");
    ASSERT_EQ(t["step"].size(), 3001u);
    EXPECT_NEAR(t["eps22"].back(), -0.03, 1e-14);
    const double scale = alpha1 * 0.03;
    const auto& e = t["eps22"];
    EXPECT_LE(maxDeviation(t["sigma22"], [&](std::size_t i) { return alpha1 * e[i]; }), 1e-10 * scale);
    EXPECT_LE(maxDeviation(t["sigma11"], [&](std::size_t i) { return alpha2 * e[i]; }), 1e-10 * scale);
    EXPECT_LE(maxDeviation(t["sigma33"], [&](std::size_t i) { return alpha2 * e[i]; }), 1e-10 * scale);
    EXPECT_LE(maxDeviation(t["eps11"], [](std::size_t) { return 0.0; }), 1e-15);
    EXPECT_LE(maxDeviation(t["sigma12"], [](std::size_t) { return 0.0; }), 1e-10 * scale);
}

TEST_F(MaterialDriver, linearElasticSimpleShearGivesGGammaAndTheJaumannRotation)
{
    // Without spin the shear stress is sigma12 = G gamma exactly. With the spin of simple
    // shear (w12 = gamma/2) the Jaumann rate gives sigma12 = G sin(gamma) and
    // sigma11 = -sigma22 = G (1 - cos(gamma)) (tension along the stretched diagonal's side);
    // the step error is O(d gamma) = 1e-5, so 1e-5 of G gamma. A wrong spin sign flips the
    // normal stresses (an error of 2.5e-2 of G gamma).
    writeDict("pure   { path simpleShear; gamma 0.05; steps 5000; spin no; }\n"
              "simple { path simpleShear; gamma 0.05; steps 5000; }\n");
    run();
    const double scale = G * 0.05;
    Table pure = result("pure");
    const auto& e = pure["eps12"];
    EXPECT_NEAR(2 * e.back(), 0.05, 1e-14);
    EXPECT_LE(maxDeviation(pure["sigma12"], [&](std::size_t i) { return G * 2 * e[i]; }), 1e-10 * scale);
    EXPECT_LE(maxDeviation(pure["sigma11"], [](std::size_t) { return 0.0; }), 1e-10 * scale);
    EXPECT_LE(maxDeviation(pure["sigma22"], [](std::size_t) { return 0.0; }), 1e-10 * scale);

    Table simple = result("simple");
    const auto& g = simple["eps12"];
    EXPECT_LE(maxDeviation(simple["sigma12"], [&](std::size_t i) { return G * std::sin(2 * g[i]); }),
              1e-5 * scale);
    EXPECT_LE(maxDeviation(simple["sigma11"], [&](std::size_t i) { return G * (1 - std::cos(2 * g[i])); }),
              1e-5 * scale);
    EXPECT_LE(maxDeviation(simple["sigma22"], [&](std::size_t i) { return -G * (1 - std::cos(2 * g[i])); }),
              1e-5 * scale);
}

TEST_F(MaterialDriver, linearElasticBiaxialHoldsTheConfiningStressAndFollowsThePlaneStrainClosedForm)
{
    // sigma11 is held at -c while eps22 is imposed and eps33 = 0. From the consolidated start
    // (isotropic -c) d sigma11 = 0 gives d eps11 = -(alpha2/alpha1) d eps22, so
    //   sigma22 = -c + (alpha1 - alpha2^2/alpha1) eps22,  sigma33 = -c + alpha2 (eps11 + eps22).
    // From a zero start the first step jumps to sigma11 = -c:
    //   eps11 = (-c - alpha2 eps22)/alpha1,  sigma22 = alpha2 eps11 + alpha1 eps22.
    // The iteration tolerance is 1e-10 of the largest stress; the closed forms hold to 1e-9.
    // A general path driving sigma11 = sigma22 to -c (isotropic in-plane compression) ends at
    // eps11 = eps22 = -c/(alpha1 + alpha2).
    const double c = 100e3;
    writeDict("consolidated { path biaxial; strain -0.05; confining 100e3; steps 5000; }\n"
              "fromZero { path biaxial; strain -0.05; confining 100e3; steps 5000; "
              "initialStress (0 0 0 0); }\n"
              "isotropic { path general; sigma11 -100e3; sigma22 -100e3; steps 100; }\n");
    const AppResult r = run();
    EXPECT_NE(r.out.find("consolidated (sand, biaxial, 5000 steps): sigma = ("), std::string::npos) << r.out;

    Table t = result("consolidated");
    const auto &e11 = t["eps11"], &e22 = t["eps22"];
    const double scale = c + alpha1 * 0.05;
    EXPECT_NEAR(e22.back(), -0.05, 1e-14);
    EXPECT_LE(maxDeviation(t["sigma11"], [&](std::size_t) { return -c; }), 1e-10 * scale);
    EXPECT_LE(maxDeviation(e11, [&](std::size_t i) { return -alpha2 / alpha1 * e22[i]; }), 1e-9 * 0.05);
    EXPECT_LE(maxDeviation(t["sigma22"],
                           [&](std::size_t i) { return -c + (alpha1 - alpha2 * alpha2 / alpha1) * e22[i]; }),
              1e-9 * scale);
    EXPECT_LE(maxDeviation(t["sigma33"], [&](std::size_t i) { return -c + alpha2 * (e11[i] + e22[i]); }),
              1e-9 * scale);

    Table z = result("fromZero");
    const auto &z11 = z["eps11"], &z22 = z["eps22"];
    for (std::size_t i = 1; i < z11.size(); ++i) {
        ASSERT_NEAR(z["sigma11"][i], -c, 1e-10 * scale) << "step " << i;
        ASSERT_NEAR(z11[i], (-c - alpha2 * z22[i]) / alpha1, 1e-9 * 0.05) << "step " << i;
        ASSERT_NEAR(z["sigma22"][i], alpha2 * z11[i] + alpha1 * z22[i], 1e-9 * scale) << "step " << i;
    }

    Table iso = result("isotropic");
    const double eIso = -c / (alpha1 + alpha2);
    EXPECT_NEAR(iso["sigma11"].back(), -c, 1e-10 * c);
    EXPECT_NEAR(iso["sigma22"].back(), -c, 1e-10 * c);
    EXPECT_NEAR(iso["eps11"].back(), eIso, 1e-9 * std::abs(eIso));
    EXPECT_NEAR(iso["eps22"].back(), eIso, 1e-9 * std::abs(eIso));
    EXPECT_NEAR(iso["sigma33"].back(), 2 * alpha2 * eIso, 1e-9 * c);
}

TEST_F(MaterialDriver, rigidRotationByNinetyDegreesTurnsTheStressAndKeepsItsInvariants)
{
    // An anticlockwise quarter turn, no strain: sigma' = R sigma R^T, so sigma11 and sigma22
    // swap, sigma12 changes sign and sigma33, p and q stay (1e-6 relative, the objectivity
    // requirement; a first-order Jaumann update would miss it by 2 %).
    writeDict("turn { path rotation; angle 90; steps 100; initialStress (-3e5 -1e5 -1.2e5 4e4); }\n");
    run();
    Table t = result("turn");
    const double scale = 3e5;
    ASSERT_EQ(t["step"].size(), 101u);
    EXPECT_NEAR(t["sigma11"].back(), -1e5, 1e-6 * scale);
    EXPECT_NEAR(t["sigma22"].back(), -3e5, 1e-6 * scale);
    EXPECT_NEAR(t["sigma12"].back(), -4e4, 1e-6 * scale);
    // Half way, at 45 degrees, the sense shows: anticlockwise gives sigma11 = (s11 + s22)/2 - s12
    // = -2.4e5, sigma22 = -1.6e5 and sigma12 = (s11 - s22)/2 = -1e5 (clockwise: -1.6e5, -2.4e5).
    EXPECT_NEAR(t["sigma11"][50], -2.4e5, 1e-6 * scale);
    EXPECT_NEAR(t["sigma22"][50], -1.6e5, 1e-6 * scale);
    EXPECT_NEAR(t["sigma12"][50], -1e5, 1e-6 * scale);
    const double p0 = t["p"][0], q0 = t["q"][0];
    EXPECT_NEAR(p0, (3e5 + 1e5 + 1.2e5) / 3, 1e-9 * scale);
    EXPECT_LE(maxDeviation(t["p"], [&](std::size_t) { return p0; }), 1e-6 * scale);
    EXPECT_LE(maxDeviation(t["q"], [&](std::size_t) { return q0; }), 1e-6 * scale);
    EXPECT_LE(maxDeviation(t["sigma33"], [](std::size_t) { return -1.2e5; }), 1e-6 * scale);
    const double det0 = -3e5 * -1e5 - 4e4 * 4e4;  // of the in-plane stress
    double worstDet = 0;
    for (std::size_t i = 0; i < t["step"].size(); ++i)
        worstDet = std::max(worstDet, std::abs(t["sigma11"][i] * t["sigma22"][i] -
                                               t["sigma12"][i] * t["sigma12"][i] - det0));
    EXPECT_LE(worstDet, 1e-6 * scale * scale);
    EXPECT_LE(maxDeviation(t["eps11"], [](std::size_t) { return 0.0; }), 1e-15);
}

TEST_F(MaterialDriver, writesTheCsvAndThePlotOfEveryTestAndASummaryLine)
{
    writeDict("short { path oedometer; strain -0.001; steps 10; }\n"
              "spin  { path general; eps11 0.001; sigma22 -1e3; angle 10; steps 20; }\n");
    const AppResult r = run();
    for (const char* test : {"short", "spin"}) {
        SCOPED_TRACE(test);
        const fs::path out = dir / "postProcessing/picMaterialTest";
        const std::string csv = readText(out / (std::string(test) + ".csv"));
        EXPECT_EQ(csv.substr(0, csv.find('\n')),
                  "step,eps11,eps22,eps12,sigma11,sigma22,sigma33,sigma12,p,q");
        const std::string png = readText(out / (std::string(test) + ".png"));
        ASSERT_GT(png.size(), 1000u) << "no plot (is gnuplot installed?)";
        EXPECT_EQ(png.substr(1, 3), "PNG");
        // One summary line with the final stress and the wall time, then the files.
        const auto at = r.out.find(std::string(test) + " (sand, ");
        ASSERT_NE(at, std::string::npos) << r.out;
        const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
        EXPECT_NE(line.find("sigma = ("), std::string::npos) << line;
        EXPECT_NE(line.find(", wall "), std::string::npos) << line;
        EXPECT_NE(r.out.find((out / (std::string(test) + ".csv")).string()), std::string::npos) << r.out;
    }
    EXPECT_EQ(readCsv(dir / "postProcessing/picMaterialTest/spin.csv")["step"].size(), 21u);
}

TEST_F(MaterialDriver, badInputIsOneLineNamingTheKeyword)
{
    writeDict("a { path triaxial; strain -0.01; steps 10; }\n");
    expectRejected({":5:", "'path'", "'triaxial'", "oedometer, biaxial, simpleShear, rotation, general"});
    writeDict("a { path oedometer; steps 10; }\n");
    expectRejected({":5:", "'strain'", "undefined"});
    writeDict("a { path biaxial; strain -0.01; confining -5; steps 10; }\n");
    expectRejected({":5:", "'confining'", "confining >= 0"});
    writeDict("a { path oedometer; strain -0.01; steps 0; }\n");
    expectRejected({":5:", "'steps'", "1 <= steps"});
    writeDict("a { path general; eps11 0.01; sigma11 -5; steps 10; }\n");
    expectRejected({":5:", "sigma11", "not both"});
    writeDict("a { path oedometer; strain -0.01; steps 10; }\n", "material clay;\n");
    expectRejected({":2:", "'clay'", "valid choices: sand"});
    writeDict("a { path oedometer; strain -0.01; steps 10; }\n",
              "material { type linearElastic; rho 1; E 1e6; nu 0.7; }\n");
    expectRejected({":2:", "'nu'", "-1 < nu < 0.5"});
    writeDict("a { path oedometer; strain -0.01; steps 10; initialStress (0 0 0); }\n");
    expectRejected({":5:", "initialStress", "four"});
    EXPECT_FALSE(fs::exists(dir / "postProcessing/picMaterialTest/a.csv"));
}

TEST_F(MaterialDriver, aGeneralPathWithBackGoesOutOverHalfTheStepsAndReturns)
{
    // Linear elastic, eps11 out to 0.01 and sigma22 driven to -10 kPa over 50 steps, then
    // both back to their start over 50: at the turn eps11 = 0.01 and sigma22 = -10 kPa; at
    // the end the strain and every stress are zero again (to rounding). Odd steps cannot turn.
    writeDict("loop { path general; eps11 0.01; sigma22 -1e4; back yes; steps 100; }\n");
    run();
    Table t = result("loop");
    ASSERT_EQ(t["step"].size(), 101u);
    EXPECT_NEAR(t["eps11"][50], 0.01, 1e-15);
    EXPECT_NEAR(t["sigma22"][50], -1e4, 1e-10 * 1e4 + 1e-6);
    // sigma22 held: eps22 = (sigma22 - alpha2 eps11) / alpha1 at the turn.
    EXPECT_NEAR(t["eps22"][50], (-1e4 - alpha2 * 0.01) / alpha1, 1e-9);
    EXPECT_NEAR(t["eps11"].back(), 0.0, 1e-15);
    for (const char* c : {"sigma11", "sigma22", "sigma33", "sigma12"})
        EXPECT_NEAR(t[c].back(), 0.0, 1e-6 * alpha1 * 0.01) << c;
    writeDict("loop { path general; eps11 0.01; back yes; steps 99; }\n");
    expectRejected({":5:", "'steps'", "even", "back"});
}

TEST_F(MaterialDriver, aStressThatCannotBeHeldStopsTheRunWithExitStatus2)
{
    // Von Mises, sigmaY = 100 kPa, no hardening: in pure shear the point yields at
    // sigma12 = sigmaY/sqrt(3) = 57.7 kPa, so a target of 80 kPa (reached linearly over 100
    // steps) fails at step 73 (58.4 kPa): one line naming the test, step and component.
    writeDict("tooMuch { path general; sigma12 80e3; steps 100; }\n",
              "material { type vonMises; rho 1; E 20e6; nu 0.3; sigmaY 100e3; H 0; }\n");
    const AppResult r = runApplication("picMaterialTest", dir);
    EXPECT_FALSE(r.signalled) << r.command;
    EXPECT_EQ(r.exitCode, 2) << r.err;
    ASSERT_EQ(r.errorLines.size(), 1u) << r.err;
    for (const char* m : {"Error: run stopped: ", "'tooMuch'", "step 73", "sigma12"})
        EXPECT_NE(r.errorLines.front().find(m), std::string::npos) << m << " is not in " << r.err;
}

TEST(MaterialDriverTutorial, mohrCoulombOedometerFollowsTheClosedFormOfH54)
{
    // tutorials/materials/oedometerPoint, seed case 4.5 (Table 4.4: K = G = 200 MPa, c = 1 MPa,
    // phi = 10 deg, psi = 10 and 0 deg; eps22 to -0.03 in 3000 steps). Appendix H.5.4:
    // elastic, -sigma22 = alpha1 e with e = -eps22, up to e_y = 2 c sqrt(N_phi)/(alpha1 -
    // alpha2 N_phi) = 0.006408; then flow along the edge sigma11 = sigma33 with slope
    // alpha1 - 2 lambda (alpha1 - alpha2 N_psi) and sigma11 = (sigma22 + 2 c sqrt(N_phi))/N_phi.
    // The seed's curves agree with it to plotting accuracy; 0.5 % here (measured: 3e-12, the
    // CSV's rounding, since the edge return is exact).
    ScratchDir scratch("oedometerPoint");
    const fs::path dir = scratch.path() / "oedometerPoint";
    copyCase(tutorialPath("materials/oedometerPoint"), dir);
    const AppResult r = runApplication("picMaterialTest", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;

    const double Kmc = 200e6, Gmc = 200e6, c = 1e6, phi = 10 * M_PI / 180;
    const double a1 = Kmc + 4 * Gmc / 3, a2 = Kmc - 2 * Gmc / 3;
    auto flowFactor = [](double angle) { return (1 + std::sin(angle)) / (1 - std::sin(angle)); };
    const double Nphi = flowFactor(phi);
    const double eY = 2 * c * std::sqrt(Nphi) / (a1 - a2 * Nphi);
    EXPECT_NEAR(eY, 0.006408, 1e-6);  // the reference number of seed-cases.md

    const std::pair<std::string, double> tests[] = {{"associated", 10.0}, {"nonAssociated", 0.0}};
    for (const auto& [test, psiDeg] : tests) {
        SCOPED_TRACE(test);
        const double Npsi = flowFactor(psiDeg * M_PI / 180);
        const double lambda =
            (a1 - a2 * Nphi) / ((a1 + a2) * Nphi * Npsi - 2 * a2 * (Nphi + Npsi) + 2 * a1);
        const double slope = a1 - 2 * lambda * (a1 - a2 * Npsi);
        auto exact22 = [&](double e) { return e <= eY ? -a1 * e : -(a1 * eY + slope * (e - eY)); };
        Table t = readCsv(dir / "postProcessing/picMaterialTest" / (test + ".csv"));
        ASSERT_EQ(t["step"].size(), 3001u);
        double worst22 = 0, worst11 = 0;
        for (std::size_t i = 1; i < t["step"].size(); ++i) {
            const double e = -t["eps22"][i], s22 = exact22(e);
            worst22 = std::max(worst22, std::abs(t["sigma22"][i] - s22) / std::abs(s22));
            const double s11 = e <= eY ? -a2 * e : (s22 + 2 * c * std::sqrt(Nphi)) / Nphi;
            worst11 = std::max(worst11, std::abs(t["sigma11"][i] - s11) / std::abs(s11));
        }
        EXPECT_LT(worst22, 0.005);
        EXPECT_LT(worst11, 0.005);
        // The seed's reference number at -eps22 = 0.03: -sigma22 = 10.00 (psi 10) and 8.87 MPa (psi 0).
        EXPECT_NEAR(-t["sigma22"].back() / 1e6, psiDeg > 0 ? 10.00 : 8.87, 0.01);
    }
}

// An axisymmetric ring's point: the hoop strain eps33 alone, in the elastic range of every
// built-in non-polar model, gives sigma33 = (K + 4G/3) eps33 and sigma11 = sigma22 =
// (K - 2G/3) eps33 (eq. H.2.1 with de33); the same models in plane strain keep eps33 = 0.
TEST_F(MaterialDriver, theHoopStrainOfAnAxisymmetricRingLoadsEveryModelThroughItsElasticConstants)
{
    std::ofstream(dir / "constant/materials")
        << "FoamFile { version 2.0; format ascii; class dictionary; object materials; }\n"
           "elastic { type linearElastic; rho 2000; E 1e7; nu 0.3; }\n"
           "metal   { type vonMises; rho 2000; E 1e7; nu 0.3; sigmaY 1e9; }\n"
           "corn    { type druckerPrager; rho 2000; E 1e7; nu 0.3; qPhi 0.4; kPhi 1e9; qPsi 0; }\n"
           "sand    { type mohrCoulomb; rho 2000; E 1e7; nu 0.3; phi 30; c 1e9; }\n"
           "beads   { type muI; rho 2000; E 1e7; nu 0.3; muS 1; mu2 2; I0 0.3; d 1e-3; rhoS 2600; rhoC 1900; }\n";
    for (const char* material : {"elastic", "metal", "corn", "sand", "beads"}) {
        SCOPED_TRACE(material);
        writeDict("hoop { path general; eps33 -0.001; steps 10; }\n", std::string("material ") + material + ";\n");
        run();
        Table t = result("hoop");
        const double e = -0.001, scale = alpha1 * 0.001;
        EXPECT_NEAR(t["sigma33"].back(), alpha1 * e, 1e-9 * scale);
        EXPECT_NEAR(t["sigma11"].back(), alpha2 * e, 1e-9 * scale);
        EXPECT_NEAR(t["sigma22"].back(), alpha2 * e, 1e-9 * scale);
        EXPECT_NEAR(t["sigma12"].back(), 0.0, 1e-9 * scale);
    }
}

#if GPIC_WITH_3D
TEST_F(MaterialDriver, threeDTriaxialMohrCoulombFailsAtThePassiveRatioAndTheOedometerIsThePlaneOne)
{
    // geometry threeD: the 3D model. A Mohr-Coulomb point (phi 30, psi 0, c 0) compressed
    // axially with its lateral stresses held at -100 kPa (the triaxial test) fails at
    // sigma22 = -100 kPa (1 + sin phi) / (1 - sin phi) = -300 kPa and stays there (to 1e-6);
    // the 3D oedometer ends where the plane one does (its two lateral stresses alike, 1e-9),
    // and a 3D general path controls a stress out of the plane (sigma33 held at -50 kPa).
    std::ofstream(dir / "constant/materials")
        << "FoamFile { version 2.0; format ascii; class dictionary; object materials; }\n"
           "sand { type mohrCoulomb; rho 2000; E 1e7; nu 0.3; phi 30; psi 0; c 0; }\n";
    const std::string tests = "triaxial { path biaxial; strain -0.03; confining 100e3; steps 3000; }\n"
                              "oedometer { path oedometer; strain -0.01; steps 1000; }\n"
                              "general { path general; eps22 -0.001; sigma33 -50e3; eps23 0.0002; steps 100; }\n";
    writeDict(tests, "material sand;\ngeometry threeD;\n");
    run();
    const Table triaxial = result("triaxial"), solid = result("oedometer"), general = result("general");
    ASSERT_EQ(triaxial.at("sigma22").size(), 3001u);
    ASSERT_TRUE(triaxial.count("sigma23") && triaxial.count("eps33")) << "the 3D columns";
    EXPECT_NEAR(triaxial.at("sigma22").back(), -300e3, 0.3);
    EXPECT_NEAR(triaxial.at("sigma11").back(), -100e3, 1e-4);
    EXPECT_NEAR(triaxial.at("sigma33").back(), -100e3, 1e-4);
    EXPECT_NEAR(general.at("sigma33").back(), -50e3, 1e-4);
    EXPECT_GT(std::abs(general.at("sigma23").back()), 1.0) << "eps23 imposed: a shear stress out of the plane";

    writeDict("oedometer { path oedometer; strain -0.01; steps 1000; }\n", "material sand;\n");
    run();
    const Table plane = result("oedometer");
    for (const char* s : {"sigma11", "sigma22", "sigma33"})
        EXPECT_NEAR(solid.at(s).back(), plane.at(s).back(), 1e-9 * std::abs(plane.at("sigma22").back())) << s;
    EXPECT_NEAR(solid.at("sigma11").back(), solid.at("sigma33").back(), 1e-9 * std::abs(plane.at("sigma22").back()));
}
#endif
