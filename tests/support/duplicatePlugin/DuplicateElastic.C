// A user library that registers a material under a name the project already has
// (linearElastic): loading it must be an error naming both libraries (pluginRegistryTest).
#include "materials/Material.H"

namespace gpic {
namespace {

class DuplicateElastic : public Material {
public:
    using Material::Material;
    double waveSpeed() const override { return 1.0; }
    void updateStress(Particles&, const ParticleBlock&, double) const override {}
};

} // namespace

GPIC_REGISTER(Material, DuplicateElastic, "linearElastic")

} // namespace gpic
