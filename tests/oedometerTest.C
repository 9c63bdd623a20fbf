// Plane-strain oedometer on Mohr-Coulomb (seed Case 4.5, Table 4.4, App. H.5.4; after the
// FLAC verification problem). One material point is compressed in x2 with the sides held:
// d eps22 = V dt / L = -1e-5 per step (V = -10 m/s, dt = 1e-6 s, L = 1 m), d eps11 = d eps33 = 0.
// sigma22 is the most compressive stress and sigma11 = sigma33, so after yield the stress
// travels along the edge sigma2 = sigma3 of the Mohr-Coulomb pyramid. The closed form of
// H.5.4 is piecewise linear in eps22:
//     elastic:  sigma22 = alpha1 eps22, sigma11 = sigma33 = alpha2 eps22, up to
//               -eps22_y = 2c sqrt(N_phi) / (alpha1 - alpha2 N_phi)                 (eq. H.5.42)
//     plastic:  d sigma22 / d eps22 = alpha1 - 2 lambda (alpha1 - alpha2 N_psi),
//               lambda = (alpha1 - alpha2 N_phi) /
//                        ((alpha1 + alpha2) N_phi N_psi - 2 alpha2 (N_phi + N_psi) + 2 alpha1)  (eq. H.5.53)
//               sigma11 = sigma33 = (sigma22 + 2c sqrt(N_phi)) / N_phi.
// Both surfaces of the edge flow at once, so a return that handles the edge in closed form
// is exact for every step, including the one in which yield starts: the test asks for
// agreement to 1e-9 of the stress, far inside the seed's criterion (0.5 %). A return that
// corrects one surface per step (the seed's way) leaves sigma11 != sigma33 and fails.
#include "dictionary/Dictionary.H"
#include "materials/Material.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace gpic;

namespace {

struct ClosedForm {
    double K = 200e6, G = 200e6, c = 1e6, phiDeg = 10, psiDeg;
    double alpha1 = K + 4 * G / 3, alpha2 = K - 2 * G / 3;
    double Nphi = N(phiDeg), Npsi = N(psiDeg);
    double epsYield = 2 * c * std::sqrt(Nphi) / (alpha1 - alpha2 * Nphi);  // -eps22 at yield
    double lambda = (alpha1 - alpha2 * Nphi) /
                    ((alpha1 + alpha2) * Nphi * Npsi - 2 * alpha2 * (Nphi + Npsi) + 2 * alpha1);
    double slope = alpha1 - 2 * lambda * (alpha1 - alpha2 * Npsi);

    explicit ClosedForm(double psi) : psiDeg(psi) {}
    static double N(double deg)
    {
        const double s = std::sin(deg * M_PI / 180);
        return (1 + s) / (1 - s);
    }
    //- sigma22 at compression e = -eps22 >= 0
    double sigma22(double e) const
    {
        return e <= epsYield ? -alpha1 * e : -alpha1 * epsYield - slope * (e - epsYield);
    }
    double sigma11(double e) const
    {
        return e <= epsYield ? -alpha2 * e : (sigma22(e) + 2 * c * std::sqrt(Nphi)) / Nphi;
    }
};

struct Run {
    std::vector<double> e, s11, s22, s33, s12, state;
};

Run oedometer(double psiDeg)
{
    Dictionary d = Dictionary::parse("type mohrCoulomb; rho 2000; K 200e6; G 200e6; c 1e6; phi 10; psi " +
                                         std::to_string(psiDeg) + "; sigmaT 5.67e6;",
                                     "constant/materials/oedometer");
    auto m = Material<2>::New(d);
    Particles<2> p;
    p.add(Vector2::Zero(), m->rho(), 1.0, Vector2::Constant(0.5), 0, 0);  // packed: m = rho V
    m->declareFields(p);
    const double V = -10, dt = 1e-6, L = 1;
    Run r;
    for (int k = 1; k <= 3000; ++k) {
        p.dEps[0] = SymTensor(0, V * dt / L, 0, 0);  // eq. H.5.39
        p.dOmega[0] = 0;
        m->updateStress(p, {0, 1, 0}, dt);
        r.e.push_back(k * 1e-5);
        r.s11.push_back(p.sigma[0][XX]);
        r.s22.push_back(p.sigma[0][YY]);
        r.s33.push_back(p.sigma[0][ZZ]);
        r.s12.push_back(p.sigma[0][XY]);
        r.state.push_back(p.history("yieldState")[0]);
    }
    return r;
}

void expectClosedForm(double psiDeg, const std::vector<double>& reference)
{
    const ClosedForm exact(psiDeg);
    const Run r = oedometer(psiDeg);
    double worst = 0;
    for (std::size_t k = 0; k < r.e.size(); ++k) {
        const double e = r.e[k], scale = std::abs(exact.sigma22(e));
        worst = std::max(worst, std::abs(r.s22[k] - exact.sigma22(e)) / scale);
        ASSERT_NEAR(r.s22[k], exact.sigma22(e), 1e-9 * scale) << "-eps22 = " << e;
        ASSERT_NEAR(r.s11[k], exact.sigma11(e), 1e-9 * scale) << "-eps22 = " << e;
        // On the edge sigma11 = sigma33, and no shear appears.
        ASSERT_NEAR(r.s33[k], r.s11[k], 1e-9 * scale) << "-eps22 = " << e;
        ASSERT_EQ(r.s12[k], 0.0);
        // Elastic before yield, on the shear-shear edge after.
        ASSERT_EQ(r.state[k], e < exact.epsYield ? 0.0 : 4.0) << "-eps22 = " << e;
    }
    std::cout << "oedometer psi " << psiDeg << ": largest relative error of sigma22 " << worst
              << "; -sigma22 at 0.01/0.02/0.03: " << -r.s22[999] / 1e6 << " / " << -r.s22[1999] / 1e6
              << " / " << -r.s22[2999] / 1e6 << " MPa\n";
    // The seed-case numbers (seed-cases.md, Case 4.5), to their printed digits.
    EXPECT_NEAR(exact.epsYield, 0.006408, 5e-7);
    EXPECT_NEAR(-exact.sigma22(exact.epsYield) / 1e6, 2.990, 5e-4);
    EXPECT_NEAR(-r.s22[999] / 1e6, reference[0], 5e-3);
    EXPECT_NEAR(-r.s22[1999] / 1e6, reference[1], 5e-3);
    EXPECT_NEAR(-r.s22[2999] / 1e6, reference[2], 5e-3);
}

} // namespace

TEST(MohrCoulombOedometer, dilatantFlowFollowsTheClosedFormAlongTheEdge)
{
    expectClosedForm(10, {4.06, 7.03, 10.00});
}

TEST(MohrCoulombOedometer, nonDilatantFlowFollowsTheClosedFormAlongTheEdge)
{
    expectClosedForm(0, {3.89, 6.38, 8.87});
}
