#include "cosseratDruckerPrager/CosseratDruckerPrager.H"

#include "core/Info.H"
#include "dictionary/Dictionary.H"
#include "plasticity/YieldState.H"

#include <Eigen/Cholesky>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace gpic {

GPIC_REGISTER(Material<2>, CosseratDruckerPrager, "cosseratDruckerPrager")

namespace {

double coefficient(const Dictionary& dict, const char* key, double deflt)
{
    if (!dict.found(key)) return deflt;
    return dict.getChecked<double>(key, [](const double& v) { return v >= 0; }, std::string(key) + " >= 0");
}

//- Gc = G / (2 (a1 - a2)) (eq. I.5.9); -1 (Gc required) when a1 = a2.
double defaultGc(const Dictionary& dict, double a1, double a2)
{
    if (!(a1 > a2)) return -1.0;
    const double G = dict.getChecked<double>("G", [](const double& v) { return v > 0; }, "G > 0");
    return G / (2.0 * (a1 - a2));
}

const char* const twoForms = "give either alpha (and beta), or phi (and psi) in degrees, not both";

} // namespace

CosseratDruckerPrager::CosseratDruckerPrager(const Dictionary& dict)
    : Material<2>(dict),
      a1_(coefficient(dict, "a1", 0.375)),
      a2_(coefficient(dict, "a2", 0.125)),
      a3_(coefficient(dict, "a3", 1.0)),
      elastic_(dict, defaultGc(dict, a1_, a2_)),
      alpha_(0), beta_(0), c_(0), tolerance_(1e-6), grains_(dict, rho())
{
    if (std::abs(a1_ + a2_ - 0.5) > 1e-12)
        dict.fail(dict.found("a2") ? "a2" : "a1", "keyword 'a1'/'a2' in dictionary " + dict.name() +
                                                      ": a1 + a2 must be 1/2 (seed I.5), got a1 + a2 = " +
                                                      std::to_string(a1_ + a2_));
    if (a1_ < a2_)
        dict.fail("a2", "keyword 'a2' in dictionary " + dict.name() + ": a2 <= a1 needed (J2 >= 0)");

    const bool direct = dict.found("alpha") || dict.found("beta");
    const bool angles = dict.found("phi") || dict.found("psi");
    if (direct && angles) dict.fail(dict.found("phi") ? "phi" : "psi", std::string("keyword in dictionary ") + dict.name() + ": " + twoForms);
    if (!direct && !angles)
        dict.fail("alpha", "keyword 'alpha' is undefined in dictionary " + dict.name() + "; " + twoForms);
    if (direct) {
        alpha_ = dict.getChecked<double>("alpha", [](const double& v) { return v >= 0; }, "alpha >= 0");
        const double a = alpha_;
        beta_ = dict.found("beta")
                    ? dict.getChecked<double>("beta", [a](const double& v) { return v >= 0 && v <= a; }, "0 <= beta <= alpha")
                    : 0.0;
    } else {
        const double toRad = M_PI / 180.0;
        const double phi = dict.getChecked<double>("phi", [](const double& v) { return v >= 0 && v < 90; },
                                                   "0 <= phi < 90 (degrees)");
        const double psi = dict.found("psi")
                               ? dict.getChecked<double>("psi", [phi](const double& v) { return v >= 0 && v <= phi; },
                                                         "0 <= psi <= phi (degrees)")
                               : 0.0;
        alpha_ = std::sin(phi * toRad);  // Tejchman 1997, seed A13
        beta_ = std::sin(psi * toRad);
    }
    if (dict.found("c")) c_ = dict.getChecked<double>("c", [](const double& v) { return v >= 0; }, "c >= 0");
    if (dict.found("tolerance"))
        tolerance_ = dict.getChecked<double>("tolerance", [](const double& v) { return v > 0 && v <= 1e-3; },
                                             "0 < tolerance <= 1e-3");

    const std::string mean = dict.getWordOrDefault("meanStress", {"inPlane", "threeD"}, "inPlane");
    pi_.setZero();
    if (mean == "inPlane") pi_[0] = pi_[1] = 0.5;  // p = (s11 + s22)/2, seed A13
    else pi_[0] = pi_[1] = pi_[2] = 1.0 / 3.0;      // p = (s11 + s22 + s33)/3, eq. H.3.1
    P_.setZero();
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) P_(a, b) = a == b ? 2.0 / 3.0 : -1.0 / 3.0;
    P_(3, 3) = P_(4, 4) = 2.0 * a1_;
    P_(3, 4) = P_(4, 3) = 2.0 * a2_;
    P_(5, 5) = P_(6, 6) = 2.0 * a3_;
    D_ = elastic_.D();

    std::ostringstream line;
    line << std::setprecision(6) << "cosseratDruckerPrager " << name() << ": alpha " << alpha_ << " beta " << beta_
         << " c " << c_ << " Gc " << elastic_.Gc() << " l " << elastic_.l() << " J33 " << elastic_.J33()
         << " a (" << a1_ << " " << a2_ << " " << a3_ << "), p " << mean;
    info() << line.str() << '\n';
}

int CosseratDruckerPrager::returnMap(CosseratVector& s, double& dLambda, CosseratVector& dEpsP) const
{
    const CosseratVector trial = s;
    const CosseratVector trialShear = P_ * trial;
    constexpr int maxIterations = 100;
    for (int it = 0; it < maxIterations; ++it) {
        const double qs = q(s);
        const double f = qs + alpha_ * meanStress(s) - c_;
        if (qs > 0 && std::abs(f) <= tolerance_ * qs) return static_cast<int>(YieldState::shear);
        if (!(qs > 0)) break;
        // eq. I.5.13, I.5.14: dq/dsigma = P sigma / (2q)
        const CosseratVector dq = (P_ * s) / (2.0 * qs);
        const CosseratVector df = dq + alpha_ * pi_, dg = dq + beta_ * pi_;
        const CosseratVector Ddg = D_ * dg;
        const double dl = f / df.dot(Ddg);  // eq. I.5.11, h = 0
        s -= dl * Ddg;                      // eq. I.5.12
        dLambda += dl;
        dEpsP += dl * dg;
        // Past the apex the deviatoric part turns over: the cone's tip is the answer.
        if (trialShear.dot(s) < 0.0) break;
    }
    if (!(alpha_ > 0)) return static_cast<int>(YieldState::shear);  // a cylinder has no apex
    // Apex: q = 0, p = c/alpha; all of the step beyond it is plastic.
    CosseratVector apex = CosseratVector::Zero();
    apex[0] = apex[1] = apex[2] = c_ / alpha_;
    dEpsP = D_.ldlt().solve(trial - apex);
    dLambda = q(trial) / elastic_.G();
    s = apex;
    return static_cast<int>(YieldState::apex);
}

void CosseratDruckerPrager::updateStress(Particles<2>& p, const ParticleBlock& block, double) const
{
    auto& state = p.history("yieldState");
    auto& epsPs = p.history("epsPs");
    CosseratParticles& c = p.polar;
    const double l = elastic_.l();
    for (std::size_t i = block.begin; i < block.end; ++i) {
        if (grains_.lost(p.m[i], p.V[i])) {
            p.sigma[i] = SymTensor::Zero();
            c.sigma21[i] = 0;
            c.mu[i].setZero();
            state[i] = code(YieldState::disconnected);
            continue;
        }
        // The trial in locals: the particle's arrays are written once, at the end.
        SymTensor sigma = p.sigma[i];
        double sigma21 = c.sigma21[i];
        Vector2 mu = c.mu[i];
        CosseratElasticity::rotate(sigma, sigma21, mu, p.dOmega[i]);
        elastic_.addElasticIncrement(sigma, sigma21, mu, p.dEps[i], c.dRotation[i], c.dKappa[i]);
        CosseratVector s = cosseratStress(sigma, sigma21, mu, l);
        const double qs = q(s);
        if (!(qs + alpha_ * meanStress(s) - c_ > tolerance_ * qs)) {
            p.sigma[i] = sigma;
            c.sigma21[i] = sigma21;
            c.mu[i] = mu;
            state[i] = code(YieldState::elastic);
            continue;
        }
        double dLambda = 0;
        CosseratVector dEpsP = CosseratVector::Zero();
        state[i] = returnMap(s, dLambda, dEpsP);
        setCosseratStress(p, i, s, l);
        p.epsP[i] += SymTensor(dEpsP[0], dEpsP[1], dEpsP[2], 0.5 * (dEpsP[3] + dEpsP[4]));
        epsPs[i] += dLambda;
    }
}

} // namespace gpic
