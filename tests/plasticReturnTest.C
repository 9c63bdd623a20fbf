// Return mapping of the plastic models, checked point by point against plasticity theory:
// after a return the stress lies on the yield surface (every yield function <= 0, one = 0),
// the plastic strain increment is a non-negative combination of the potential gradients of
// the surfaces it ended on, and the stress change is the elastic response to that plastic
// strain, sigma_N = sigma_I - D : dEpsP. Trials are drawn at random around each surface, in
// every region (main plane, edges, tension, apex); each model's own classification is not
// trusted, the test works the geometry out again from the returned state. Also: elastic
// trials are left untouched, Drucker-Prager with qPhi = 0 is von Mises, Mohr-Coulomb with
// phi = 0 is Tresca, and a softening table acts one step late.
#include "dictionary/Dictionary.H"
#include "materials/Material.H"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <map>
#include <random>
#include <sstream>

using namespace gpic;

namespace {

constexpr double degree = M_PI / 180;

std::unique_ptr<Material<2>> material(const std::string& entries)
{
    Dictionary d = Dictionary::parse(entries, "constant/materials/soil");
    return Material<2>::New(d);
}

//- One material point driven directly through updateStress.
struct Point {
    std::unique_ptr<Material<2>> m;
    Particles<2> p;

    explicit Point(const std::string& entries) : m(material(entries))
    {
        p.add(Vector2::Zero(), m->rho(), 1.0, Vector2::Constant(0.5), 0, 0);  // packed: m = rho V
        m->declareFields(p);
    }
    void step(const SymTensor& dEps, double dOmega = 0)
    {
        p.dEps[0] = dEps;
        p.dOmega[0] = dOmega;
        m->updateStress(p, {0, 1, 0}, 1e-6);
    }
    //- Return from the trial stress `trial` (no strain, no spin), fresh history.
    void returnFrom(const SymTensor& trial)
    {
        p.sigma[0] = trial;
        p.epsP[0].setZero();
        for (const auto& h : p.historyNames()) p.history(h)[0] = 0;
        step(SymTensor::Zero());
    }
    const SymTensor& sigma() const { return p.sigma[0]; }
    double history(const std::string& name) const { return p.history(name)[0]; }
};

Eigen::Matrix3d full(const SymTensor& s)
{
    Eigen::Matrix3d m;
    m << s[XX], s[XY], 0, s[XY], s[YY], 0, 0, 0, s[ZZ];
    return m;
}

//- D : e for isotropic elasticity, all components (plane-strain plastic strain has e33).
Eigen::Matrix3d elasticStress(const Eigen::Matrix3d& e, double K, double G)
{
    return 2 * G * e + (K - 2 * G / 3) * e.trace() * Eigen::Matrix3d::Identity();
}

//- A plane-strain stress with the given principal values: `order` puts them on the major
//  in-plane, minor in-plane and out-of-plane axes, theta turns the in-plane pair.
SymTensor withPrincipal(const Eigen::Vector3d& v, const std::array<int, 3>& order, double theta)
{
    const double a = v[order[0]], b = v[order[1]], c = std::cos(theta), s = std::sin(theta);
    return SymTensor(a * c * c + b * s * s, a * s * s + b * c * c, v[order[2]], (a - b) * s * c);
}

//- Is e = B lambda for some lambda >= 0 (columns of B: potential gradients)? Tries every
//  subset of up to three columns by least squares.
bool inCone(const Eigen::Vector3d& e, const std::vector<Eigen::Vector3d>& gradients)
{
    const int n = static_cast<int>(gradients.size());
    const double tol = 1e-8 * std::max(e.norm(), 1e-300);
    if (e.norm() == 0) return true;
    for (unsigned mask = 1; mask < (1u << n); ++mask) {
        if (__builtin_popcount(mask) > 3) continue;
        Eigen::MatrixXd B(3, __builtin_popcount(mask));
        int k = 0;
        for (int j = 0; j < n; ++j)
            if (mask & (1u << j)) B.col(k++) = gradients[j];
        const Eigen::VectorXd lambda = B.colPivHouseholderQr().solve(e);
        if ((B * lambda - e).norm() <= tol && lambda.minCoeff() >= -tol) return true;
    }
    return false;
}

// ------------------------------------------------------------------ Mohr-Coulomb geometry

struct McSurface {
    double Nphi, Npsi, k, sigmaT;  // sigmaT infinite for none
    struct Plane {
        std::string name;
        Eigen::Vector3d a, b;
        double k;
    };
    std::vector<Plane> planes() const
    {
        std::vector<Plane> out;
        const auto shear = [&](int i, int j, const char* name) {
            Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
            a[i] = -1; a[j] = Nphi; b[i] = -1; b[j] = Npsi;
            out.push_back({name, a, b, k});
        };
        shear(0, 2, "s13"); shear(0, 1, "s12"); shear(1, 2, "s23");
        if (std::isfinite(sigmaT))
            for (int j = 2; j >= 0; --j)
                out.push_back({"t" + std::to_string(j + 1), Eigen::Vector3d::Unit(j),
                               Eigen::Vector3d::Unit(j), sigmaT});
        return out;
    }
};

McSurface mcSurface(double c, double phiDeg, double psiDeg, double sigmaT)
{
    const auto N = [](double deg) { return (1 + std::sin(deg * degree)) / (1 - std::sin(deg * degree)); };
    return {N(phiDeg), N(psiDeg), 2 * c * std::sqrt(N(phiDeg)), sigmaT};
}

//- Check one Mohr-Coulomb return from `trial`; returns the active planes, e.g. "s13+t3".
std::string checkMohrCoulombReturn(Point& pt, const McSurface& mc, double K, double G,
                                   const SymTensor& trial, double c)
{
    pt.returnFrom(trial);
    const Eigen::Matrix3d T = full(trial), S = full(pt.sigma()), E = full(pt.p.epsP[0]);
    const double scale = std::max(T.cwiseAbs().maxCoeff(), c), tol = 1e-9 * scale;
    EXPECT_LT((S - (T - elasticStress(E, K, G))).cwiseAbs().maxCoeff(), tol)
        << "sigma_N != sigma_I - D:dEpsP";

    // Principal axes of the trial are kept: the result is diagonal in them.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(T);
    const Eigen::Matrix3d V = eig.eigenvectors();
    const Eigen::Matrix3d Sp = V.transpose() * S * V, Ep = V.transpose() * E * V;
    const Eigen::Vector3d sigma = Sp.diagonal(), e = Ep.diagonal();
    EXPECT_LT((Sp - Eigen::Matrix3d(sigma.asDiagonal())).cwiseAbs().maxCoeff(), tol);
    EXPECT_LT((Ep - Eigen::Matrix3d(e.asDiagonal())).cwiseAbs().maxCoeff(), 1e-9 * E.norm() + 1e-300);
    EXPECT_LE(sigma[0], sigma[1] + tol);
    EXPECT_LE(sigma[1], sigma[2] + tol);

    std::string active;
    std::vector<Eigen::Vector3d> gradients;
    double fmax = -INFINITY;
    for (const auto& plane : mc.planes()) {
        const double f = plane.a.dot(sigma) - plane.k;
        fmax = std::max(fmax, f / plane.a.norm());
        if (f > -tol * plane.a.norm()) {
            active += (active.empty() ? "" : "+") + plane.name;
            gradients.push_back(plane.b);
        }
    }
    const bool plastic = E.norm() > 0;
    if (!plastic) {
        EXPECT_LE(fmax, 0.0);
        EXPECT_EQ(pt.history("yieldState"), 0.0);
        return "elastic";
    }
    EXPECT_NEAR(fmax, 0.0, tol) << "not on the yield surface";
    EXPECT_TRUE(inCone(e, gradients)) << "plastic strain " << e.transpose()
                                      << " is not along the potentials of " << active;
    EXPECT_GT(pt.history("yieldState"), 0.0);
    return active;
}

Eigen::Vector3d randomPrincipal(std::mt19937& rng, double c)
{
    std::uniform_real_distribution<double> u(0, 1);
    Eigen::Vector3d v;
    const double family = u(rng);
    if (family < 0.5) {  // anywhere around the surface
        for (int i = 0; i < 3; ++i) v[i] = c * (-8 + 11 * u(rng));
    } else if (family < 0.8) {  // two nearly equal values: towards the edges
        const double a = c * (-8 + 11 * u(rng)), b = c * (-8 + 11 * u(rng));
        v << a, a * (1 + 1e-3 * (u(rng) - 0.5)) + 1e-3 * c * u(rng), b;
    } else {  // near the hydrostatic axis on the tension side: the apex
        const double m = c * 6 * u(rng);
        for (int i = 0; i < 3; ++i) v[i] = m + c * (u(rng) - 0.5);
    }
    return v;
}

void mohrCoulombRegions(const std::string& entries, double K, double G, const McSurface& mc, double c,
                        const std::vector<std::string>& mustSee)
{
    Point pt(entries);
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> angle(0, M_PI);
    std::map<std::string, int> seen;
    std::map<double, int> states;
    std::array<std::array<int, 3>, 6> orders{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    for (int n = 0; n < 6000; ++n) {
        const Eigen::Vector3d v = randomPrincipal(rng, c);
        const SymTensor trial = withPrincipal(v, orders[n % 6], angle(rng));
        ++seen[checkMohrCoulombReturn(pt, mc, K, G, trial, c)];
        ++states[pt.history("yieldState")];
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "trial " << trial.transpose();
            return;
        }
    }
    std::cout << "regions:";
    for (const auto& [name, count] : seen) std::cout << ' ' << name << ' ' << count;
    std::cout << "\nyieldState:";
    for (const auto& [code, count] : states) std::cout << ' ' << code << ' ' << count;
    std::cout << '\n';
    for (const auto& name : mustSee) EXPECT_GE(seen[name], 5) << "too few returns to " << name;
}

// ----------------------------------------------------------- Drucker-Prager, von Mises

double meanOf(const Eigen::Matrix3d& s) { return s.trace() / 3; }
Eigen::Matrix3d deviatorOf(const Eigen::Matrix3d& s) { return s - meanOf(s) * Eigen::Matrix3d::Identity(); }
double qOf(const Eigen::Matrix3d& s) { return std::sqrt(0.5 * deviatorOf(s).squaredNorm()); }

//- A random plane-strain stress with mean stress p and q = sqrt(J2) = q.
SymTensor randomStress(std::mt19937& rng, double p, double q)
{
    std::normal_distribution<double> n(0, 1);
    SymTensor s(n(rng), n(rng), n(rng), n(rng));
    const Eigen::Matrix3d d = deviatorOf(full(s));
    const double scale = q / qOf(d);
    return SymTensor(d(0, 0) * scale + p, d(1, 1) * scale + p, d(2, 2) * scale + p, d(0, 1) * scale);
}

struct DpParameters {
    double K, G, qPhi, kPhi, qPsi, sigmaT;
};

//- Check one Drucker-Prager return; returns "elastic", "shear", "tension", "edge" or "apex".
std::string checkDruckerPragerReturn(Point& pt, const DpParameters& dp, const SymTensor& trial)
{
    pt.returnFrom(trial);
    const Eigen::Matrix3d T = full(trial), S = full(pt.sigma()), E = full(pt.p.epsP[0]);
    const double scale = std::max(T.cwiseAbs().maxCoeff(), dp.kPhi), tol = 1e-9 * scale;
    EXPECT_LT((S - (T - elasticStress(E, dp.K, dp.G))).cwiseAbs().maxCoeff(), tol)
        << "sigma_N != sigma_I - D:dEpsP";
    const double p = meanOf(S), q = qOf(S);
    const double fs = (q + dp.qPhi * p - dp.kPhi) / std::sqrt(1 + dp.qPhi * dp.qPhi);
    const double ft = p - dp.sigmaT;
    if (E.norm() == 0) {
        EXPECT_LE(fs, 0.0);
        EXPECT_LE(ft, 0.0);
        EXPECT_EQ(pt.history("yieldState"), 0.0);
        return "elastic";
    }
    EXPECT_NEAR(std::max(fs, ft), 0.0, tol) << "not on the yield surface";
    // dEpsP = lambda_s (s/(2q) + qPsi/3 I) + lambda_t I/3: the deviatoric part is along the
    // trial deviator (radial return) with |dev| = lambda_s/sqrt(2), the rest is volumetric.
    const Eigen::Matrix3d devE = deviatorOf(E), devT = deviatorOf(T);
    const double lambdaS = std::sqrt(2.0) * devE.norm();
    if (devE.norm() > 0) {
        const double mu = devE.cwiseProduct(devT).sum() / devT.squaredNorm();
        EXPECT_GE(mu, 0.0);
        EXPECT_LT((devE - mu * devT).norm(), 1e-9 * devE.norm()) << "deviatoric flow not radial";
    }
    const double lambdaT = E.trace() - dp.qPsi * lambdaS;
    EXPECT_GE(dp.K * lambdaT, -tol) << "negative tension multiplier";
    const bool shearActive = fs > -tol, tensionActive = ft > -tol;
    if (!shearActive) {
        EXPECT_LT(dp.G * lambdaS, tol) << "shear flow off the shear surface";
    }
    if (!tensionActive) {
        EXPECT_LT(dp.K * std::abs(lambdaT), tol) << "tension flow off the cutoff";
    }
    EXPECT_GT(pt.history("yieldState"), 0.0);
    if (shearActive && tensionActive) return q < tol ? "apex" : "edge";
    return shearActive ? "shear" : "tension";
}

void druckerPragerRegions(const std::string& entries, const DpParameters& dp,
                          const std::map<std::string, double>& expectedState)
{
    Point pt(entries);
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> u(0, 1);
    std::map<std::string, int> seen;
    const double k = dp.kPhi;
    for (int n = 0; n < 4000; ++n) {
        const SymTensor trial = randomStress(rng, k * (-6 + 10 * u(rng)), k * 4 * u(rng) * u(rng));
        const std::string region = checkDruckerPragerReturn(pt, dp, trial);
        ++seen[region];
        EXPECT_EQ(pt.history("yieldState"), expectedState.at(region)) << region;
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "trial " << trial.transpose();
            return;
        }
    }
    std::cout << "regions:";
    for (const auto& [name, count] : seen) std::cout << ' ' << name << ' ' << count;
    std::cout << '\n';
    for (const auto& [name, state] : expectedState) EXPECT_GE(seen[name], 5) << "too few " << name;
}

} // namespace

// ------------------------------------------------------------------------ Mohr-Coulomb

TEST(MohrCoulombReturn, everyRegionEndsOnTheSurfaceWithFlowAlongItsPotentials)
{
    // A truncated cone (sigmaT half the apex stress): main plane, both shear edges, the
    // tension plane, the shear-tension edge, the tension edge and the tension vertex.
    const double c = 1e5, K = 2e7, G = 1e7;
    mohrCoulombRegions("type mohrCoulomb; rho 2000; K 2e7; G 1e7; phi 30; psi 10; c 1e5; sigmaT 86602;",
                       K, G, mcSurface(c, 30, 10, 86602), c,
                       {"elastic", "s13", "s13+s12", "s13+s23", "s13+t3", "t3", "t3+t2", "t3+t2+t1",
                        "s13+s12+t3+t2", "s13+s23+t3"});
}

TEST(MohrCoulombReturn, apexOfACohesiveConeAndOfACohesionlessOne)
{
    // sigmaT at its default, the apex c/tan(phi): the tension face shrinks to the apex.
    const double c = 1e5, K = 2e7, G = 1e7;
    mohrCoulombRegions("type mohrCoulomb; rho 2000; K 2e7; G 1e7; phi 35; psi 5; c 1e5;", K, G,
                       mcSurface(c, 35, 5, c / std::tan(35 * degree)), c,
                       {"s13", "s13+s12", "s13+s23", "s13+s12+s23+t3+t2+t1"});
    // Associated flow, no cohesion: everything meets at the origin.
    mohrCoulombRegions("type mohrCoulomb; rho 2000; E 1e7; nu 0.25; phi 25; psi 25; c 0;", 1e7 / 1.5,
                       1e7 / 2.5, mcSurface(0, 25, 25, 0), 1e5,
                       {"s13", "s13+s12", "s13+s23", "s13+s12+s23+t3+t2+t1"});
}

TEST(MohrCoulombReturn, elasticTrialIsLeftBitForBitAsLinearElasticLeavesIt)
{
    // Same E and nu: inside the surface the update must be the elastic one exactly.
    Point elastic("type linearElastic; rho 2000; E 3e7; nu 0.3;");
    Point mc("type mohrCoulomb; rho 2000; E 3e7; nu 0.3; phi 30; psi 5; c 2e4;");
    Point dp("type druckerPrager; rho 2000; E 3e7; nu 0.3; phi 30; psi 5; c 2e4; fit inner;");
    Point vm("type vonMises; rho 2000; E 3e7; nu 0.3; sigmaY 1e5;");
    const SymTensor s0(-5e4, -7e4, -6e4, 3e3), dEps(-1.3e-5, 0.7e-5, 0, 2.1e-5);
    for (Point* pt : {&elastic, &mc, &dp, &vm}) {
        pt->p.sigma[0] = s0;
        pt->step(dEps, 0.01);
    }
    for (Point* pt : {&mc, &dp, &vm}) {
        for (int i = 0; i < 4; ++i) EXPECT_EQ(pt->sigma()[i], elastic.sigma()[i]) << i;
        EXPECT_EQ(pt->p.epsP[0], SymTensor(SymTensor::Zero()));
        EXPECT_EQ(pt->history("yieldState"), 0.0);
    }
}

// ---------------------------------------------------------------------- Drucker-Prager

TEST(DruckerPragerReturn, everyRegionEndsOnTheSurfaceWithFlowAlongItsPotentials)
{
    // Cutoff below the apex (kPhi/qPhi = 2e5): shear, tension and the corner between them.
    druckerPragerRegions("type druckerPrager; rho 2000; K 2e7; G 1e7; qPhi 0.5; kPhi 1e5; qPsi 0.2; sigmaT 1e5;",
                         {2e7, 1e7, 0.5, 1e5, 0.2, 1e5},
                         {{"elastic", 0}, {"shear", 1}, {"tension", 2}, {"edge", 4}});
    // Cutoff at the apex: returns beyond the apex end on its tip.
    druckerPragerRegions("type druckerPrager; rho 2000; K 2e7; G 1e7; qPhi 0.5; kPhi 1e5; qPsi 0.1;",
                         {2e7, 1e7, 0.5, 1e5, 0.1, 2e5}, {{"elastic", 0}, {"shear", 1}, {"apex", 3}});
    // A cylinder (qPhi = 0) with a cutoff.
    druckerPragerRegions("type druckerPrager; rho 2000; K 2e7; G 1e7; qPhi 0; kPhi 1e5; sigmaT 5e4;",
                         {2e7, 1e7, 0, 1e5, 0, 5e4},
                         {{"elastic", 0}, {"shear", 1}, {"tension", 2}, {"edge", 4}});
}

TEST(DruckerPragerReturn, cohesionlessApexReturnsToTheOriginWithItsDeviatorGone)
{
    // c = 0 sand pulled apart: the trial is past the apex p = 0, q = 0.
    Point pt("type druckerPrager; rho 2000; K 2e7; G 1e7; phi 30; psi 0; c 0; fit outer;");
    pt.returnFrom(SymTensor(2e3, -1e3, 5e2, 1.5e3));
    EXPECT_LT(pt.sigma().cwiseAbs().maxCoeff(), 1e-9 * 2e3);
    EXPECT_EQ(pt.history("yieldState"), 3.0);
}

TEST(DruckerPragerReturn, withoutFrictionIsVonMisesAlongAStrainPath)
{
    // qPhi = qPsi = 0, kPhi = sigmaY/sqrt(3), no cutoff: f_s = q - sigmaY/sqrt(3), g_s = q,
    // the von Mises model of H.4 (eq. H.6.3). A path of shear, compression, unloading and
    // spin must give the same stress to round-off.
    const double sigmaY = 2e5, kPhi = sigmaY / std::sqrt(3.0);
    std::ostringstream dpText;
    dpText << std::setprecision(17) << "type druckerPrager; rho 2000; K 2e7; G 1e7; qPhi 0; kPhi " << kPhi << ";";
    Point dp(dpText.str());
    Point vm("type vonMises; rho 2000; K 2e7; G 1e7; sigmaY 2e5;");
    int plasticSteps = 0;
    for (int k = 0; k < 400; ++k) {
        const double t = k / 400.0;
        const SymTensor dEps(-2e-4 * std::cos(7 * t), 1e-4 * std::sin(5 * t), 0, 3e-4 * std::cos(3 * t));
        dp.step(dEps, 2e-3);
        vm.step(dEps, 2e-3);
        for (int i = 0; i < 4; ++i) ASSERT_NEAR(dp.sigma()[i], vm.sigma()[i], 1e-9 * sigmaY) << "step " << k;
        ASSERT_EQ(dp.history("yieldState"), vm.history("yieldState"));
        plasticSteps += vm.history("yieldState") > 0;
    }
    EXPECT_GT(plasticSteps, 100);  // the path does yield
}

// --------------------------------------------------------------------------- von Mises

TEST(VonMisesReturn, radialReturnOntoTheHardenedCylinder)
{
    // f = q - (sigmaY + H epsPs)/sqrt(3) = 0 after the return, p unchanged, dEpsP along s,
    // epsPs = sqrt(2/3 dEpsP:dEpsP) (equivalent plastic strain), sigma_N = sigma_I - D dEpsP.
    const double K = 2e7, G = 1e7, sigmaY = 2e5, H = 3e6;
    Point pt("type vonMises; rho 2000; K 2e7; G 1e7; sigmaY 2e5; H 3e6;");
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    int plastic = 0;
    for (int n = 0; n < 500; ++n) {
        const SymTensor trial = randomStress(rng, sigmaY * (2 * u(rng) - 1), sigmaY * 1.5 * u(rng));
        pt.returnFrom(trial);
        const Eigen::Matrix3d T = full(trial), S = full(pt.sigma()), E = full(pt.p.epsP[0]);
        EXPECT_LT((S - (T - elasticStress(E, K, G))).cwiseAbs().maxCoeff(), 1e-9 * sigmaY);
        EXPECT_NEAR(meanOf(S), meanOf(T), 1e-9 * sigmaY);
        const double epsPs = pt.history("epsPs");
        EXPECT_NEAR(epsPs, std::sqrt(2.0 / 3.0) * E.norm(), 1e-12);
        if (qOf(T) <= sigmaY / std::sqrt(3.0)) {
            EXPECT_EQ(E.norm(), 0.0);
            EXPECT_EQ(pt.history("yieldState"), 0.0);
            continue;
        }
        ++plastic;
        EXPECT_EQ(pt.history("yieldState"), 1.0);
        EXPECT_NEAR(qOf(S), (sigmaY + H * epsPs) / std::sqrt(3.0), 1e-9 * sigmaY);
        const Eigen::Matrix3d devT = deviatorOf(T);
        const double mu = E.cwiseProduct(devT).sum() / devT.squaredNorm();
        EXPECT_GT(mu, 0.0);
        EXPECT_LT((E - mu * devT).norm(), 1e-9 * E.norm());
    }
    EXPECT_GT(plastic, 100);
}

// ------------------------------------------------------------------ Tresca and softening

TEST(MohrCoulombReturn, withoutFrictionIsTrescaInSimpleShear)
{
    // phi = psi = 0: f = sigma3 - sigma1 - 2c, so in simple shear (any mean stress) the
    // in-plane shear stress stops at (sigma3 - sigma1)/2 = sigma12 = c once 2G eps12 = c.
    const double c = 5e4, G = 1e7;
    for (double p0 : {0.0, -3e5}) {
        Point pt("type mohrCoulomb; rho 2000; K 2e7; G 1e7; phi 0; c 5e4;");
        pt.p.sigma[0] = SymTensor(p0, p0, p0, 0);
        for (int k = 1; k <= 300; ++k) {
            pt.step(SymTensor(0, 0, 0, 1e-5));
            const SymTensor& s = pt.sigma();
            const double elastic = 2 * G * 1e-5 * k;
            const double expected = std::min(elastic, c);
            ASSERT_NEAR(s[XY], expected, 1e-9 * c) << "step " << k;
            const double radius = std::hypot(0.5 * (s[XX] - s[YY]), s[XY]);
            ASSERT_NEAR(radius, expected, 1e-9 * c);
            ASSERT_NEAR(s[XX], p0, 1e-9 * c);  // no dilatancy: the normal stresses stay
            ASSERT_NEAR(s[ZZ], p0, 1e-9 * c);
        }
        EXPECT_EQ(pt.history("yieldState"), 1.0);
        // Tensor plastic shear = total minus elastic; epsPs of eq. H.5.36 equals it here.
        const double epsP12 = 300e-5 - c / (2 * G);
        EXPECT_NEAR(pt.p.epsP[0][XY], epsP12, 1e-12);
        EXPECT_NEAR(pt.history("epsPs"), epsP12, 1e-12);
    }
}

TEST(MohrCoulombReturn, softeningCohesionActsOneStepLate)
{
    // Tresca with c falling linearly from 5e4 to 2e4 Pa over epsPs = 0.01 (seed H.5.3): in
    // simple shear each plastic step ends on the surface of the c at the start of the step.
    const double G = 1e7;
    Point pt("type mohrCoulomb; rho 2000; K 2e7; G 1e7; phi 0; cTable ((0 5e4) (0.01 2e4));");
    const auto c = [](double e) { return e >= 0.01 ? 2e4 : 5e4 - 3e6 * e; };
    int plastic = 0;
    for (int k = 1; k <= 1500; ++k) {
        const double before = pt.history("epsPs");
        pt.step(SymTensor(0, 0, 0, 1e-5));
        if (pt.history("yieldState") == 0) continue;
        ++plastic;
        ASSERT_NEAR(pt.sigma()[XY], c(before), 1e-9 * 5e4) << "step " << k;
    }
    EXPECT_GT(plastic, 1000);
    EXPECT_NEAR(pt.sigma()[XY], 2e4, 1e-9 * 5e4);
    EXPECT_NEAR(pt.history("epsPs"), 1500e-5 - 2e4 / (2 * G), 1e-12);
}

TEST(MohrCoulombReturn, tensileStrengthSoftensWithPlasticTensileStrain)
{
    // Uniaxial extension in x1 with phi = 30, c = 1e5 (apex 173 kPa) and sigmaT falling from
    // 50 kPa to 0 over epsPt = 1e-3: sigma11 = sigmaT(epsPt at the start of the step), and
    // epsPt adds the principal plastic strain of the cutoff (eq. H.5.38), here d epsP11.
    Point pt("type mohrCoulomb; rho 2000; K 2e7; G 1e7; phi 30; c 1e5; sigmaTTable ((0 5e4) (1e-3 0));");
    const auto sigmaT = [](double e) { return std::max(5e4 * (1 - e / 1e-3), 0.0); };
    int plastic = 0;
    for (int k = 1; k <= 400; ++k) {
        const double before = pt.history("epsPt");
        pt.step(SymTensor(1e-5, 0, 0, 0));
        if (pt.history("yieldState") == 0) continue;
        ++plastic;
        ASSERT_EQ(pt.history("yieldState"), 2.0) << "step " << k;
        ASSERT_NEAR(pt.sigma()[XX], sigmaT(before), 1e-9 * 5e4) << "step " << k;
        ASSERT_NEAR(pt.history("epsPt"), pt.p.epsP[0][XX], 1e-15);
    }
    EXPECT_GT(plastic, 100);
}
