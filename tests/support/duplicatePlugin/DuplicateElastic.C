// A user library that registers a material under a name the project already has
// (linearElastic): loading it must be an error naming both libraries (pluginRegistryTest).
#include "materials/Material.H"

namespace gpic {
namespace {

class DuplicateElastic : public Material<2> {
public:
    using Material<2>::Material;
    double waveSpeed() const override { return 1.0; }
    void updateStress(Particles<2>&, const ParticleBlock&, double) const override {}
};

} // namespace

GPIC_REGISTER(Material<2>, DuplicateElastic, "linearElastic")

} // namespace gpic
