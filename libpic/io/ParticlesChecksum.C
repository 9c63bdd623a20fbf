#include "io/ParticlesChecksum.H"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cstdint>
#include <cstring>
#include <cstdio>

namespace gpic {
namespace detail {

namespace {
constexpr std::uint64_t offsetBasis = 14695981039346656037ull, prime = 1099511628211ull;

void hashBytes(std::uint64_t& h, const void* data, std::size_t bytes)
{
    const auto* c = static_cast<const unsigned char*>(data);
    std::size_t k = 0;
    for (; k + 8 <= bytes; k += 8) {
        std::uint64_t word;
        std::memcpy(&word, c + k, 8);
        h = (h ^ word) * prime;
    }
    for (; k < bytes; ++k) h = (h ^ c[k]) * prime;
}

void hashArray(std::uint64_t& h, vtkDataArray* a)
{
    if (!a) return;
    const auto bytes = static_cast<std::size_t>(a->GetNumberOfValues()) * static_cast<std::size_t>(a->GetDataTypeSize());
    if (bytes > 0) hashBytes(h, a->GetVoidPointer(0), bytes);
    h = (h ^ bytes) * prime;  // the length too: a shortened array changes the sum
}
} // namespace

std::string particleDataChecksum(vtkPolyData* poly)
{
    std::uint64_t h = offsetBasis;
    if (poly->GetPoints()) hashArray(h, poly->GetPoints()->GetData());
    vtkPointData* pd = poly->GetPointData();
    for (int i = 0; pd && i < pd->GetNumberOfArrays(); ++i) hashArray(h, pd->GetArray(i));
    char text[32];
    std::snprintf(text, sizeof text, "fnv1a64:%016llx", static_cast<unsigned long long>(h));
    return text;
}

} // namespace detail
} // namespace gpic
