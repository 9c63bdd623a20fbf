// The rate-dependent granular material muI (muI/MuI.H; Dunatunga & Kamrin 2015 with the mu(I)
// rheology of Jop, Forterre & Pouliquen 2006):
// - the return's closed-form root of tau^2 - B tau + H = 0 against a bisection of
//   tau = p mu(I(tau)) over pressures, trial stresses, moduli and steps (to 1e-12 relative),
//   and the root lies in [muS p, min(mu2 p, tauTr)];
// - a point sheared at a set rate (the shear without its rigid spin, so that the deviator
//   keeps its axes) reaches tau/p = mu(I) of the imposed rate, I = gammaDot d sqrt(rhoS/p),
//   to 1e-9 relative, at I from 0.01 to 2, in plane strain and in 3D, and reports that I and
//   gammaDotP = gammaDot;
// - a point that dilates loses its stress (separated, then below rhoC disconnected) and,
//   compressed back, is elastic again with the stress of the compression taken since its
//   density passed rhoC (to 1e-9 relative), in plane strain and in 3D;
// - bad parameters give one-line errors naming file, line and keyword.
#include "core/error.H"
#include "dictionary/Dictionary.H"
#include "materials/Material.H"
#include "muI/MuI.H"
#include "plasticity/InertialRheology.H"
#include "plasticity/StressInvariants.H"
#include "plasticity/YieldState.H"

#include "support/MaterialInput.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace gpic;

namespace {

// Glass beads (MuI.H), soft, with 5 mm grains.
const double rho = 1500, rhoS = 2450, rhoC = 1485, E = 1e7, nu = 0.3, d = 5e-3;
const double muS = 0.3819, mu2 = 0.6435, I0 = 0.278;
const std::string beads = "type muI; rho 1500; E 1e7; nu 0.3; muS 0.3819; mu2 0.6435; I0 0.278; "
                          "d 5e-3; rhoS 2450; rhoC 1485;";

const InertialRheology rheology{muS, mu2, I0, d, rhoS};

//- tau with tau = p mu(I), I = (tauTr - tau) d sqrt(rhoS/p) / (G dt), by bisection on
//  [muS p, tauTr], where tau - p mu(I(tau)) rises from below zero to above it.
double bisectReturn(double p, double tauTr, double G, double dt)
{
    const auto residual = [&](double tau) {
        const double I = (tauTr - tau) / (G * dt) * d * std::sqrt(rhoS / p);
        return tau - p * rheology.mu(I);
    };
    double low = muS * p, high = tauTr;
    for (int k = 0; k < 200 && high - low > 1e-15 * high; ++k) {
        const double mid = 0.5 * (low + high);
        (residual(mid) < 0 ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

//- One material point of dimension D at its material's density, driven by increments.
template <int D> struct Point {
    using SymTensor = typename Space<D>::SymTensor;
    std::unique_ptr<Material<D>> material;
    Particles<D> p;
    explicit Point(const std::string& entries)
    {
        material = Material<D>::New(Dictionary::parse(entries, "constant/materials/beads"));
        p.add(Space<D>::Vector::Zero(), material->rho(), 1.0, Space<D>::Vector::Constant(0.5), 0, 0);
        material->declareFields(p);
    }
    //- A strain increment without spin; the volume follows its diagonal.
    void step(const SymTensor& de, double dt)
    {
        p.dEps[0] = de;
        double J = 1;
        for (int c : {XX, YY, ZZ}) J *= 1.0 + de[c];
        p.V[0] *= J;
        material->updateStress(p, ParticleBlock{0, 1, 0}, dt);
    }
    double history(const char* name) const { return p.history(name)[0]; }
    double density() const { return p.m[0] / p.V[0]; }
};

template <int D> typename Space<D>::SymTensor isotropic(double sigma)
{
    typename Space<D>::SymTensor s = Space<D>::SymTensor::Zero();
    for (int c : {XX, YY, ZZ}) s[c] = sigma;
    return s;
}

//- Shear at a set rate from an isotropic pressure p0: returns the worst relative error of
//  tau/p against mu(I(gammaDot)), and of the reported I and gammaDotP, over the rates.
template <int D> void shearAtSetRates()
{
    const double p0 = 1e3, dt = 1e-6;
    double worst = 0;
    for (double I : {0.01, 0.1, 0.278, 1.0, 2.0}) {
        const double gammaDot = I / (d * std::sqrt(rhoS / p0));
        SCOPED_TRACE("I = " + std::to_string(I));
        Point<D> point(beads);
        point.p.sigma[0] = isotropic<D>(-p0);
        typename Space<D>::SymTensor de = Space<D>::SymTensor::Zero();
        de[XY] = 0.5 * gammaDot * dt;
        // Elastic loading to mu2 p0 takes mu2 p0 / (G gammaDot); the viscous relaxation
        // after it is far shorter (eta/G with eta = p dmu/dgammaDot).
        const double G = E / (2 * (1 + nu));
        const int steps = static_cast<int>(3.0 * mu2 * p0 / (G * gammaDot * dt)) + 2000;
        for (int n = 0; n < steps; ++n) point.step(de, dt);
        const auto& s = point.p.sigma[0];
        const double p = -meanStress(s), tau = shearStress(s);
        EXPECT_NEAR(p, p0, 1e-9 * p0);  // the flow is isochoric and the pressure elastic
        EXPECT_NEAR(tau / p, rheology.mu(I), 1e-9 * rheology.mu(I));
        EXPECT_NEAR(std::abs(s[XY]), tau, 1e-9 * tau);  // the deviator keeps its axes
        EXPECT_EQ(point.history("yieldState"), code(YieldState::shear));
        EXPECT_NEAR(point.history("I"), I, 1e-9 * I);
        EXPECT_NEAR(point.history("gammaDotP"), gammaDot, 1e-9 * gammaDot);
        worst = std::max(worst, std::abs(tau / p - rheology.mu(I)) / rheology.mu(I));
    }
    std::cout << "D = " << D << ": worst relative error of tau/p against mu(I): " << worst << "\n";
}

//- Dilate from p0 until the density is below rhoC, then compress back by as much: the stress
//  goes (separated, disconnected), and on the way back the point is elastic again with the
//  stress of the compression taken since its density passed rhoC.
template <int D> void dilateAndRecompress()
{
    using SymTensor = typename Space<D>::SymTensor;
    const double p0 = 1e3, dt = 1e-5, e = 1e-4;
    const int steps = 200;  // two volumetric 1e-4 a step: J = 0.96 of rho/rhoC = 0.99
    Point<D> point(beads);
    point.p.sigma[0] = isotropic<D>(-p0);
    SymTensor de = SymTensor::Zero();
    de[XX] = de[YY] = e;

    bool separated = false, disconnected = false;
    for (int n = 0; n < steps; ++n) {
        point.step(de, dt);
        const double state = point.history("yieldState");
        if (point.density() < rhoC) {
            EXPECT_EQ(state, code(YieldState::disconnected)) << "step " << n;
            disconnected = true;
        } else if (state == code(YieldState::tension)) {
            separated = true;
        }
        if (state != code(YieldState::elastic)) {
            EXPECT_TRUE(point.p.sigma[0].isZero(0)) << "step " << n;
        }
    }
    EXPECT_TRUE(separated) << "the trial should turn tensile before the density passes rhoC";
    EXPECT_TRUE(disconnected);

    // Back: the elastic stress of the strain taken from the first step at rho >= rhoC.
    SymTensor taken = SymTensor::Zero();
    bool reconnected = false;
    for (int n = 0; n < steps; ++n) {
        // The test of the material, m < rhoC V, on the volume after the step.
        const bool connectedAfter = !(point.p.m[0] < rhoC * (point.p.V[0] * ((1.0 - e) * (1.0 - e))));
        point.step(-de, dt);
        if (connectedAfter) {
            reconnected = true;
            taken -= de;
            EXPECT_EQ(point.history("yieldState"), code(YieldState::elastic)) << "step " << n;
        } else {
            EXPECT_EQ(point.history("yieldState"), code(YieldState::disconnected)) << "step " << n;
        }
    }
    ASSERT_TRUE(reconnected);
    const auto& muI = dynamic_cast<const MuI<D>&>(*point.material);
    SymTensor expected = SymTensor::Zero();
    muI.elastic().addElasticIncrement(expected, taken);
    const auto& s = point.p.sigma[0];
    double worst = 0;
    for (int c = 0; c < Space<D>::nSym; ++c) {
        EXPECT_NEAR(s[c], expected[c], 1e-9 * std::abs(expected[XX])) << "component " << c;
        worst = std::max(worst, std::abs(s[c] - expected[c]) / std::abs(expected[XX]));
    }
    std::cout << "D = " << D << ": re-formed at p = " << -meanStress(s) << " Pa, error " << worst << "\n";
    EXPECT_GT(-meanStress(s), 0.0);
    EXPECT_LE(shearStress(s), muS * -meanStress(s));
}

void expectInputError(const std::string& entries, int line, const std::vector<std::string>& words)
{
    gpic::test::expectMaterialRefused("beads", entries, line, words);
}

} // namespace

TEST(MuIMaterial, returnIsTheRootOfTheDirectSolve)
{
    int checked = 0;
    double worst = 0;
    for (double p : {10.0, 1e3, 1e5, 1e7})
        for (double over : {1.0001, 1.05, 1.5, 3.0, 30.0, 1e3})
            for (double G : {1e5, 1e7, 1e9})
                for (double dt : {1e-7, 1e-5, 1e-3}) {
                    const double tauTr = over * muS * p;
                    const double tau = rheology.returnedShear(p, tauTr, G, dt);
                    const double direct = bisectReturn(p, tauTr, G, dt);
                    worst = std::max(worst, std::abs(tau - direct) / direct);
                    EXPECT_NEAR(tau, direct, 1e-12 * direct) << "p " << p << " tauTr " << tauTr << " G " << G << " dt " << dt;
                    EXPECT_GE(tau, muS * p * (1 - 1e-15));
                    EXPECT_LE(tau, std::min(mu2 * p, tauTr) * (1 + 1e-15));
                    ++checked;
                }
    EXPECT_EQ(checked, 216);
    std::cout << "worst relative difference from the bisection: " << worst << "\n";
}

TEST(MuIMaterial, inverseOfTheFrictionLaw)
{
    for (double I : {1e-4, 0.01, 0.278, 3.0, 100.0})
        EXPECT_NEAR(rheology.inertialNumberOf(rheology.mu(I)), I, 1e-9 * I);
    EXPECT_DOUBLE_EQ(rheology.mu(I0), 0.5 * (muS + mu2));
}

TEST(MuIMaterial, shearAtSetRatesFollowsTheFrictionLawPlane) { shearAtSetRates<2>(); }
TEST(MuIMaterial, dilatedPointSeparatesAndReconsolidatesPlane) { dilateAndRecompress<2>(); }
#if GPIC_WITH_3D
TEST(MuIMaterial, shearAtSetRatesFollowsTheFrictionLaw3D) { shearAtSetRates<3>(); }
TEST(MuIMaterial, dilatedPointSeparatesAndReconsolidates3D) { dilateAndRecompress<3>(); }
#endif

TEST(MuIMaterial, belowMuSItIsElastic)
{
    Point<2> point(beads);
    point.p.sigma[0] = isotropic<2>(-1e3);
    Space<2>::SymTensor de = Space<2>::SymTensor::Zero();
    de[XY] = 1e-5;  // tau = 2G de = 77 Pa < muS p = 382 Pa
    point.step(de, 1e-4);
    EXPECT_EQ(point.history("yieldState"), code(YieldState::elastic));
    EXPECT_DOUBLE_EQ(point.p.sigma[0][XY], 2 * E / (2 * (1 + nu)) * 1e-5);
    EXPECT_EQ(point.history("gammaDotP"), 0.0);
}

TEST(MuIMaterial, badParameters)
{
    const std::string elastic = "type muI; rho 1500; E 1e7; nu 0.3;\n";  // line 4
    const std::string rest = "I0 0.278; d 5e-3; rhoS 2450; rhoC 1485;";
    expectInputError(elastic + "muS 0.4;\nmu2 0.3; " + rest, 6, {"'mu2'", "mu2 > muS"});
    expectInputError(elastic + "muS 0.4;\nmu2 0.4; " + rest, 6, {"'mu2'", "mu2 > muS"});
    expectInputError(elastic + "\nmuS -0.1; mu2 0.3; " + rest, 6, {"'muS'", "muS >= 0"});
    expectInputError(elastic + "muS 0.38; mu2 0.64;\nI0 0; d 5e-3; rhoS 2450; rhoC 1485;", 6, {"'I0'", "I0 > 0"});
    expectInputError(elastic + "muS 0.38; mu2 0.64; I0 0.278;\nd -1; rhoS 2450; rhoC 1485;", 6, {"'d'", "d > 0"});
    expectInputError(elastic + "muS 0.38; mu2 0.64; I0 0.278; d 5e-3;\nrhoS 1400; rhoC 1300;", 6,
                     {"'rhoS'", "rhoS > rho (1500"});
    expectInputError(elastic + "muS 0.38; mu2 0.64; I0 0.278; d 5e-3; rhoS 2450;\nrhoC 1600;", 6,
                     {"'rhoC'", "rhoC <= rho (1500"});
    expectInputError(elastic + "muS 0.38; mu2 0.64; I0 0.278; d 5e-3; rhoS 2450;\nrhoC 0;", 6, {"'rhoC'"});
    expectInputError(elastic + "muS 0.38; mu2 0.64; I0 0.278; rhoS 2450; rhoC 1485;", 2, {"'d'"});  // missing
}
