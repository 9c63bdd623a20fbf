#include "io/ParticlesVtk.H"

#include "core/error.H"
#include "particles/Particles.H"

#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace gpic {

namespace {

// Arrays written by writeParticles; any other one-component Float64 array is a history variable.
const std::array<const char*, 15> builtinArrays{
    "id", "body", "material", "velocity", "displacement", "initialPosition", "mass", "volume",
    "halfSize", "stress", "strain", "plasticStrain", "pressure", "vonMisesStress", "work"};

bool isBuiltin(const std::string& name)
{
    for (const char* b : builtinArrays)
        if (name == b) return true;
    return false;
}

//- Collects VTK error/warning events so they become exceptions instead of stderr noise.
class ErrorCollector : public vtkCommand {
public:
    static ErrorCollector* New() { return new ErrorCollector; }
    void Execute(vtkObject*, unsigned long event, void* callData) override
    {
        if (event != vtkCommand::ErrorEvent) return;
        std::string text = callData ? static_cast<const char*>(callData) : "unknown VTK error";
        // VTK prefixes "ERROR: In file.cxx, line N\nClass (0x...): "; keep only the message.
        const auto colon = text.rfind("): ");
        if (colon != std::string::npos) text = text.substr(colon + 3);
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
        if (first.empty()) first = text;
        failed = true;
    }
    bool failed = false;
    std::string first;  //- the first error (later ones are usually consequences)
};

//- Silences VTK's global error output while a reader parses a possibly broken file (the XML
//  parser reports through its own object, which an observer on the reader does not see).
class QuietVtk {
public:
    QuietVtk() : previous_(vtkObject::GetGlobalWarningDisplay())
    {
        vtkObject::GlobalWarningDisplayOff();
    }
    ~QuietVtk() { vtkObject::SetGlobalWarningDisplay(previous_); }
    QuietVtk(const QuietVtk&) = delete;
    QuietVtk& operator=(const QuietVtk&) = delete;

private:
    int previous_;
};

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, int nComponents, vtkIdType n)
{
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(nComponents);
    a->SetNumberOfTuples(n);
    return a;
}

vtkSmartPointer<vtkIntArray> intArray(const char* name, const std::vector<int>& values)
{
    auto a = vtkSmartPointer<vtkIntArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(1);
    a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
    std::copy(values.begin(), values.end(), a->GetPointer(0));
    return a;
}

//- Plane-strain (11, 22, 33, 12) as a full 3x3 tensor, row-major, as ParaView expects.
void fullTensor(const SymTensor& s, double* out)
{
    out[0] = s[XX]; out[1] = s[XY]; out[2] = 0.0;
    out[3] = s[XY]; out[4] = s[YY]; out[5] = 0.0;
    out[6] = 0.0;   out[7] = 0.0;   out[8] = s[ZZ];
}

vtkSmartPointer<vtkDoubleArray> tensorArray(const char* name, const std::vector<SymTensor>& t)
{
    auto a = doubleArray(name, 9, static_cast<vtkIdType>(t.size()));
    double* out = a->GetPointer(0);
    for (std::size_t i = 0; i < t.size(); ++i) fullTensor(t[i], out + 9 * i);
    return a;
}

vtkSmartPointer<vtkDoubleArray> vectorArray(const char* name, const std::vector<Vector2>& v,
                                            int nComponents)
{
    auto a = doubleArray(name, nComponents, static_cast<vtkIdType>(v.size()));
    double* out = a->GetPointer(0);
    for (std::size_t i = 0; i < v.size(); ++i) {
        out[nComponents * i] = v[i].x();
        out[nComponents * i + 1] = v[i].y();
        if (nComponents == 3) out[3 * i + 2] = 0.0;
    }
    return a;
}

vtkSmartPointer<vtkDoubleArray> scalarArray(const char* name, const std::vector<double>& s)
{
    auto a = doubleArray(name, 1, static_cast<vtkIdType>(s.size()));
    std::copy(s.begin(), s.end(), a->GetPointer(0));
    return a;
}

vtkSmartPointer<vtkStringArray> stringArray(const char* name, const std::vector<std::string>& s)
{
    auto a = vtkSmartPointer<vtkStringArray>::New();
    a->SetName(name);
    a->SetNumberOfValues(static_cast<vtkIdType>(s.size()));
    for (std::size_t i = 0; i < s.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), s[i]);
    return a;
}

[[noreturn]] void cannotRead(const std::string& path, const std::string& why)
{
    throw InputError(path, 0, "cannot read particles: " + why);
}

//- The value of attribute `name` in one XML element's text ("" when absent).
std::string attribute(const std::string& element, const std::string& name)
{
    const std::string key = " " + name + "=\"";
    const auto at = element.find(key);
    if (at == std::string::npos) return "";
    const auto begin = at + key.size();
    const auto close = element.find('"', begin);
    return element.substr(begin, close == std::string::npos ? std::string::npos : close - begin);
}

//- A whole-string unsigned decimal count.
bool parseCount(const std::string& text, std::uint64_t& value)
{
    if (text.empty() || !std::isdigit(static_cast<unsigned char>(text.front()))) return false;
    char* tail = nullptr;
    errno = 0;
    value = std::strtoull(text.c_str(), &tail, 10);
    return *tail == '\0' && errno == 0;
}

//- VTK 9.1 crashes instead of failing on some corrupt files: an unknown array type (null
//  dereference), a wrong header_type or a string array whose byte count runs past the end
//  (overrun), a bad compressed-block header (SIGFPE). So accept only the layout writeParticles
//  writes (UInt64 headers, no compression, appended raw data, known types, every block inside
//  the file, string blocks properly terminated) and check it before VTK sees the file.
void checkLayout(const std::string& path)
{
    // Known types and their sizes (0: not checked by size).
    static const std::array<std::pair<const char*, std::uint64_t>, 12> known{{
        {"Int8", 1}, {"UInt8", 1}, {"Int16", 2}, {"UInt16", 2}, {"Int32", 4}, {"UInt32", 4},
        {"Int64", 8}, {"UInt64", 8}, {"Float32", 4}, {"Float64", 8}, {"String", 0}, {"Bit", 0}}};
    std::ifstream in(path, std::ios::binary);
    in.seekg(0, std::ios::end);
    const auto fileSize = static_cast<std::uint64_t>(in.tellg());
    in.seekg(0);

    // The XML part ends at the '_' that opens the appended binary block.
    std::string header;
    std::size_t tag = std::string::npos, underscore = std::string::npos;
    char chunk[4096];
    while (underscore == std::string::npos && in.read(chunk, sizeof chunk).gcount() > 0) {
        header.append(chunk, static_cast<std::size_t>(in.gcount()));
        if (tag == std::string::npos) tag = header.find("<AppendedData");
        if (tag != std::string::npos) underscore = header.find('_', tag);
    }
    if (underscore == std::string::npos) cannotRead(path, "no appended data block");
    // VTK takes the first non-blank character after the tag as the start of the data.
    const auto tagEnd = header.find('>', tag);
    if (tagEnd > underscore || header.find_first_not_of(" \t\r\n", tagEnd + 1) != underscore)
        cannotRead(path, "corrupt appended data block");
    in.clear();
    const std::uint64_t dataStart = underscore + 1;
    header.resize(tag);

    const auto file = header.find("<VTKFile");
    const std::string root =
        file == std::string::npos ? "" : header.substr(file, header.find('>', file) - file);
    if (attribute(root, "header_type") != "UInt64" ||
        root.find(" compressor=") != std::string::npos)
        cannotRead(path, "not written by writeParticles (expected header_type=\"UInt64\" and no "
                         "compressor)");

    // Point arrays have NumberOfPoints tuples; with the byte counts checked against it, a
    // corrupt count cannot make VTK allocate more than the file holds.
    const auto piece = header.find("<Piece");
    const std::string pieceElement =
        piece == std::string::npos ? "" : header.substr(piece, header.find('>', piece) - piece);
    std::uint64_t nPoints = 0;
    if (!parseCount(attribute(pieceElement, "NumberOfPoints"), nPoints))
        cannotRead(path, "no NumberOfPoints");
    const auto inside = [&](std::size_t pos, const char* open, const char* close) {
        const auto o = header.rfind(open, pos);
        const auto c = header.rfind(close, pos);
        return o != std::string::npos && (c == std::string::npos || c < o);
    };

    for (const char* name : {"<DataArray", "<Array"}) {
        for (auto pos = header.find(name); pos != std::string::npos;
             pos = header.find(name, pos + 1)) {
            const auto end = header.find('>', pos);
            const std::string element =
                header.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
            const std::string arrayName = attribute(element, "Name");
            const std::string type = attribute(element, "type");
            const auto kind = std::find_if(known.begin(), known.end(),
                                           [&](const auto& k) { return type == k.first; });
            if (kind == known.end()) cannotRead(path, "unknown array type '" + type + "'");
            if (attribute(element, "format") != "appended")
                cannotRead(path, "array '" + arrayName + "' is not appended data");

            // Each block is a UInt64 byte count followed by that many bytes.
            std::uint64_t offset = 0, bytes = 0;
            const bool offsetOk = parseCount(attribute(element, "offset"), offset);
            const std::uint64_t at = dataStart + offset;
            if (!offsetOk || offset > fileSize || at > fileSize || fileSize - at < 8 ||
                !in.seekg(static_cast<std::streamoff>(at)) ||
                !in.read(reinterpret_cast<char*>(&bytes), sizeof bytes) ||
                bytes > fileSize - at - 8)
                cannotRead(path, "truncated or corrupt: data of array '" + arrayName +
                                     "' runs past the end of the file");
            std::uint64_t tuples = 0, components = 1;
            const bool pointArray = inside(pos, "<PointData", "</PointData>") ||
                                    inside(pos, "<Points>", "</Points>");
            const bool counted = pointArray || !attribute(element, "NumberOfTuples").empty();
            if (pointArray) tuples = nPoints;
            else if (counted && !parseCount(attribute(element, "NumberOfTuples"), tuples))
                cannotRead(path, "bad NumberOfTuples of array '" + arrayName + "'");
            if (!attribute(element, "NumberOfComponents").empty() &&
                !parseCount(attribute(element, "NumberOfComponents"), components))
                cannotRead(path, "bad NumberOfComponents of array '" + arrayName + "'");
            bool sizeOk = true;
            if (counted && kind->second > 0) {
                // Divide rather than multiply, so that corrupt counts cannot overflow.
                if (tuples == 0 || components == 0) sizeOk = bytes == 0;
                else if (components > fileSize) sizeOk = false;
                else sizeOk = bytes % (components * kind->second) == 0 &&
                              bytes / (components * kind->second) == tuples;
            }
            if (!sizeOk)
                cannotRead(path, "array '" + arrayName + "' holds " +
                                     std::to_string(bytes) + " bytes, expected " +
                                     std::to_string(tuples) + " tuples of " +
                                     std::to_string(components) + " " + type);
            if (type == "String") {
                // NumberOfTuples strings, each terminated by '\0', filling the block exactly.
                std::string block(bytes, '\0');
                in.read(block.data(), static_cast<std::streamsize>(bytes));
                const auto strings = std::count(block.begin(), block.end(), '\0');
                if (!in || (bytes > 0 && block.back() != '\0') ||
                    std::to_string(strings) != attribute(element, "NumberOfTuples"))
                    cannotRead(path, "corrupt string array '" + arrayName + "'");
            }
        }
    }
}

//- The point array `name` with `nComponents` components and one tuple per point.
vtkDataArray* required(vtkPointData* pd, const char* name, int nComponents, vtkIdType n,
                       const std::string& path)
{
    vtkDataArray* a = pd->GetArray(name);
    if (!a) cannotRead(path, std::string("missing point array '") + name + "'");
    if (a->GetNumberOfComponents() != nComponents || a->GetNumberOfTuples() != n)
        cannotRead(path, std::string("point array '") + name + "' has " +
                             std::to_string(a->GetNumberOfTuples()) + " tuples of " +
                             std::to_string(a->GetNumberOfComponents()) + " components, expected " +
                             std::to_string(n) + " of " + std::to_string(nComponents));
    return a;
}

void readInts(vtkDataArray* a, std::vector<int>& out)
{
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<int>(a->GetComponent(static_cast<vtkIdType>(i), 0));
}

void readVectors(vtkDataArray* a, std::vector<Vector2>& out)
{
    for (std::size_t i = 0; i < out.size(); ++i) {
        const auto t = static_cast<vtkIdType>(i);
        out[i] = Vector2(a->GetComponent(t, 0), a->GetComponent(t, 1));
    }
}

void readScalars(vtkDataArray* a, std::vector<double>& out)
{
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = a->GetComponent(static_cast<vtkIdType>(i), 0);
}

void readTensors(vtkDataArray* a, std::vector<SymTensor>& out)
{
    for (std::size_t i = 0; i < out.size(); ++i) {
        const auto t = static_cast<vtkIdType>(i);
        out[i] = SymTensor(a->GetComponent(t, 0), a->GetComponent(t, 4), a->GetComponent(t, 8),
                           a->GetComponent(t, 1));
    }
}

std::vector<std::string> readStrings(vtkFieldData* fd, const char* name)
{
    std::vector<std::string> values;
    auto* a = vtkStringArray::SafeDownCast(fd ? fd->GetAbstractArray(name) : nullptr);
    if (!a) return values;
    for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i) values.push_back(a->GetValue(i));
    return values;
}

} // namespace

void writeParticles(const std::string& path, const Particles& p, double time,
                    const std::vector<std::string>& materialNames,
                    const std::vector<std::string>& bodyNames)
{
    for (const auto& name : p.historyNames())
        if (isBuiltin(name))
            throw std::logic_error("particle history variable '" + name +
                                   "' has the name of a built-in output array");

    const std::size_t n = p.size();
    const auto nv = static_cast<vtkIdType>(n);

    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(nv);
    for (std::size_t i = 0; i < n; ++i)
        points->SetPoint(static_cast<vtkIdType>(i), p.x[i].x(), p.x[i].y(), 0.0);

    // One vertex cell per point, so ParaView renders the points without a glyph filter.
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfValues(nv + 1);
    connectivity->SetNumberOfValues(nv);
    for (vtkIdType i = 0; i < nv; ++i) {
        offsets->SetValue(i, i);
        connectivity->SetValue(i, i);
    }
    offsets->SetValue(nv, nv);
    vtkNew<vtkCellArray> verts;
    verts->SetData(offsets, connectivity);

    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetVerts(verts);

    vtkPointData* pd = poly->GetPointData();
    pd->AddArray(intArray("id", p.id));
    pd->AddArray(intArray("body", p.body));
    pd->AddArray(intArray("material", p.material));
    pd->AddArray(vectorArray("velocity", p.v, 3));
    std::vector<Vector2> displacement(n);
    for (std::size_t i = 0; i < n; ++i) displacement[i] = p.x[i] - p.x0[i];
    pd->AddArray(vectorArray("displacement", displacement, 3));
    pd->AddArray(vectorArray("initialPosition", p.x0, 3));
    pd->AddArray(scalarArray("mass", p.m));
    pd->AddArray(scalarArray("volume", p.V));
    pd->AddArray(scalarArray("work", p.work));
    pd->AddArray(vectorArray("halfSize", p.halfSize, 2));
    pd->AddArray(tensorArray("stress", p.sigma));
    pd->AddArray(tensorArray("strain", p.eps));
    pd->AddArray(tensorArray("plasticStrain", p.epsP));

    auto pressure = doubleArray("pressure", 1, nv);
    auto vonMises = doubleArray("vonMisesStress", 1, nv);
    for (std::size_t i = 0; i < n; ++i) {
        const SymTensor& s = p.sigma[i];
        const double mean = (s[XX] + s[YY] + s[ZZ]) / 3.0;
        const double d1 = s[XX] - mean, d2 = s[YY] - mean, d3 = s[ZZ] - mean;
        const double J2 = 0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + s[XY] * s[XY];
        pressure->SetValue(static_cast<vtkIdType>(i), -mean);
        vonMises->SetValue(static_cast<vtkIdType>(i), std::sqrt(3.0 * J2));
    }
    pd->AddArray(pressure);
    pd->AddArray(vonMises);
    for (const auto& name : p.historyNames())
        pd->AddArray(scalarArray(name.c_str(), p.history(name)));

    // "TimeValue" is the field ParaView shows as the dataset time.
    vtkFieldData* fd = poly->GetFieldData();
    auto timeValue = doubleArray("TimeValue", 1, 1);
    timeValue->SetValue(0, time);
    fd->AddArray(timeValue);
    fd->AddArray(stringArray("materialNames", materialNames));
    fd->AddArray(stringArray("bodyNames", bodyNames));

    const std::string tmp = path + ".tmp";
    vtkNew<vtkXMLPolyDataWriter> writer;
    vtkNew<ErrorCollector> errors;
    writer->AddObserver(vtkCommand::ErrorEvent, errors);
    writer->SetInputData(poly);
    writer->SetFileName(tmp.c_str());
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw bytes: smaller, and Float64 stays bit-exact
    writer->SetHeaderTypeToUInt64();  // arrays over 4 GiB
    // Uncompressed: faster to write, and VTK 9.1 crashes (SIGFPE, huge allocations) on some
    // corrupt compressed-block headers instead of reporting an error.
    writer->SetCompressorTypeToNone();
    const int ok = writer->Write();
    std::error_code ec;
    if (!ok || errors->failed || writer->GetErrorCode() != 0) {
        std::filesystem::remove(tmp, ec);
        throw RunError("cannot write particles to " + path + ": " +
                       (errors->first.empty() ? "VTK writer failed" : errors->first));
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw RunError("cannot write particles to " + path + ": " + ec.message());
    }
}

void readParticles(const std::string& path, Particles& p, double& time,
                   std::vector<std::string>* materialNames, std::vector<std::string>* bodyNames)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) cannotRead(path, "no such file");

    vtkNew<vtkXMLPolyDataReader> reader;
    vtkNew<ErrorCollector> errors;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(path.c_str());
    {
        QuietVtk quiet;
        if (!reader->CanReadFile(path.c_str())) cannotRead(path, "not a VTK XML PolyData file");
        checkLayout(path);
        // A corrupt block header can make VTK ask for an absurd allocation.
        try {
            reader->Update();
        } catch (const std::exception& e) {
            cannotRead(path, std::string("corrupt data (") + e.what() + ")");
        }
    }
    if (errors->failed) cannotRead(path, errors->first);
    vtkPolyData* poly = reader->GetOutput();
    if (!poly) cannotRead(path, "VTK returned no data");

    const vtkIdType nv = poly->GetNumberOfPoints();
    const auto n = static_cast<std::size_t>(nv);
    if (nv > 0 && (!poly->GetPoints() || !poly->GetPoints()->GetData()))
        cannotRead(path, "missing points");
    vtkPointData* pd = poly->GetPointData();
    if (!pd) cannotRead(path, "missing point data");

    // Look every required array up before touching p, so a bad file leaves p unchanged.
    vtkDataArray* idA = required(pd, "id", 1, nv, path);
    vtkDataArray* bodyA = required(pd, "body", 1, nv, path);
    vtkDataArray* materialA = required(pd, "material", 1, nv, path);
    vtkDataArray* velocityA = required(pd, "velocity", 3, nv, path);
    vtkDataArray* x0A = required(pd, "initialPosition", 3, nv, path);
    vtkDataArray* massA = required(pd, "mass", 1, nv, path);
    vtkDataArray* volumeA = required(pd, "volume", 1, nv, path);
    vtkDataArray* workA = required(pd, "work", 1, nv, path);
    vtkDataArray* halfSizeA = required(pd, "halfSize", 2, nv, path);
    vtkDataArray* stressA = required(pd, "stress", 9, nv, path);
    vtkDataArray* strainA = required(pd, "strain", 9, nv, path);
    vtkDataArray* plasticA = required(pd, "plasticStrain", 9, nv, path);

    vtkFieldData* fd = poly->GetFieldData();
    vtkDataArray* timeA = fd ? fd->GetArray("TimeValue") : nullptr;
    if (!timeA || timeA->GetNumberOfTuples() < 1) cannotRead(path, "missing field 'TimeValue'");

    Particles result;
    result.resize(n);
    for (vtkIdType i = 0; i < nv; ++i) {
        double xyz[3];
        poly->GetPoint(i, xyz);
        result.x[static_cast<std::size_t>(i)] = Vector2(xyz[0], xyz[1]);
    }
    readInts(idA, result.id);
    readInts(bodyA, result.body);
    readInts(materialA, result.material);
    readVectors(velocityA, result.v);
    readVectors(x0A, result.x0);
    readScalars(massA, result.m);
    readScalars(volumeA, result.V);
    readScalars(workA, result.work);
    readVectors(halfSizeA, result.halfSize);
    readTensors(stressA, result.sigma);
    readTensors(strainA, result.eps);
    readTensors(plasticA, result.epsP);

    for (int k = 0; k < pd->GetNumberOfArrays(); ++k) {
        vtkDataArray* a = pd->GetArray(k);
        if (!a || !a->GetName() || isBuiltin(a->GetName())) continue;
        if (a->GetDataType() != VTK_DOUBLE || a->GetNumberOfComponents() != 1) continue;
        if (a->GetNumberOfTuples() != nv)
            cannotRead(path, std::string("point array '") + a->GetName() + "' has " +
                                 std::to_string(a->GetNumberOfTuples()) + " tuples, expected " +
                                 std::to_string(nv));
        result.declareHistory(a->GetName());
        readScalars(a, result.history(a->GetName()));
    }

    time = timeA->GetComponent(0, 0);
    if (materialNames) *materialNames = readStrings(fd, "materialNames");
    if (bodyNames) *bodyNames = readStrings(fd, "bodyNames");
    p = std::move(result);
}

} // namespace gpic
