#include "io/ParticlesVtkFormat.H"

#include "core/error.H"

#include <array>

namespace gpic {
namespace detail {

namespace {

// Arrays written by writeParticles; any other one-component Float64 array is a history variable.
const std::array<const char*, 21> builtinArrays{
    "id", "body", "material", "velocity", "displacement", "initialPosition", "mass", "volume",
    "halfSize", "stress", "strain", "plasticStrain", "pressure", "vonMisesStress", "work",
    // Cosserat scenes only
    "microRotation", "microRotationRate", "coupleStress", "curvature",
    // APIC only
    "affineVelocity", "affineKineticEnergy"};

} // namespace

bool isBuiltinParticleArray(const std::string& name)
{
    for (const char* b : builtinArrays)
        if (name == b) return true;
    return false;
}

void cannotReadParticles(const std::string& path, const std::string& why)
{
    throw InputError(path, 0, "cannot read particles: " + why);
}

} // namespace detail
} // namespace gpic
