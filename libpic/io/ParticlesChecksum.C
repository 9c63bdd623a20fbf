#include "io/ParticlesChecksum.H"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace gpic {
namespace detail {

namespace {
constexpr std::uint64_t prime = 1099511628211ull;
}

void ParticleChecksum::add(const void* data, std::size_t bytes)
{
    const auto* c = static_cast<const unsigned char*>(data);
    arrayBytes_ += bytes;
    std::size_t k = 0;
    if (pendingBytes_ > 0) {  // complete the word an earlier piece began
        const std::size_t take = std::min<std::size_t>(8 - pendingBytes_, bytes);
        std::memcpy(pending_ + pendingBytes_, c, take);
        pendingBytes_ += take;
        k = take;
        if (pendingBytes_ < 8) return;
        std::uint64_t word;
        std::memcpy(&word, pending_, 8);
        hash_ = (hash_ ^ word) * prime;
        pendingBytes_ = 0;
    }
    for (; k + 8 <= bytes; k += 8) {
        std::uint64_t word;
        std::memcpy(&word, c + k, 8);
        hash_ = (hash_ ^ word) * prime;
    }
    std::memcpy(pending_, c + k, bytes - k);
    pendingBytes_ = bytes - k;
}

void ParticleChecksum::endArray()
{
    for (std::size_t k = 0; k < pendingBytes_; ++k) hash_ = (hash_ ^ pending_[k]) * prime;
    hash_ = (hash_ ^ arrayBytes_) * prime;  // the length too: a shortened array changes the sum
    pendingBytes_ = 0;
    arrayBytes_ = 0;
}

std::string ParticleChecksum::text() const
{
    char text[32];
    std::snprintf(text, sizeof text, "fnv1a64:%016llx", static_cast<unsigned long long>(hash_));
    return text;
}

} // namespace detail
} // namespace gpic
