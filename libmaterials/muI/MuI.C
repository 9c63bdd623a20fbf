#include "muI/MuI.H"
#include "core/Info.H"

#include "dictionary/Dictionary.H"
#include "materials/JaumannRate.H"
#include "plasticity/StressInvariants.H"
#include "plasticity/YieldState.H"

#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

namespace gpic {

GPIC_REGISTER_DIMS(Material, MuI, "muI")

namespace {

std::string number(double v)
{
    std::ostringstream s;
    s << std::setprecision(6) << v;
    return s.str();
}

//- A finite value above `low` (or at it, when `orEqual`).
std::function<bool(const double&)> above(double low, bool orEqual = false)
{
    return [low, orEqual](const double& v) { return std::isfinite(v) && (v > low || (orEqual && v == low)); };
}

InertialRheology readRheology(const Dictionary& dict, double rho)
{
    InertialRheology r{};
    r.muS = dict.getChecked<double>("muS", above(0.0, true), "muS >= 0 (static friction coefficient)");
    r.mu2 = dict.getChecked<double>("mu2", above(r.muS),
                                    "mu2 > muS (" + number(r.muS) + "): the friction grows with I");
    r.I0 = dict.getChecked<double>("I0", above(0.0), "I0 > 0 (inertial number)");
    r.d = dict.getChecked<double>("d", above(0.0), "d > 0 (grain diameter, m)");
    r.rhoS = dict.getChecked<double>("rhoS", above(rho),
                                     "rhoS > rho (" + number(rho) +
                                         " kg/m^3): the grains are denser than their packing");
    return r;
}

} // namespace

template <int D>
MuI<D>::MuI(const Dictionary& dict)
    : Material<D>(dict), elastic_(dict), rheology_(readRheology(dict, this->rho())),
      rhoC_(dict.getChecked<double>(
          "rhoC", [rho = this->rho()](const double& v) { return std::isfinite(v) && v > 0 && v <= rho; },
          "0 < rhoC <= rho (" + number(this->rho()) +
              " kg/m^3): a packing placed looser than rhoC would start without stress"))
{
    info() << std::setprecision(6) << "muI " << this->name() << ": muS " << rheology_.muS << " (atan "
           << std::atan(rheology_.muS) * 180.0 / M_PI << " deg), mu2 " << rheology_.mu2 << " (atan "
           << std::atan(rheology_.mu2) * 180.0 / M_PI << " deg), I0 " << rheology_.I0 << ", d "
           << rheology_.d << " m, rhoS " << rheology_.rhoS << ", rhoC " << rhoC_ << " kg/m^3\n";
}

template <int D> void MuI<D>::updateStress(Particles<D>& p, const ParticleBlock& block, double dt) const
{
    const double G = elastic_.G();
    auto& state = p.history("yieldState");
    auto& inertial = p.history("I");
    auto& gammaDotP = p.history("gammaDotP");
    auto& epsPs = p.history("epsPs");
    using SymTensor = typename Space<D>::SymTensor;
    for (std::size_t i = block.begin; i < block.end; ++i) {
        SymTensor& s = p.sigma[i];
        inertial[i] = 0;
        gammaDotP[i] = 0;
        if (p.m[i] < rhoC_ * p.V[i]) {  // rho = m/V < rho_c: the grains have separated
            s = SymTensor::Zero();
            state[i] = code(YieldState::disconnected);
            continue;
        }
        rotateJaumann(s, p.dOmega[i]);
        elastic_.addElasticIncrement(s, p.dEps[i]);  // the trial, eq. H.2.1

        const double pTr = -meanStress(s), tauTr = shearStress(s);  // compression positive
        if (!(pTr > 0)) {  // a trial that is not compressive: no contact force to carry it
            s = SymTensor::Zero();
            state[i] = code(YieldState::tension);
            continue;
        }
        if (tauTr <= rheology_.muS * pTr) {
            state[i] = code(YieldState::elastic);
            continue;
        }

        // Flowing: tau = p mu(I) at p = pTr (InertialRheology.H), the deviator scaled.
        const double tau = rheology_.returnedShear(pTr, tauTr, G, dt);
        const double dGammaP = (tauTr - tau) / G;
        const double scale = tau / tauTr, half = dGammaP / (2.0 * tauTr);
        SymTensor& epsP = p.epsP[i];
        for (int c : {XX, YY, ZZ}) {
            const double dev = s[c] + pTr;  // the trial deviator
            epsP[c] += half * dev;          // D^p dt = dGammaP s/(2 tau): along the deviator
            s[c] = dev * scale - pTr;
        }
        for (int c = XY; c < Space<D>::nSym; ++c) {
            epsP[c] += half * s[c];
            s[c] *= scale;
        }
        gammaDotP[i] = dGammaP / dt;
        inertial[i] = rheology_.inertialNumber(gammaDotP[i], pTr);
        epsPs[i] += dGammaP;
        state[i] = code(YieldState::shear);
    }
}

template class MuI<2>;
#if GPIC_WITH_3D
template class MuI<3>;
#endif

} // namespace gpic
