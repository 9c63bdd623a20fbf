#include "io/ParticlesVtk.H"

#include "io/AtomicVtkWrite.H"
#include "io/ParticlesChecksum.H"
#include "io/ParticlesVtkFormat.H"
#include "particles/ParticleFields.H"

#include <vtkCellArray.h>
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
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>

namespace gpic {

namespace {

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, int nComponents, vtkIdType n)
{
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(nComponents);
    a->SetNumberOfTuples(n);
    // ParaView shows these names in its colour menu and bar ("stress XY", not "stress 1").
    static const char* const tensor[9] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
    static const char* const vector[3] = {"X", "Y", "Z"};
    if (nComponents == 9)
        for (int c = 0; c < 9; ++c) a->SetComponentName(c, tensor[c]);
    else if (nComponents == 2 || nComponents == 3)
        for (int c = 0; c < nComponents; ++c) a->SetComponentName(c, vector[c]);
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

// One table entry to VTK components, by element type.
void put(double value, double* out, int) { out[0] = value; }
void put(const Vector2& v, double* out, int nComponents)
{
    out[0] = v.x(); out[1] = v.y();
    if (nComponents == 3) out[2] = 0.0;
}
//- Plane-strain (11, 22, 33, 12) as a full 3x3 tensor, row-major, as ParaView expects.
void put(const SymTensor& s, double* out, int)
{
    out[0] = s[XX]; out[1] = s[XY]; out[2] = 0.0;
    out[3] = s[XY]; out[4] = s[YY]; out[5] = 0.0;
    out[6] = 0.0;   out[7] = 0.0;   out[8] = s[ZZ];
}
//- The affine velocity matrix C_p (a velocity gradient, not symmetric) as a 3x3 tensor.
void put(const Eigen::Matrix2d& C, double* out, int)
{
    out[0] = C(0, 0); out[1] = C(0, 1); out[2] = 0.0;
    out[3] = C(1, 0); out[4] = C(1, 1); out[5] = 0.0;
    out[6] = 0.0;     out[7] = 0.0;     out[8] = 0.0;
}

//- The point array of a state field (ints as Int32, everything else as Float64).
vtkSmartPointer<vtkDataArray> stateArray(const ParticleField& f, const Particles& p)
{
    return std::visit(
        [&](const auto* a) -> vtkSmartPointer<vtkDataArray> {
            using T = typename std::decay_t<decltype(*a)>::value_type;
            if constexpr (std::is_same_v<T, int>) {
                return intArray(f.name, *a);
            }
            else {
                auto out = doubleArray(f.name, f.components, static_cast<vtkIdType>(a->size()));
                double* o = out->GetPointer(0);
                for (std::size_t i = 0; i < a->size(); ++i) put((*a)[i], o + f.components * i, f.components);
                return out;
            }
        },
        fieldArray(f, p));
}

//- The point array of a derived output.
vtkSmartPointer<vtkDataArray> derivedArray(const ParticleField& f, const Particles& p)
{
    auto out = doubleArray(f.name, f.components, static_cast<vtkIdType>(p.size()));
    double* o = out->GetPointer(0);
    for (std::size_t i = 0; i < p.size(); ++i) f.derive(p, i, o + f.components * i);
    return out;
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

} // namespace

void writeParticles(const std::string& path, const Particles& p, double time,
                    const std::vector<std::string>& materialNames,
                    const std::vector<std::string>& bodyNames)
{
    for (const auto& name : p.historyNames())
        if (detail::isBuiltinParticleArray(name))
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
    for (const ParticleField& f : particleFields()) {
        if (!p.carries(f.group) || f.role == FieldRole::scratch || f.storedIn) continue;
        pd->AddArray(f.role == FieldRole::derived ? derivedArray(f, p) : stateArray(f, p));
    }
    for (const ParticleField& f : particleFields()) {  // arrays stored inside another (not the points)
        if (!p.carries(f.group) || !f.storedIn || !pd->GetArray(f.storedIn)) continue;
        const auto& values = *std::get<std::vector<double>*>(fieldArray(f, p));
        vtkDataArray* into = pd->GetArray(f.storedIn);
        for (std::size_t i = 0; i < n; ++i) into->SetComponent(static_cast<vtkIdType>(i), f.storedComponent, values[i]);
    }
    for (const auto& name : p.historyNames())
        pd->AddArray(scalarArray(name.c_str(), p.history(name)));

    // "TimeValue" is the field ParaView shows as the dataset time.
    vtkFieldData* fd = poly->GetFieldData();
    auto timeValue = doubleArray("TimeValue", 1, 1);
    timeValue->SetValue(0, time);
    fd->AddArray(timeValue);
    fd->AddArray(stringArray("materialNames", materialNames));
    fd->AddArray(stringArray("bodyNames", bodyNames));
    fd->AddArray(stringArray("checksum", {detail::particleDataChecksum(poly)}));

    vtkNew<vtkXMLPolyDataWriter> writer;
    detail::writeXmlAtomically(writer, poly, path, "particles");
}

} // namespace gpic
