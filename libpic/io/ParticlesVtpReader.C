// readParticles: the .vtp file read straight into the particle arrays, array by array through
// a fixed buffer, so that reading costs no memory per particle beyond the particles. The file
// is the layout writeParticles writes (checkParticlesLayout refuses any other); its arrays
// are taken as vtkXMLPolyDataReader gives them: point arrays by name (a later array of a name
// replaces an earlier one), any numeric type converted as vtkDataArray::GetComponent does.
#include "io/ParticlesVtk.H"

#include "io/ParticlesChecksum.H"
#include "io/ParticlesVtkCheck.H"
#include "io/ParticlesVtkFormat.H"
#include "particles/ParticleFields.H"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <type_traits>
#include <variant>

namespace gpic {

using detail::cannotReadParticles;
using detail::isBuiltinParticleArray;
using detail::ParticleFileArray;

namespace {

using Section = ParticleFileArray::Section;

//- The arrays of one section, by name as VTK's field data holds them: a later array of a
//  name takes the place of an earlier one.
std::vector<const ParticleFileArray*> section(const detail::ParticlesFileLayout& layout, Section s)
{
    std::vector<const ParticleFileArray*> arrays;
    for (const ParticleFileArray& a : layout.arrays) {
        if (a.section != s) continue;
        auto same = std::find_if(arrays.begin(), arrays.end(), [&](const auto* b) { return b->name == a.name; });
        if (same != arrays.end()) *same = &a;
        else arrays.push_back(&a);
    }
    return arrays;
}

//- The numeric array `name` (VTK's GetArray: string arrays are not found).
const ParticleFileArray* numericArray(const std::vector<const ParticleFileArray*>& arrays, const std::string& name)
{
    for (const ParticleFileArray* a : arrays)
        if (a->name == name) return a->type == "String" ? nullptr : a;
    return nullptr;
}

//- The point array `name` with `nComponents` components and one tuple per point.
const ParticleFileArray* required(const std::vector<const ParticleFileArray*>& pointArrays, const char* name,
                                  std::uint64_t nComponents, std::uint64_t n, const std::string& path)
{
    const ParticleFileArray* a = numericArray(pointArrays, name);
    if (!a) cannotReadParticles(path, std::string("missing point array '") + name + "'");
    if (a->components != nComponents || a->tuples != n)
        cannotReadParticles(path, std::string("point array '") + name + "' has " + std::to_string(a->tuples) +
                                      " tuples of " + std::to_string(a->components) + " components, expected " +
                                      std::to_string(n) + " of " + std::to_string(nComponents));
    return a;
}

template <int D> bool inPoints(const ParticleField<D>& f) { return f.storedIn && std::string(f.storedIn) == "points"; }

//- One value of VTK type `type` at `bytes`, as a double (vtkDataArray::GetComponent).
template <class T> double as(const unsigned char* bytes)
{
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return static_cast<double>(value);
}

using Converter = double (*)(const unsigned char*);

std::pair<Converter, std::size_t> converter(const std::string& type)
{
    if (type == "Float64") return {as<double>, 8};
    if (type == "Int32") return {as<std::int32_t>, 4};
    if (type == "Float32") return {as<float>, 4};
    if (type == "Int64") return {as<std::int64_t>, 8};
    if (type == "UInt64") return {as<std::uint64_t>, 8};
    if (type == "UInt32") return {as<std::uint32_t>, 4};
    if (type == "Int16") return {as<std::int16_t>, 2};
    if (type == "UInt16") return {as<std::uint16_t>, 2};
    if (type == "Int8") return {as<std::int8_t>, 1};
    return {as<std::uint8_t>, 1};  // UInt8: the layout check has refused every other type
}

// File components (c: the tuple's first) to one table entry, by element type.
void get(const double* c, int& out) { out = static_cast<int>(c[0]); }
void get(const double* c, double& out) { out = c[0]; }
void get(const double* c, Vector2& out) { out = Vector2(c[0], c[1]); }
//- The full 3x3 tensor's (11, 22, 33, 12).
void get(const double* c, SymTensor& out) { out = SymTensor(c[0], c[4], c[8], c[1]); }
void get(const double* c, PlaneSpace::Gradient& out) { out << c[0], c[1], c[3], c[4]; }
void get(const double* c, Space<3>::Vector& out) { out = Space<3>::Vector(c[0], c[1], c[2]); }
//- The full 3x3 tensor's (11 22 33 12 23 13).
void get(const double* c, Space<3>::SymTensor& out) { out << c[0], c[4], c[8], c[1], c[5], c[2]; }
void get(const double* c, Space<3>::Gradient& out) { out << c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]; }

//- Where the values of one file array go: a table entry, one component of the array into
//  a double array, or the positions.
template <int D> struct Destination {
    FieldArray<D> array;
    int component = 0;  //- > 0: that component only (an array stored in another)
};

//- Reads file arrays piecewise through fixed buffers: the raw bytes to the checksum, the
//  values converted to doubles to their destinations.
class ArrayReader {
public:
    explicit ArrayReader(const std::string& path)
        : path_(path), in_(path, std::ios::binary), values_(bufferValues), raw_(bufferValues * 8)
    {
    }

    template <int D>
    void read(const ParticleFileArray& a, detail::ParticleChecksum* checksum, const std::vector<Destination<D>>& to)
    {
        in_.seekg(static_cast<std::streamoff>(a.dataAt));
        if (to.empty()) {  // only summed: the bytes in any pieces
            if (!checksum) return;
            for (std::uint64_t left = a.bytes; left > 0;) {
                const auto bytes = static_cast<std::size_t>(std::min<std::uint64_t>(left, raw_.size()));
                fill(a, bytes);
                checksum->add(raw_.data(), bytes);
                left -= bytes;
            }
            checksum->endArray();
            return;
        }
        const auto [convert, size] = converter(a.type);
        const auto nc = static_cast<std::size_t>(a.components);
        const std::size_t step = values_.size() / nc;
        for (std::size_t begin = 0; begin < a.tuples; begin += step) {
            const std::size_t count = std::min<std::size_t>(step, a.tuples - begin);
            fill(a, count * nc * size);
            if (checksum) checksum->add(raw_.data(), count * nc * size);
            for (std::size_t k = 0; k < count * nc; ++k) values_[k] = convert(raw_.data() + k * size);
            for (const Destination<D>& d : to) store(d, begin, count, nc);
        }
        if (checksum) checksum->endArray();
    }

    //- The first value of `a` (which has one).
    double first(const ParticleFileArray& a)
    {
        const auto [convert, size] = converter(a.type);
        in_.seekg(static_cast<std::streamoff>(a.dataAt));
        fill(a, size);
        return convert(raw_.data());
    }

private:
    static constexpr std::size_t bufferValues = 1 << 15;  //- at least one tuple of 9 components

    void fill(const ParticleFileArray& a, std::size_t bytes)
    {
        // The layout check has seen the data inside the file: only a file changed since fails.
        if (!in_.read(reinterpret_cast<char*>(raw_.data()), static_cast<std::streamsize>(bytes)))
            cannotReadParticles(path_, "truncated or corrupt: data of array '" + a.name +
                                           "' runs past the end of the file");
    }

    template <int D> void store(const Destination<D>& d, std::size_t begin, std::size_t count, std::size_t nc) const
    {
        std::visit(
            [&](auto* values) {
                for (std::size_t t = 0; t < count; ++t) {
                    const double* c = values_.data() + t * nc;
                    if (d.component == 0) get(c, (*values)[begin + t]);
                    else if constexpr (std::is_same_v<std::decay_t<decltype(*values)>, std::vector<double>>)
                        (*values)[begin + t] = c[d.component];
                }
            },
            d.array);
    }

    std::string path_;
    std::ifstream in_;
    std::vector<double> values_;
    std::vector<unsigned char> raw_;
};

} // namespace

template <int D>
void readParticles(const std::string& path, Particles<D>& p, double& time,
                   std::vector<std::string>* materialNames, std::vector<std::string>* bodyNames,
                   bool requireChecksum)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) cannotReadParticles(path, "no such file");
    const detail::ParticlesFileLayout layout = detail::checkParticlesLayout(path);
    const auto fieldArrays = section(layout, Section::field);
    const auto pointArrays = section(layout, Section::point);
    const auto pointsArrays = section(layout, Section::points);

    const std::uint64_t n64 = layout.nPoints;
    const auto n = static_cast<std::size_t>(n64);
    const ParticleFileArray* points =
        pointsArrays.empty() || pointsArrays.front()->type == "String" ? nullptr : pointsArrays.front();
    if (n > 0 && !points) cannotReadParticles(path, "missing points");
    if (points && points->components != 3)
        cannotReadParticles(path, "the points have " + std::to_string(points->components) + " components, expected 3");

    // Look every required array up before touching p, so a bad file leaves p unchanged. An
    // optional group is in the file when its first array is; then all of its arrays must be.
    const std::vector<ParticleField<D>>& fields = particleFields<D>();
    std::array<bool, 4> groupInFile{true, false, false, false};
    for (const ParticleField<D>& f : fields)
        if (f.group != FieldGroup::core && f.role == FieldRole::state && *f.name && numericArray(pointArrays, f.name))
            groupInFile[static_cast<int>(f.group)] = true;
    std::vector<const ParticleFileArray*> arrays(fields.size(), nullptr);
    for (std::size_t k = 0; k < fields.size(); ++k) {
        const ParticleField<D>& f = fields[k];
        if (f.role != FieldRole::state || !groupInFile[static_cast<int>(f.group)] || inPoints(f)) continue;
        arrays[k] = f.storedIn ? numericArray(pointArrays, f.storedIn)
                               : required(pointArrays, f.name, static_cast<std::uint64_t>(f.components), n64, path);
        if (f.storedIn && arrays[k] && arrays[k]->components <= static_cast<std::uint64_t>(f.storedComponent))
            cannotReadParticles(path, std::string("point array '") + f.storedIn + "' has " +
                                          std::to_string(arrays[k]->components) + " components");
    }
    const auto strings = [&](const char* name) {
        for (const ParticleFileArray* a : fieldArrays)
            if (a->name == name) return a->type == "String" ? a->strings : std::vector<std::string>{};
        return std::vector<std::string>{};
    };
    // Files written before the checksum have none; those with one must match it.
    const std::vector<std::string> sum = strings("checksum");
    if (sum.empty() && requireChecksum)
        cannotReadParticles(path, "it has no checksum (the field array 'checksum' picInit and picSolver write): "
                                  "a run starts only from a state it can check");
    detail::ParticleChecksum checksum;
    detail::ParticleChecksum* const check = sum.empty() ? nullptr : &checksum;

    Particles<D> result;
    for (const ParticleField<D>& f : fields)
        if (f.group != FieldGroup::core && groupInFile[static_cast<int>(f.group)]) result.carry(f.group);
    result.resize(n);
    ArrayReader reader(path);
    // The checksum's order: the points, then the point arrays in file order.
    if (points) {
        std::vector<Destination<D>> to;
        for (const ParticleField<D>& f : fields)
            if (inPoints(f)) to.push_back({f.array(result), 0});
        reader.read(*points, check, to);
    }
    for (const ParticleFileArray* a : pointArrays) {
        if (a->type == "String") continue;  // not a data array: neither read nor summed
        std::vector<Destination<D>> to;
        for (std::size_t k = 0; k < fields.size(); ++k)
            if (arrays[k] == a) to.push_back({fields[k].array(result), fields[k].storedIn ? fields[k].storedComponent : 0});
        // History variables are exactly the extra one-component Float64 arrays.
        if (!a->name.empty() && !isBuiltinParticleArray(a->name) && a->type == "Float64" && a->components == 1) {
            if (a->tuples != n64)
                cannotReadParticles(path, "point array '" + a->name + "' has " + std::to_string(a->tuples) +
                                              " tuples, expected " + std::to_string(n));
            result.declareHistory(a->name);
            to.push_back({&result.history(a->name), 0});
        }
        reader.read(*a, check, to);
    }
    if (check && sum.front() != checksum.text())
        cannotReadParticles(path, "its data do not match the checksum written with them: the file is damaged");

    const ParticleFileArray* timeValue = numericArray(fieldArrays, "TimeValue");
    if (!timeValue || timeValue->tuples < 1 || timeValue->bytes == 0)
        cannotReadParticles(path, "missing field 'TimeValue'");
    time = reader.first(*timeValue);
    if (materialNames) *materialNames = strings("materialNames");
    if (bodyNames) *bodyNames = strings("bodyNames");
    p = std::move(result);
}

template void readParticles(const std::string&, Particles<2>&, double&, std::vector<std::string>*,
                            std::vector<std::string>*, bool);
#if GPIC_WITH_3D
template void readParticles(const std::string&, Particles<3>&, double&, std::vector<std::string>*,
                            std::vector<std::string>*, bool);
#endif

} // namespace gpic
