#include "io/ParticlesVtk.H"

#include "io/ParticlesChecksum.H"
#include "io/ParticlesVtkCheck.H"
#include "io/ParticlesVtkFormat.H"
#include "io/VtkErrorGuard.H"
#include "particles/ParticleFields.H"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <array>
#include <exception>
#include <filesystem>
#include <system_error>
#include <type_traits>
#include <variant>

namespace gpic {

using detail::cannotReadParticles;
using detail::isBuiltinParticleArray;

namespace {

//- The point array `name` with `nComponents` components and one tuple per point.
vtkDataArray* required(vtkPointData* pd, const char* name, int nComponents, vtkIdType n,
                       const std::string& path)
{
    vtkDataArray* a = pd->GetArray(name);
    if (!a) cannotReadParticles(path, std::string("missing point array '") + name + "'");
    if (a->GetNumberOfComponents() != nComponents || a->GetNumberOfTuples() != n)
        cannotReadParticles(path, std::string("point array '") + name + "' has " +
                                      std::to_string(a->GetNumberOfTuples()) + " tuples of " +
                                      std::to_string(a->GetNumberOfComponents()) +
                                      " components, expected " + std::to_string(n) + " of " +
                                      std::to_string(nComponents));
    return a;
}

// VTK components to one table entry, by element type.
void get(vtkDataArray* a, vtkIdType t, int& out) { out = static_cast<int>(a->GetComponent(t, 0)); }
void get(vtkDataArray* a, vtkIdType t, double& out) { out = a->GetComponent(t, 0); }
void get(vtkDataArray* a, vtkIdType t, Vector2& out) { out = Vector2(a->GetComponent(t, 0), a->GetComponent(t, 1)); }
//- The full 3x3 tensor's (11, 22, 33, 12).
void get(vtkDataArray* a, vtkIdType t, SymTensor& out)
{
    out = SymTensor(a->GetComponent(t, 0), a->GetComponent(t, 4), a->GetComponent(t, 8), a->GetComponent(t, 1));
}
void get(vtkDataArray* a, vtkIdType t, Eigen::Matrix2d& out)
{
    out << a->GetComponent(t, 0), a->GetComponent(t, 1), a->GetComponent(t, 3), a->GetComponent(t, 4);
}

void readScalars(vtkDataArray* a, std::vector<double>& out)
{
    for (std::size_t i = 0; i < out.size(); ++i) get(a, static_cast<vtkIdType>(i), out[i]);
}

bool inPoints(const ParticleField& f) { return f.storedIn && std::string(f.storedIn) == "points"; }

//- The checksum of the points and of every point array, in the file's order.
std::string particleDataChecksum(vtkPolyData* poly)
{
    detail::ParticleChecksum sum;
    const auto add = [&sum](vtkDataArray* a) {
        if (!a) return;
        const auto bytes = static_cast<std::size_t>(a->GetNumberOfValues()) * static_cast<std::size_t>(a->GetDataTypeSize());
        if (bytes > 0) sum.add(a->GetVoidPointer(0), bytes);
        sum.endArray();
    };
    if (poly->GetPoints()) add(poly->GetPoints()->GetData());
    vtkPointData* pd = poly->GetPointData();
    for (int i = 0; pd && i < pd->GetNumberOfArrays(); ++i) add(pd->GetArray(i));
    return sum.text();
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

void readParticles(const std::string& path, Particles& p, double& time,
                   std::vector<std::string>* materialNames, std::vector<std::string>* bodyNames)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) cannotReadParticles(path, "no such file");

    vtkNew<vtkXMLPolyDataReader> reader;
    vtkNew<detail::ErrorCollector> errors;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(path.c_str());
    {
        detail::QuietVtk quiet;
        if (!reader->CanReadFile(path.c_str()))
            cannotReadParticles(path, "not a VTK XML PolyData file");
        detail::checkParticlesLayout(path);
        // A corrupt block header can make VTK ask for an absurd allocation.
        try {
            reader->Update();
        } catch (const std::exception& e) {
            cannotReadParticles(path, std::string("corrupt data (") + e.what() + ")");
        }
    }
    if (errors->failed) cannotReadParticles(path, errors->first);
    vtkPolyData* poly = reader->GetOutput();
    if (!poly) cannotReadParticles(path, "VTK returned no data");

    const vtkIdType nv = poly->GetNumberOfPoints();
    const auto n = static_cast<std::size_t>(nv);
    if (nv > 0 && (!poly->GetPoints() || !poly->GetPoints()->GetData()))
        cannotReadParticles(path, "missing points");
    vtkPointData* pd = poly->GetPointData();
    if (!pd) cannotReadParticles(path, "missing point data");

    // Look every required array up before touching p, so a bad file leaves p unchanged. An
    // optional group is in the file when its first array is; then all of its arrays must be.
    const std::vector<ParticleField>& fields = particleFields();
    std::array<bool, 4> groupInFile{true, false, false, false};
    for (const ParticleField& f : fields)
        if (f.group != FieldGroup::core && f.role == FieldRole::state && *f.name && pd->GetArray(f.name))
            groupInFile[static_cast<int>(f.group)] = true;
    std::vector<vtkDataArray*> arrays(fields.size(), nullptr);
    for (std::size_t k = 0; k < fields.size(); ++k) {
        const ParticleField& f = fields[k];
        if (f.role != FieldRole::state || !groupInFile[static_cast<int>(f.group)] || inPoints(f)) continue;
        arrays[k] = f.storedIn ? pd->GetArray(f.storedIn) : required(pd, f.name, f.components, nv, path);
    }

    vtkFieldData* fd = poly->GetFieldData();
    // Files written before the checksum have none; those with one must match it.
    if (auto* sum = vtkStringArray::SafeDownCast(fd ? fd->GetAbstractArray("checksum") : nullptr);
        sum && sum->GetNumberOfValues() > 0 && sum->GetValue(0) != particleDataChecksum(poly))
        cannotReadParticles(path, "its data do not match the checksum written with them: the file is damaged");
    vtkDataArray* timeA = fd ? fd->GetArray("TimeValue") : nullptr;
    if (!timeA || timeA->GetNumberOfTuples() < 1)
        cannotReadParticles(path, "missing field 'TimeValue'");

    Particles result;
    for (const ParticleField& f : fields)
        if (f.group != FieldGroup::core && groupInFile[static_cast<int>(f.group)]) result.carry(f.group);
    result.resize(n);
    for (vtkIdType i = 0; i < nv; ++i) {
        double xyz[3];
        poly->GetPoint(i, xyz);
        result.x[static_cast<std::size_t>(i)] = Vector2(xyz[0], xyz[1]);
    }
    for (std::size_t k = 0; k < fields.size(); ++k) {
        vtkDataArray* a = arrays[k];
        if (!a) continue;
        const int component = fields[k].storedIn ? fields[k].storedComponent : 0;
        std::visit(
            [&](auto* values) {
                for (std::size_t i = 0; i < n; ++i) {
                    if (component == 0) get(a, static_cast<vtkIdType>(i), (*values)[i]);
                    else if constexpr (std::is_same_v<std::decay_t<decltype(*values)>, std::vector<double>>)
                        (*values)[i] = a->GetComponent(static_cast<vtkIdType>(i), component);
                }
            },
            fields[k].array(result));
    }

    for (int k = 0; k < pd->GetNumberOfArrays(); ++k) {
        vtkDataArray* a = pd->GetArray(k);
        if (!a || !a->GetName() || isBuiltinParticleArray(a->GetName())) continue;
        if (a->GetDataType() != VTK_DOUBLE || a->GetNumberOfComponents() != 1) continue;
        if (a->GetNumberOfTuples() != nv)
            cannotReadParticles(path, std::string("point array '") + a->GetName() + "' has " +
                                          std::to_string(a->GetNumberOfTuples()) +
                                          " tuples, expected " + std::to_string(nv));
        result.declareHistory(a->GetName());
        readScalars(a, result.history(a->GetName()));
    }

    time = timeA->GetComponent(0, 0);
    if (materialNames) *materialNames = readStrings(fd, "materialNames");
    if (bodyNames) *bodyNames = readStrings(fd, "bodyNames");
    p = std::move(result);
}

} // namespace gpic
