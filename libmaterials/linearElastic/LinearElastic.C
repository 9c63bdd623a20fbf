#include "linearElastic/LinearElastic.H"

#include "dictionary/Dictionary.H"
#include "materials/JaumannRate.H"

namespace gpic {

GPIC_REGISTER_DIMS(Material, LinearElastic, "linearElastic")

template <int D>
LinearElastic<D>::LinearElastic(const Dictionary& dict)
    : Material<D>(dict),
      E_(dict.getChecked<double>("E", [](const double& v) { return v > 0; }, "E > 0")),
      nu_(dict.getChecked<double>(
          "nu", [](const double& v) { return v > -1.0 && v < 0.5; }, "-1 < nu < 0.5")),
      elastic_(E_, nu_)
{}

template <int D> void LinearElastic<D>::updateStress(Particles<D>& p, const ParticleBlock& block, double) const
{
    for (std::size_t i = block.begin; i < block.end; ++i) {
        typename Space<D>::SymTensor& s = p.sigma[i];
        rotateJaumann(s, p.dOmega[i]);
        elastic_.addElasticIncrement(s, p.dEps[i]);  // eq. H.2.1
    }
}

template class LinearElastic<2>;
#if GPIC_WITH_3D
template class LinearElastic<3>;
#endif

} // namespace gpic
