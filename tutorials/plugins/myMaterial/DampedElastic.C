#include "DampedElastic.H"

#include "dictionary/Dictionary.H"
#include "materials/JaumannRate.H"

#include <cmath>

namespace myMaterial {

using gpic::XX;
using gpic::XY;
using gpic::YY;
using gpic::ZZ;

// The one line that makes the model selectable as `type viscoElastic;`, in plane and 3D scenes.
GPIC_REGISTER_DIMS(gpic::Material, DampedElastic, "viscoElastic")

template <int D>
DampedElastic<D>::DampedElastic(const gpic::Dictionary& dict)
    : gpic::Material<D>(dict),
      E_(dict.getChecked<double>("E", [](const double& v) { return v > 0; }, "E > 0")),
      nu_(dict.getChecked<double>(
          "nu", [](const double& v) { return v > -1.0 && v < 0.5; }, "-1 < nu < 0.5")),
      eta_(dict.getChecked<double>("eta", [](const double& v) { return v >= 0; }, "eta >= 0"))
{}

template <int D> double DampedElastic<D>::waveSpeed() const
{
    // P-wave speed sqrt((K + 4G/3)/rho); viscosity does not change the front speed.
    return std::sqrt((K() + 4.0 * G() / 3.0) / this->rho());
}

template <int D>
void DampedElastic<D>::updateStress(gpic::Particles<D>& p, const gpic::ParticleBlock& block, double dt) const
{
    const double G2 = 2.0 * G();
    const double alpha1 = K() + 2.0 * G2 / 3.0;
    const double alpha2 = K() - G2 / 3.0;
    // dt = 0 (e.g. an initial stress evaluation) has no rate: no viscous stress.
    const double etaByDt = dt > 0 ? eta_ / dt : 0.0;
    std::vector<double>& sigmaV = p.history("sigmaV");
    for (std::size_t i = block.begin; i < block.end; ++i) {
        typename gpic::Space<D>::SymTensor& s = p.sigma[i];
        const typename gpic::Space<D>::SymTensor& de = p.dEps[i];
        // Remove last step's viscous stress so that s holds the elastic part only.
        s[XX] -= sigmaV[i];
        s[YY] -= sigmaV[i];
        s[ZZ] -= sigmaV[i];
        gpic::rotateJaumann(s, p.dOmega[i]);
        if constexpr (D == 2) {
            s[XX] += alpha1 * de[XX] + alpha2 * de[YY];
            s[YY] += alpha2 * de[XX] + alpha1 * de[YY];
            s[ZZ] += alpha2 * (de[XX] + de[YY]);
            s[XY] += G2 * de[XY];
            sigmaV[i] = etaByDt * (de[XX] + de[YY]);
        } else {
            const double trace = de[XX] + de[YY] + de[ZZ];
            for (int c : {XX, YY, ZZ}) s[c] += alpha2 * trace + G2 * de[c];
            for (int c = XY; c < gpic::Space<D>::nSym; ++c) s[c] += G2 * de[c];
            sigmaV[i] = etaByDt * trace;
        }
        s[XX] += sigmaV[i];
        s[YY] += sigmaV[i];
        s[ZZ] += sigmaV[i];
    }
}

template class DampedElastic<2>;
template class DampedElastic<3>;

} // namespace myMaterial
