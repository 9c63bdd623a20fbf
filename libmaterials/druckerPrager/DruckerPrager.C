#include "druckerPrager/DruckerPrager.H"
#include "core/Info.H"

#include "dictionary/Dictionary.H"
#include "materials/JaumannRate.H"
#include "plasticity/MohrCoulombFit.H"
#include "plasticity/StressInvariants.H"
#include "plasticity/YieldState.H"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace gpic {

GPIC_REGISTER_DIMS(Material, DruckerPrager, "druckerPrager")

namespace {

const char* const twoForms = "give either qPhi and kPhi (and qPsi), or phi, c and fit (and psi)";

std::string number(double v)
{
    std::ostringstream s;
    s << std::setprecision(6) << v;
    return s.str();
}

} // namespace

template <int D>
DruckerPrager<D>::DruckerPrager(const Dictionary& dict)
    : Material<D>(dict), elastic_(dict), qPhi_(0), kPhi_(0), qPsi_(0),
      sigmaT_(std::numeric_limits<double>::infinity()), grains_(dict, this->rho())
{
    const auto nonNegative = [](const char* key) { return std::string(key) + " >= 0"; };
    const auto isNonNegative = [](const double& v) { return v >= 0; };
    const char* direct = nullptr;
    for (const char* key : {"qPhi", "kPhi", "qPsi"})
        if (!direct && dict.found(key)) direct = key;
    const char* fitted = nullptr;
    for (const char* key : {"phi", "psi", "c", "fit"})
        if (!fitted && dict.found(key)) fitted = key;
    if (direct && fitted)
        dict.fail(fitted, "keyword '" + std::string(fitted) + "' in dictionary " + dict.name() +
                              ": Drucker-Prager parameters given twice (" + direct + " and " +
                              fitted + "); " + twoForms + ", not both");
    if (!direct && !fitted)
        dict.fail("qPhi", "keyword 'qPhi' is undefined in dictionary " + dict.name() + "; " + twoForms);

    // Coefficients to 4 digits, stresses and angles to 6.
    std::ostringstream line;
    line << std::setprecision(6) << "druckerPrager " << this->name() << ": ";
    if (direct) {
        qPhi_ = dict.getChecked<double>("qPhi", isNonNegative, nonNegative("qPhi"));
        kPhi_ = dict.getChecked<double>("kPhi", isNonNegative, nonNegative("kPhi"));
        const double qPhi = qPhi_;
        if (dict.found("qPsi"))
            qPsi_ = dict.getChecked<double>(
                "qPsi", [qPhi](const double& v) { return v >= 0 && v <= qPhi; },
                "0 <= qPsi <= qPhi (" + number(qPhi) + ")");
        line << "parameters given:";
    } else {
        const double phi = dict.getChecked<double>(
            "phi", [](const double& v) { return v >= 0 && v < 90; }, "0 <= phi < 90 (degrees)");
        const double psi = dict.found("psi")
            ? dict.getChecked<double>("psi", [phi](const double& v) { return v >= 0 && v <= phi; },
                                      "0 <= psi <= phi (" + number(phi) + " degrees)")
            : 0.0;
        const double c = dict.getChecked<double>("c", isNonNegative, nonNegative("c"));
        const std::string fit = dict.getWord("fit", mohrCoulombFitNames());
        const double toRad = M_PI / 180.0;
        const DruckerPragerParameters dp =
            fitMohrCoulomb(mohrCoulombFitKind(fit), phi * toRad, psi * toRad, c);
        qPhi_ = dp.qPhi;
        kPhi_ = dp.kPhi;
        qPsi_ = dp.qPsi;
        line << fit << " fit to Mohr-Coulomb (phi " << phi << ", psi " << psi << ", c " << c << "):";
    }
    line << " qPhi " << std::setprecision(4) << qPhi_ << " kPhi " << std::setprecision(6) << kPhi_
         << " qPsi " << std::setprecision(4) << qPsi_;

    // The cutoff may not pass the apex kPhi/qPhi (eq. H.3.10); it defaults to it.
    const double apex = qPhi_ > 0 ? kPhi_ / qPhi_ : std::numeric_limits<double>::infinity();
    if (dict.found("sigmaT"))
        sigmaT_ = dict.getChecked<double>(
            "sigmaT", [apex](const double& v) { return v >= 0 && v <= apex * (1 + 1e-12); },
            "0 <= sigmaT <= kPhi/qPhi (" + number(apex) + ")");
    else
        sigmaT_ = apex;
    sigmaT_ = std::min(sigmaT_, apex);
    info() << line.str() << '\n';
}

template <int D> void DruckerPrager<D>::updateStress(Particles<D>& p, const ParticleBlock& block, double) const
{
    const double G = elastic_.G(), K = elastic_.K();
    const double tauP = std::max(kPhi_ - qPhi_ * sigmaT_, 0.0);  // q at the corner, eq. H.3.14
    auto& state = p.history("yieldState");
    auto& epsPs = p.history("epsPs");
    using SymTensor = typename Space<D>::SymTensor;
    for (std::size_t i = block.begin; i < block.end; ++i) {
        SymTensor& s = p.sigma[i];
        if (grains_.lost(p.m[i], p.V[i])) {
            s = SymTensor::Zero();
            state[i] = code(YieldState::disconnected);
            continue;
        }
        rotateJaumann(s, p.dOmega[i]);
        elastic_.addElasticIncrement(s, p.dEps[i]);  // sigma_I, eq. H.2.1

        const double pI = meanStress(s), qI = shearStress(s);
        const double fs = qI + qPhi_ * pI - kPhi_;  // eq. H.3.8
        const double ft = pI - sigmaT_;             // eq. H.3.9
        if (!(fs > 0) && !(ft > 0)) {
            state[i] = code(YieldState::elastic);
            continue;
        }

        double lambdaS = 0, lambdaT = 0, pN = pI, qN = qI;
        YieldState how = YieldState::shear;
        bool done = false;
        if (fs > 0) {  // shear, eq. H.3.20, H.3.21
            lambdaS = fs / (G + K * qPhi_ * qPsi_);
            qN = qI - G * lambdaS;
            pN = pI - K * qPsi_ * lambdaS;
            done = qN >= 0 && pN <= sigmaT_;
        }
        if (!done && ft > 0 && qI <= tauP) {  // tension, eq. H.3.27, H.3.28
            lambdaS = 0;
            lambdaT = (pI - sigmaT_) / K;
            qN = qI;
            pN = sigmaT_;
            how = YieldState::tension;
            done = true;
        }
        if (!done) {  // the corner B = (sigmaT, tau_p): shear and tension together
            qN = tauP;
            lambdaS = (qI - tauP) / G;
            lambdaT = (pI - K * qPsi_ * lambdaS - sigmaT_) / K;
            pN = sigmaT_;
            how = tauP > 0 ? YieldState::edge : YieldState::apex;
        }

        // The deviator keeps its direction (eq. H.3.22, H.3.30); dEpsP = lambda_s dg_s/dsigma
        // + lambda_t dg_t/dsigma (eq. H.3.16, H.3.24). Component by component in registers:
        // tensors built on the stack and read back as pairs stall on store forwarding.
        const double volumetric = (lambdaS * qPsi_ + lambdaT) / 3.0;
        const double twoQ = 2.0 * qI, scale = qI > 0 ? qN / qI : 0.0;
        SymTensor& epsP = p.epsP[i];
        for (int c : {XX, YY, ZZ}) {
            const double dev = s[c] - pI;  // deviator(s)
            s[c] = (qI > 0 ? dev * scale : 0.0) + pN;
            epsP[c] += lambdaS * (qI > 0 ? dev / twoQ : 0.0) + volumetric;
        }
        for (int c = XY; c < Space<D>::nSym; ++c) {  // the shears
            epsP[c] += lambdaS * (qI > 0 ? s[c] / twoQ : 0.0);
            s[c] = qI > 0 ? s[c] * scale : 0.0;
        }
        epsPs[i] += lambdaS;  // eps_q of the plastic increment, eq. H.3.4
        state[i] = code(how);
    }
}

template class DruckerPrager<2>;
#if GPIC_WITH_3D
template class DruckerPrager<3>;
#endif

} // namespace gpic
