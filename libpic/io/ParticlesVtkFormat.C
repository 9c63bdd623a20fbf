#include "io/ParticlesVtkFormat.H"

#include "core/error.H"
#include "particles/ParticleFields.H"

namespace gpic {
namespace detail {

bool isBuiltinParticleArray(const std::string& name)
{
    // Every array the table writes, in any scene; any other one-component Float64 array is
    // a history variable.
    for (const ParticleField<2>& f : particleFields<2>())
        if (*f.name && name == f.name) return true;
#if GPIC_WITH_3D
    for (const ParticleField<3>& f : particleFields<3>())
        if (*f.name && name == f.name) return true;
#endif
    return false;
}

void cannotReadParticles(const std::string& path, const std::string& why)
{
    throw InputError(path, 0, "cannot read particles: " + why);
}

} // namespace detail
} // namespace gpic
