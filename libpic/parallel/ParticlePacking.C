#include "parallel/ParticlePacking.H"

#include "particles/ParticleFields.H"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace gpic {

namespace {

//- Calls f(data pointer of element q, bytes per element) for every array p carries.
template <int D, class F> void forEachArray(Particles<D>& p, F&& f)
{
    for (const auto& field : particleFields<D>()) {
        if (!field.array || field.role == FieldRole::derived || !p.carries(field.group)) continue;
        std::visit([&](auto* array) { f(*array); }, field.array(p));
    }
    for (const auto& name : p.historyNames()) f(p.history(name));
}

} // namespace

template <int D> std::vector<char> packParticles(const Particles<D>& p, const std::vector<std::size_t>& which)
{
    auto& q = const_cast<Particles<D>&>(p);  // the walk reads only
    std::size_t perParticle = 0;
    forEachArray(q, [&](auto& array) { perParticle += sizeof(typename std::decay_t<decltype(array)>::value_type); });
    std::vector<char> bytes(sizeof(std::uint64_t) * 2 + perParticle * which.size());
    const std::uint64_t header[2] = {which.size(), perParticle};
    std::memcpy(bytes.data(), header, sizeof header);
    char* out = bytes.data() + sizeof header;
    forEachArray(q, [&](auto& array) {
        const std::size_t size = sizeof(typename std::decay_t<decltype(array)>::value_type);
        for (std::size_t k : which) std::memcpy(out, &array[k], size), out += size;
    });
    return bytes;
}

template <int D> std::size_t unpackParticles(const std::vector<char>& bytes, Particles<D>& p)
{
    std::uint64_t header[2] = {0, 0};
    if (bytes.size() < sizeof header) throw std::runtime_error("unpackParticles: no header");
    std::memcpy(header, bytes.data(), sizeof header);
    std::size_t perParticle = 0;
    forEachArray(p, [&](auto& array) { perParticle += sizeof(typename std::decay_t<decltype(array)>::value_type); });
    const std::size_t n = header[0];
    if (header[1] != perParticle || bytes.size() != sizeof header + n * perParticle)
        throw std::runtime_error("unpackParticles: the particles carry other arrays than this set");
    const std::size_t first = p.size();
    p.resize(first + n);
    const char* in = bytes.data() + sizeof header;
    forEachArray(p, [&](auto& array) {
        const std::size_t size = sizeof(typename std::decay_t<decltype(array)>::value_type);
        for (std::size_t k = 0; k < n; ++k) std::memcpy(&array[first + k], in, size), in += size;
    });
    return n;
}

template std::vector<char> packParticles<2>(const Particles<2>&, const std::vector<std::size_t>&);
template std::size_t unpackParticles<2>(const std::vector<char>&, Particles<2>&);
#if GPIC_WITH_3D
template std::vector<char> packParticles<3>(const Particles<3>&, const std::vector<std::size_t>&);
template std::size_t unpackParticles<3>(const std::vector<char>&, Particles<3>&);
#endif

} // namespace gpic
