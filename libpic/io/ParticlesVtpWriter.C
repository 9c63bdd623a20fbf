// writeParticles: the .vtp file written straight from the particle arrays, array by array
// through a fixed buffer, so that writing costs no memory per particle. The bytes are those
// vtkXMLPolyDataWriter (VTK 9.1) writes for a vtkPolyData holding the same arrays, in the
// settings the grid files use (AtomicVtkWrite.C: appended raw data, UInt64 block headers, no
// compressor): the same XML, attribute order, padding, ranges and offsets, so that ParaView
// and VTK's reader see the files they always saw. tests/support/ReferenceParticlesWriter.H
// holds that VTK writer; vtkIoTest compares the two byte for byte.
//
// One case might differ: VTK computes a range in parallel chunks (TBB), so where +0 and -0
// tie for a one-component array's minimum or maximum, its "0" or "-0" could depend on the
// chunks; this writer prints the first in particle order, as VTK did in every trial.
#include "io/ParticlesVtk.H"

#include "io/AtomicFile.H"
#include "io/ParticlesChecksum.H"
#include "io/ParticlesVtkFormat.H"
#include "particles/ParticleFields.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

namespace gpic {

namespace {

enum class ValueType { int32, int64, float64 };

std::size_t valueBytes(ValueType t) { return t == ValueType::int32 ? 4 : 8; }

const char* typeName(ValueType t)
{
    return t == ValueType::int32 ? "Int32" : t == ValueType::int64 ? "Int64" : "Float64";
}

//- One DataArray of the file and how to produce its values.
struct OutputArray {
    std::string name;
    ValueType type = ValueType::float64;
    int components = 1;
    bool componentNames = false;  //- ParaView's "X Y Z" / "XX XY ..." (not on the points)
    std::size_t tuples = 0;
    //- The values of tuples [begin, end): int, std::int64_t or double by `type`.
    std::function<void(std::size_t begin, std::size_t end, void* out)> fill;
    //- Components that hold another state array (sigma21 in `stress`), Float64 arrays only.
    std::vector<std::pair<int, const std::vector<double>*>> stored;
    double range[2] = {0.0, 0.0};  //- RangeMin, RangeMax as VTK writes them
    std::uint64_t offset = 0;      //- of its block in the appended data

    std::uint64_t bytes() const { return tuples * components * valueBytes(type); }
};

// One table entry to file components, by element type (as ParaView expects them).
void put(int value, int* out, int) { out[0] = value; }
void put(double value, double* out, int) { out[0] = value; }
void put(const Vector2& v, double* out, int nComponents)
{
    out[0] = v.x(); out[1] = v.y();
    if (nComponents == 3) out[2] = 0.0;
}
//- Plane-strain (11, 22, 33, 12) as a full 3x3 tensor, row-major.
void put(const SymTensor& s, double* out, int)
{
    out[0] = s[XX]; out[1] = s[XY]; out[2] = 0.0;
    out[3] = s[XY]; out[4] = s[YY]; out[5] = 0.0;
    out[6] = 0.0;   out[7] = 0.0;   out[8] = s[ZZ];
}
//- The affine velocity matrix C_p (a velocity gradient, not symmetric) as a 3x3 tensor.
void put(const PlaneSpace::Gradient& C, double* out, int)
{
    out[0] = C(0, 0); out[1] = C(0, 1); out[2] = 0.0;
    out[3] = C(1, 0); out[4] = C(1, 1); out[5] = 0.0;
    out[6] = 0.0;     out[7] = 0.0;     out[8] = 0.0;
}
void put(const Space<3>::Vector& v, double* out, int)
{
    out[0] = v.x(); out[1] = v.y(); out[2] = v.z();
}
//- (11 22 33 12 23 13) as a full 3x3 tensor, row-major.
void put(const Space<3>::SymTensor& s, double* out, int)
{
    out[0] = s[XX]; out[1] = s[XY]; out[2] = s[XZ];
    out[3] = s[XY]; out[4] = s[YY]; out[5] = s[YZ];
    out[6] = s[XZ]; out[7] = s[YZ]; out[8] = s[ZZ];
}
void put(const Space<3>::Gradient& C, double* out, int)
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[3 * i + j] = C(i, j);
}

template <int D> OutputArray stateArray(const ParticleField<D>& f, const Particles<D>& p)
{
    OutputArray a;
    a.name = f.name;
    a.components = f.components;
    a.componentNames = f.components > 1;
    const FieldArray<D> source = fieldArray(f, p);
    a.tuples = std::visit([](const auto* values) { return values->size(); }, source);
    a.type = std::holds_alternative<std::vector<int>*>(source) ? ValueType::int32 : ValueType::float64;
    const int nc = f.components;
    a.fill = [source, nc](std::size_t begin, std::size_t end, void* out) {
        std::visit(
            [&](const auto* values) {
                using T = typename std::decay_t<decltype(*values)>::value_type;
                using Out = std::conditional_t<std::is_same_v<T, int>, int, double>;
                Out* o = static_cast<Out*>(out);
                for (std::size_t i = begin; i < end; ++i) put((*values)[i], o + nc * (i - begin), nc);
            },
            source);
    };
    return a;
}

template <int D> OutputArray derivedArray(const ParticleField<D>& f, const Particles<D>& p)
{
    OutputArray a;
    a.name = f.name;
    a.components = f.components;
    a.componentNames = f.components > 1;
    a.tuples = p.size();
    const int nc = f.components;
    const auto derive = f.derive;
    a.fill = [&p, nc, derive](std::size_t begin, std::size_t end, void* out) {
        double* o = static_cast<double*>(out);
        for (std::size_t i = begin; i < end; ++i) derive(p, i, o + nc * (i - begin));
    };
    return a;
}

OutputArray scalarArray(const std::string& name, const std::vector<double>& values)
{
    OutputArray a;
    a.name = name;
    a.tuples = values.size();
    a.fill = [&values](std::size_t begin, std::size_t end, void* out) {
        std::copy(values.begin() + begin, values.begin() + end, static_cast<double*>(out));
    };
    return a;
}

template <int D> OutputArray pointsArray(const Particles<D>& p)
{
    OutputArray a;
    a.name = "Points";
    a.components = 3;
    a.tuples = p.size();
    a.fill = [&p](std::size_t begin, std::size_t end, void* out) {
        double* o = static_cast<double*>(out);
        for (std::size_t i = begin; i < end; ++i, o += 3) {
            o[0] = p.x[i].x(); o[1] = p.x[i].y(); o[2] = D == 3 ? p.x[i][D - 1] : 0.0;
        }
    };
    return a;
}

//- The vertex cells' arrays: VTK writes the offsets without their leading 0.
OutputArray cellArray(const char* name, std::size_t tuples, std::int64_t first)
{
    OutputArray a;
    a.name = name;
    a.type = ValueType::int64;
    a.tuples = tuples;
    a.fill = [first](std::size_t begin, std::size_t end, void* out) {
        auto* o = static_cast<std::int64_t*>(out);
        for (std::size_t i = begin; i < end; ++i) *o++ = first + static_cast<std::int64_t>(i);
    };
    return a;
}

//- Calls use(values, tuples) for consecutive pieces of `a`, produced in `buffer` (which
//  holds at least one tuple of 9 components).
template <class Use>
void forEachPiece(const OutputArray& a, std::vector<double>& buffer, Use use)
{
    const std::size_t bytesPerTuple = a.components * valueBytes(a.type);
    const std::size_t step = buffer.size() * sizeof(double) / bytesPerTuple;
    for (std::size_t begin = 0; begin < a.tuples; begin += step) {
        const std::size_t end = std::min(a.tuples, begin + step);
        a.fill(begin, end, buffer.data());
        for (const auto& [component, values] : a.stored)
            for (std::size_t i = begin; i < end; ++i) buffer[a.components * (i - begin) + component] = (*values)[i];
        use(static_cast<const void*>(buffer.data()), end - begin);
    }
}

//- The range VTK writes (vtkDataArray::GetRange(-1)): of the values for one component, of
//  the tuples' magnitude for more; {1e299, -1e299} (VTK_DOUBLE_MAX/MIN) without tuples.
//  std::min/max in VTK's argument order, so that NaNs are passed over as VTK does.
class VtkRange {
public:
    explicit VtkRange(int components) : components_(components) {}
    template <class T> void add(const T* values, std::size_t tuples)
    {
        for (std::size_t t = 0; t < tuples; ++t, values += components_) {
            double v;
            if (components_ == 1) v = static_cast<double>(values[0]);
            else {
                v = 0.0;  // the squared magnitude, summed in component order as VTK does
                for (int c = 0; c < components_; ++c) v += static_cast<double>(values[c]) * static_cast<double>(values[c]);
            }
            lo_ = std::min(lo_, v);
            hi_ = std::max(hi_, v);
        }
        any_ = any_ || tuples > 0;
    }
    void get(double range[2]) const
    {
        range[0] = lo_;
        range[1] = hi_;
        if (any_ && components_ > 1) {
            range[0] = std::sqrt(lo_);
            range[1] = std::sqrt(hi_);
        }
    }

private:
    int components_;
    double lo_ = 1.0e+299, hi_ = -1.0e+299;
    bool any_ = false;
};

//- Range and checksum of every array, from a first pass over the particles.
void scan(OutputArray& a, std::vector<double>& buffer, detail::ParticleChecksum* checksum)
{
    VtkRange range(a.components);
    const std::size_t bytesPerTuple = a.components * valueBytes(a.type);
    forEachPiece(a, buffer, [&](const void* values, std::size_t tuples) {
        if (a.type == ValueType::int32) range.add(static_cast<const int*>(values), tuples);
        else if (a.type == ValueType::float64) range.add(static_cast<const double*>(values), tuples);
        if (checksum) checksum->add(values, tuples * bytesPerTuple);
    });
    if (checksum) checksum->endArray();
    range.get(a.range);
}

//- A double as vtkXMLWriter prints it: a C-locale stream with precision 11.
std::string vtkNumber(double value)
{
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os.precision(11);
    os << value;
    return os.str();
}

//- vtkXMLWriter reserves ` name=""` and 20 spaces for a value it learns later and then
//  writes ` name="value"` over the start of it.
void reserved(std::string& xml, const char* name, const std::string& value)
{
    xml += ' ';
    xml += name;
    xml += "=\"" + value + '"';
    if (value.size() < 20) xml.append(20 - value.size(), ' ');
}

std::string indent(int level) { return std::string(2 * level, ' '); }

void dataArrayElement(std::string& xml, int level, const OutputArray& a, bool numberOfTuples, bool range)
{
    static const char* const tensor[9] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
    static const char* const vector[3] = {"X", "Y", "Z"};
    xml += indent(level) + "<DataArray type=\"" + typeName(a.type) + "\" Name=\"" + a.name + '"';
    if (a.components > 1) xml += " NumberOfComponents=\"" + std::to_string(a.components) + '"';
    if (a.componentNames)
        for (int c = 0; c < a.components; ++c)
            xml += " ComponentName" + std::to_string(c) + "=\"" + (a.components == 9 ? tensor[c] : vector[c]) + '"';
    if (numberOfTuples) xml += " NumberOfTuples=\"" + std::to_string(a.tuples) + '"';
    xml += " format=\"appended\"";
    // VTK fills in the ranges of point and field arrays, not those of the cell arrays.
    reserved(xml, "RangeMin", range ? vtkNumber(a.range[0]) : "");
    reserved(xml, "RangeMax", range ? vtkNumber(a.range[1]) : "");
    reserved(xml, "offset", std::to_string(a.offset));
    xml += "/>\n";
}

//- A field array of strings, each written with its terminating '\0'.
struct StringArray {
    const char* name;
    const std::vector<std::string>* values;
    std::uint64_t offset = 0;

    std::uint64_t bytes() const
    {
        std::uint64_t n = 0;
        for (const std::string& s : *values) n += s.size() + 1;
        return n;
    }
};

void stringArrayElement(std::string& xml, int level, const StringArray& a)
{
    xml += indent(level) + "<Array type=\"String\" Name=\"" + a.name + "\" NumberOfTuples=\"" +
           std::to_string(a.values->size()) + "\" format=\"appended\"";
    reserved(xml, "offset", std::to_string(a.offset));
    xml += "/>\n";
}

void writeBlockHeader(detail::AtomicFile& out, std::uint64_t bytes)
{
    static_assert(sizeof bytes == 8);
    out.write(&bytes, sizeof bytes);  // the UInt64 byte count, little-endian like the data
}

void writeBlock(detail::AtomicFile& out, const OutputArray& a, std::vector<double>& buffer)
{
    writeBlockHeader(out, a.bytes());
    const std::size_t bytesPerTuple = a.components * valueBytes(a.type);
    forEachPiece(a, buffer, [&](const void* values, std::size_t tuples) { out.write(values, tuples * bytesPerTuple); });
}

void writeBlock(detail::AtomicFile& out, const StringArray& a)
{
    writeBlockHeader(out, a.bytes());
    for (const std::string& s : *a.values) out.write(s.c_str(), s.size() + 1);
}

} // namespace

template <int D>
void writeParticles(const std::string& path, const Particles<D>& p, double time,
                    const std::vector<std::string>& materialNames,
                    const std::vector<std::string>& bodyNames)
{
    static_assert(sizeof(int) == 4 && sizeof(double) == 8, "Int32 and Float64 on file");
    static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the header says LittleEndian");
    for (const auto& name : p.historyNames())
        if (detail::isBuiltinParticleArray(name))
            throw std::logic_error("particle history variable '" + name +
                                   "' has the name of a built-in output array");
    const std::size_t n = p.size();

    // The point arrays in the order of the table, then the history variables.
    std::vector<OutputArray> pointArrays;
    for (const ParticleField<D>& f : particleFields<D>()) {
        if (!p.carries(f.group) || f.role == FieldRole::scratch || f.storedIn) continue;
        pointArrays.push_back(f.role == FieldRole::derived ? derivedArray(f, p) : stateArray(f, p));
    }
    for (const ParticleField<D>& f : particleFields<D>()) {  // arrays stored inside another (not the points)
        if (!p.carries(f.group) || !f.storedIn) continue;
        for (OutputArray& into : pointArrays)
            if (into.name == f.storedIn && into.type == ValueType::float64)
                into.stored.emplace_back(f.storedComponent, std::get<std::vector<double>*>(fieldArray(f, p)));
    }
    for (const auto& name : p.historyNames()) pointArrays.push_back(scalarArray(name, p.history(name)));
    OutputArray points = pointsArray(p);
    // One vertex cell per point, so ParaView renders the points without a glyph filter;
    // VTK writes the lines, strips and polygons as empty cell arrays.
    std::vector<OutputArray> cellArrays{cellArray("connectivity", n, 0), cellArray("offsets", n, 1)};
    for (int empty = 0; empty < 3; ++empty) {
        cellArrays.push_back(cellArray("connectivity", 0, 0));
        cellArrays.push_back(cellArray("offsets", 0, 0));
    }

    // First pass: the ranges the header holds and the checksum (points, then point arrays).
    std::vector<double> buffer(1 << 15);
    detail::ParticleChecksum checksum;
    scan(points, buffer, &checksum);
    for (OutputArray& a : pointArrays) scan(a, buffer, &checksum);
    const std::vector<std::string> checksumText{checksum.text()};

    // "TimeValue" is the field ParaView shows as the dataset time.
    OutputArray timeValue;
    timeValue.name = "TimeValue";
    timeValue.tuples = 1;
    timeValue.fill = [time](std::size_t, std::size_t, void* out) { *static_cast<double*>(out) = time; };
    scan(timeValue, buffer, nullptr);
    std::vector<StringArray> strings{{"materialNames", &materialNames},
                                     {"bodyNames", &bodyNames},
                                     {"checksum", &checksumText}};

    // The blocks follow in the order of the header's arrays.
    std::uint64_t offset = 0;
    const auto place = [&offset](auto& a) {
        a.offset = offset;
        offset += 8 + a.bytes();
    };
    place(timeValue);
    for (StringArray& a : strings) place(a);
    for (OutputArray& a : pointArrays) place(a);
    place(points);
    for (OutputArray& a : cellArrays) place(a);

    std::string xml = "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                      "header_type=\"UInt64\">\n" +
                      indent(1) + "<PolyData>\n" + indent(2) + "<FieldData>\n";
    dataArrayElement(xml, 3, timeValue, true, true);
    for (const StringArray& a : strings) stringArrayElement(xml, 3, a);
    xml += indent(2) + "</FieldData>\n" + indent(2) + "<Piece";
    reserved(xml, "NumberOfPoints", std::to_string(n));
    reserved(xml, "NumberOfVerts", std::to_string(n));
    for (const char* none : {"NumberOfLines", "NumberOfStrips", "NumberOfPolys"}) reserved(xml, none, "0");
    xml += ">\n" + indent(3) + "<PointData>\n";
    for (const OutputArray& a : pointArrays) dataArrayElement(xml, 4, a, false, true);
    xml += indent(3) + "</PointData>\n" + indent(3) + "<CellData>\n" + indent(3) + "</CellData>\n" +
           indent(3) + "<Points>\n";
    dataArrayElement(xml, 4, points, false, true);
    xml += indent(3) + "</Points>\n";
    const char* const cellKinds[4] = {"Verts", "Lines", "Strips", "Polys"};
    for (int k = 0; k < 4; ++k) {
        xml += indent(3) + "<" + cellKinds[k] + ">\n";
        dataArrayElement(xml, 4, cellArrays[2 * k], false, false);
        dataArrayElement(xml, 4, cellArrays[2 * k + 1], false, false);
        xml += indent(3) + "</" + cellKinds[k] + ">\n";
    }
    xml += indent(2) + "</Piece>\n" + indent(1) + "</PolyData>\n" + indent(1) +
           "<AppendedData encoding=\"raw\">\n" + indent(1) + " _";

    // Second pass: the data, straight from the particles.
    detail::AtomicFile out(path, "particles");
    out.write(xml.data(), xml.size());
    writeBlock(out, timeValue, buffer);
    for (const StringArray& a : strings) writeBlock(out, a);
    for (const OutputArray& a : pointArrays) writeBlock(out, a, buffer);
    writeBlock(out, points, buffer);
    for (const OutputArray& a : cellArrays) writeBlock(out, a, buffer);
    const std::string tail = "\n" + indent(1) + "</AppendedData>\n</VTKFile>\n";
    out.write(tail.data(), tail.size());
    out.commit();
}

template void writeParticles(const std::string&, const Particles<2>&, double, const std::vector<std::string>&,
                             const std::vector<std::string>&);
#if GPIC_WITH_3D
template void writeParticles(const std::string&, const Particles<3>&, double, const std::vector<std::string>&,
                             const std::vector<std::string>&);
#endif

} // namespace gpic
