#include "cosseratElastic/CosseratElastic.H"

#include "dictionary/Dictionary.H"

namespace gpic {

GPIC_REGISTER(Material<2>, CosseratElastic, "cosseratElastic")

CosseratElastic::CosseratElastic(const Dictionary& dict) : Material<2>(dict), elastic_(dict) {}

void CosseratElastic::updateStress(Particles<2>& p, const ParticleBlock& block, double) const
{
    CosseratParticles& c = p.polar;
    for (std::size_t i = block.begin; i < block.end; ++i) {
        CosseratElasticity::rotate(p.sigma[i], c.sigma21[i], c.mu[i], p.dOmega[i]);
        elastic_.addElasticIncrement(p.sigma[i], c.sigma21[i], c.mu[i], p.dEps[i], c.dRotation[i], c.dKappa[i]);
    }
}

} // namespace gpic
