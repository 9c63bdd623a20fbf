#include "vonMises/VonMises.H"

#include "dictionary/Dictionary.H"
#include "materials/JaumannRate.H"
#include "plasticity/StressInvariants.H"
#include "plasticity/YieldState.H"

#include <cmath>

namespace gpic {

GPIC_REGISTER_DIMS(Material, VonMises, "vonMises")

template <int D>
VonMises<D>::VonMises(const Dictionary& dict)
    : Material<D>(dict),
      elastic_(dict),
      sigmaY_(dict.getChecked<double>("sigmaY", [](const double& v) { return v > 0; }, "sigmaY > 0")),
      H_(dict.found("H") ? dict.getChecked<double>("H", [](const double& v) { return v >= 0; }, "H >= 0")
                         : 0.0)
{}

template <int D> void VonMises<D>::updateStress(Particles<D>& p, const ParticleBlock& block, double) const
{
    const double G = elastic_.G();
    const double r3 = std::sqrt(3.0);
    auto& state = p.history("yieldState");
    auto& epsPs = p.history("epsPs");
    for (std::size_t i = block.begin; i < block.end; ++i) {
        typename Space<D>::SymTensor& s = p.sigma[i];
        rotateJaumann(s, p.dOmega[i]);
        elastic_.addElasticIncrement(s, p.dEps[i]);  // sigma_I, eq. H.2.1

        const double qI = shearStress(s);
        const double f = qI - (sigmaY_ + H_ * epsPs[i]) / r3;  // eq. H.4.5
        if (!(f > 0)) {
            state[i] = code(YieldState::elastic);
            continue;
        }
        const double lambda = f / (G + H_ / 3.0);  // eq. H.4.12 with hardening
        const double qN = qI - G * lambda;         // eq. H.4.11
        const double pI = meanStress(s);
        const typename Space<D>::SymTensor dev = deviator(s);
        s = dev * (qN / qI);                       // eq. H.4.13, p_N = p_I
        for (int c : {XX, YY, ZZ}) s[c] += pI;
        p.epsP[i] += (lambda / (2.0 * qI)) * dev;  // dg/dsigma = s/(2q)
        epsPs[i] += lambda / r3;
        state[i] = code(YieldState::shear);
    }
}

template class VonMises<2>;
#if GPIC_WITH_3D
template class VonMises<3>;
#endif

} // namespace gpic
