// The four models of both dimensions driven in 3D (issue: materials in 3D, the 2D layout a
// prefix of the 3D one):
// - the seed's Mohr-Coulomb oedometer (Case 4.5, App. H.5.4) as a 3D point compressed along
//   x3, and along an oblique axis, against the closed form of oedometerTest (to 1e-9: the
//   edge return is exact in every step);
// - a 3D point on a plane-strain path (no out-of-plane strain) gives the plane model's
//   stress: to the bit for the elastic increment, to round-off for the returns;
// - isotropy: a strain path and its rotation give rotated stresses (the 3D principal
//   stresses and their axes, the returns, the 3D Jaumann rotation);
// - the 3D Jaumann rotation of a rigid spin keeps the invariants and turns the stress.
#include "dictionary/Dictionary.H"
#include "materials/JaumannRate.H"
#include "materials/Material.H"
#include "plasticity/PrincipalStresses.H"
#include "plasticity/StressInvariants.H"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace gpic;
using Tensor3 = Space<3>::SymTensor;
using Tensor2 = Space<2>::SymTensor;

namespace {

const std::string mohrCoulomb = "type mohrCoulomb; rho 2000; K 200e6; G 200e6; c 1e6; phi 10; psi 5;";
const std::string weakMohrCoulomb = "type mohrCoulomb; rho 2000; K 200e6; G 200e6; c 1e4; phi 30; psi 5;";
const std::string druckerPrager = "type druckerPrager; rho 2000; K 200e6; G 200e6; phi 30; psi 10; c 1e5; fit inner;";
const std::string vonMises = "type vonMises; rho 7850; K 160e9; G 80e9; sigmaY 250e6; H 1e9;";
const std::string elastic = "type linearElastic; rho 2000; E 1e7; nu 0.3;";

//- One material point of dimension D, driven by strain increments.
template <int D> struct Point {
    std::unique_ptr<Material<D>> material;
    Particles<D> p;
    explicit Point(const std::string& dict)
    {
        const Dictionary d = Dictionary::parse(dict, "constant/materials/soil");
        material = Material<D>::New(d);
        // Of its material's density: a point lighter than rhoDisconnected carries no stress.
        p.add(Space<D>::Vector::Zero(), material->rho(), 1.0, Space<D>::Vector::Constant(0.5), 0, 0);
        material->declareFields(p);
    }
    const typename Space<D>::SymTensor& step(const typename Space<D>::SymTensor& de)
    {
        p.dEps[0] = de;  // no spin: dOmega stays zero
        material->updateStress(p, ParticleBlock{0, 1, 0}, 1e-6);
        return p.sigma[0];
    }
};

Eigen::Matrix3d full(const Tensor3& s)
{
    Eigen::Matrix3d S;
    S << s[XX], s[XY], s[XZ], s[XY], s[YY], s[YZ], s[XZ], s[YZ], s[ZZ];
    return S;
}

Tensor3 voigt(const Eigen::Matrix3d& S)
{
    Tensor3 s;
    s << S(0, 0), S(1, 1), S(2, 2), S(0, 1), S(1, 2), S(0, 2);
    return s;
}

//- The closed form of the oedometer (oedometerTest.C, seed eq. H.5.42, H.5.53): the axial and
//  lateral stresses at compression e.
struct Oedometer {
    double K = 200e6, G = 200e6, c = 1e6, phi = 10, psi = 5;
    double a1 = K + 4 * G / 3, a2 = K - 2 * G / 3;
    double Nphi = N(phi), Npsi = N(psi);
    double eYield = 2 * c * std::sqrt(Nphi) / (a1 - a2 * Nphi);
    double lambda = (a1 - a2 * Nphi) / ((a1 + a2) * Nphi * Npsi - 2 * a2 * (Nphi + Npsi) + 2 * a1);
    double slope = a1 - 2 * lambda * (a1 - a2 * Npsi);
    static double N(double deg)
    {
        const double s = std::sin(deg * M_PI / 180);
        return (1 + s) / (1 - s);
    }
    double axial(double e) const { return e <= eYield ? -a1 * e : -a1 * eYield - slope * (e - eYield); }
    double lateral(double e) const { return e <= eYield ? -a2 * e : (axial(e) + 2 * c * std::sqrt(Nphi)) / Nphi; }
};

} // namespace

TEST(ThreeDMohrCoulomb, oedometerAlongX3AndAlongAnObliqueAxisFollowsTheClosedForm)
{
    const Oedometer exact;
    const Eigen::Vector3d axes[2] = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d(1, -2, 2).normalized()};
    for (const Eigen::Vector3d& n : axes) {
        Point<3> point(mohrCoulomb);
        const Eigen::Matrix3d nn = n * n.transpose();
        const double de = 1e-5;
        double worst = 0;
        for (int k = 1; k <= 1500; ++k) {  // past yield (at 6.4e-3) to 1.5e-2
            const Eigen::Matrix3d S = full(point.step(voigt(-de * nn)));
            const double e = k * de;
            const Eigen::Matrix3d expected = exact.lateral(e) * Eigen::Matrix3d::Identity() + (exact.axial(e) - exact.lateral(e)) * nn;
            worst = std::max(worst, (S - expected).norm() / std::abs(exact.axial(e)));
        }
        EXPECT_LT(worst, 1e-9) << "axis " << n.transpose();
        EXPECT_EQ(point.p.history("yieldState")[0], 4.0) << "the edge sigma2 = sigma3";
    }
}

TEST(ThreeDMaterials, aPlaneStrainPathGivesThePlaneModelsStress)
{
    for (const std::string& dict : {elastic, weakMohrCoulomb, druckerPrager, vonMises}) {
        Point<2> plane(dict);
        Point<3> solid(dict);
        const double scale = dict == vonMises ? 2e-4 : 1e-4;
        for (int k = 0; k < 60; ++k) {
            const double t = 0.1 * k;
            const Tensor2 de2(scale * std::cos(t), -scale * (0.5 + std::sin(t)), 0.0, 0.3 * scale * std::sin(2 * t));
            Tensor3 de3 = Tensor3::Zero();
            de3.head<4>() = de2;
            const Tensor2 s2 = plane.step(de2);
            const Tensor3 s3 = solid.step(de3);
            if (dict == elastic) {
                EXPECT_EQ(s3.head<4>(), s2) << "step " << k;  // the same sums, to the bit
            } else {
                EXPECT_LT((s3.head<4>() - s2).norm(), 1e-9 * s2.norm() + 1e-6) << dict << " step " << k;
            }
            EXPECT_EQ(s3[YZ], 0.0);
            EXPECT_EQ(s3[XZ], 0.0);
        }
    }
}

TEST(ThreeDMaterials, aRotatedStrainPathGivesTheRotatedStress)
{
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    for (const std::string& dict : {elastic, weakMohrCoulomb, druckerPrager, vonMises}) {
        Point<3> straight(dict), turned(dict);
        const double scale = dict == vonMises ? 2e-4 : 1e-4;
        double worst = 0, largest = 0;
        for (int k = 0; k < 80; ++k) {
            const double t = 0.13 * k;
            Tensor3 de;
            de << scale * std::cos(t), -scale * (0.6 + std::sin(t)), -0.4 * scale, 0.3 * scale * std::sin(2 * t),
                0.2 * scale * std::cos(3 * t), -0.1 * scale;
            const Eigen::Matrix3d S = full(straight.step(de));
            const Eigen::Matrix3d T = full(turned.step(voigt(R * full(de) * R.transpose())));
            worst = std::max(worst, (T - R * S * R.transpose()).norm());
            largest = std::max(largest, S.norm());
        }
        EXPECT_LT(worst, 1e-9 * largest) << dict;
        if (dict != elastic) {
            EXPECT_GT(straight.p.history("epsPs")[0], 0.0) << dict << ": the path must yield";
        }
    }
}

TEST(ThreeDJaumann, aRigidSpinTurnsTheStressAndKeepsItsInvariants)
{
    Tensor3 s;
    s << -3.0, -1.0, -2.0, 0.5, 0.25, -0.75;
    // A spin about e3 alone is the plane rotation, on the in-plane block.
    Tensor3 about3 = s;
    rotateJaumann(about3, Space<3>::Spin(0.3, 0.0, 0.0));
    Tensor2 plane = s.head<4>();
    rotateJaumann(plane, 0.3);
    EXPECT_LT((about3.head<4>() - plane).norm(), 1e-14);
    // W23 = pi/2 turns x2 onto x3: sigma22 and sigma33 trade places (R = exp(W)).
    Tensor3 quarter = s;
    rotateJaumann(quarter, Space<3>::Spin(0.0, M_PI / 2, 0.0));
    EXPECT_NEAR(quarter[YY], s[ZZ], 1e-14);
    EXPECT_NEAR(quarter[ZZ], s[YY], 1e-14);
    EXPECT_NEAR(quarter[XX], s[XX], 1e-14);
    // Any spin keeps the invariants.
    Tensor3 turned = s;
    rotateJaumann(turned, Space<3>::Spin(0.4, -0.2, 0.9));
    EXPECT_NEAR(meanStress(turned), meanStress(s), 1e-14);
    EXPECT_NEAR(secondInvariant(turned), secondInvariant(s), 1e-13);
    EXPECT_NEAR(full(turned).determinant(), full(s).determinant(), 1e-13);
}

TEST(ThreeDPrincipalStresses, nearADoubleRootTheValuesAndAxesAreExactToRoundOff)
{
    // The 3D principal stresses near a double root (a body at rest: equal lateral stresses;
    // the edges of a Mohr-Coulomb pyramid), where the closed form alone loses the pair to
    // 1e-8, and away from it: the values against Eigen's iterative solver and the stress
    // rebuilt from the values on the axes, both to 1e-13 of the stress, the axes orthonormal;
    // over gaps of 0 ... 1e-4 of the stress and no pair, random orientations, scales from
    // 1 Pa to 1 GPa.
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    double worstValue = 0, worstRebuild = 0, worstFrame = 0;
    for (int k = 0; k < 20000; ++k) {
        const double scale = std::pow(10.0, 9.0 * (0.5 + 0.5 * uniform(random)));
        const double a = uniform(random), other = uniform(random);
        const double gap = k % 5 == 0 ? 0.0 : std::pow(10.0, -4.0 - 12.0 * (0.5 + 0.5 * uniform(random)));
        const Eigen::Vector3d axis(uniform(random), uniform(random), uniform(random));
        const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI * uniform(random), axis.normalized()).toRotationMatrix();
        const Eigen::Vector3d diagonal = k % 3 == 0 ? Eigen::Vector3d(a, other, uniform(random))  // no pair at all
                                         : k % 2    ? Eigen::Vector3d(a, a + gap, other)
                                                    : Eigen::Vector3d(other, a, a + gap);
        const Eigen::Matrix3d S = scale * R * diagonal.asDiagonal() * R.transpose();
        Tensor3 s;
        s << S(0, 0), S(1, 1), S(2, 2), S(0, 1), S(1, 2), S(0, 2);
        const PrincipalStresses<3> principal(s);
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> iterative(S);
        const double size = S.cwiseAbs().maxCoeff();
        worstValue = std::max(worstValue, (principal.values() - iterative.eigenvalues()).cwiseAbs().maxCoeff() / size);
        worstRebuild = std::max(worstRebuild, (principal.tensor(principal.values()) - s).cwiseAbs().maxCoeff() / size);
        Eigen::Matrix3d frame;
        frame << principal.axis(0), principal.axis(1), principal.axis(2);
        worstFrame = std::max(worstFrame, (frame.transpose() * frame - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worstValue, 1e-13);
    EXPECT_LT(worstRebuild, 1e-13);
    EXPECT_LT(worstFrame, 1e-13);
}
