#include "linearElastic/LinearElastic.H"

#include "dictionary/Dictionary.H"
#include "materials/JaumannRate.H"

#include <cmath>

namespace gpic {

GPIC_REGISTER(Material, LinearElastic, "linearElastic")

LinearElastic::LinearElastic(const Dictionary& dict)
    : Material(dict),
      E_(dict.getChecked<double>("E", [](const double& v) { return v > 0; }, "E > 0")),
      nu_(dict.getChecked<double>(
          "nu", [](const double& v) { return v > -1.0 && v < 0.5; }, "-1 < nu < 0.5"))
{}

double LinearElastic::waveSpeed() const
{
    // P-wave speed sqrt((K + 4G/3)/rho) (seed A4).
    return std::sqrt((K() + 4.0 * G() / 3.0) / rho());
}

void LinearElastic::updateStress(Particles& p, const ParticleBlock& block, double) const
{
    const double G2 = 2.0 * G();
    const double alpha1 = K() + 2.0 * G2 / 3.0;  // eq. H.2.2
    const double alpha2 = K() - G2 / 3.0;
    for (std::size_t i = block.begin; i < block.end; ++i) {
        SymTensor& s = p.sigma[i];
        const SymTensor& de = p.dEps[i];
        rotateJaumann(s, p.dOmega[i]);
        s[XX] += alpha1 * de[XX] + alpha2 * de[YY];  // eq. H.2.1
        s[YY] += alpha2 * de[XX] + alpha1 * de[YY];
        s[ZZ] += alpha2 * (de[XX] + de[YY]);
        s[XY] += G2 * de[XY];
        if (de[ZZ] != 0.0) {  // axisymmetric: the hoop strain (plane strain has none)
            s[XX] += alpha2 * de[ZZ];
            s[YY] += alpha2 * de[ZZ];
            s[ZZ] += alpha1 * de[ZZ];
        }
    }
}

} // namespace gpic
