#include "io/ParticlesVtk.H"

#include "io/AtomicVtkWrite.H"
#include "io/ParticlesVtkFormat.H"
#include "particles/Particles.H"

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

namespace gpic {

namespace {

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

//- The affine velocity matrix C_p (a velocity gradient, not symmetric) as a 3x3 tensor.
vtkSmartPointer<vtkDoubleArray> affineArray(const char* name, const decltype(Particles::affine)& C)
{
    auto a = doubleArray(name, 9, static_cast<vtkIdType>(C.size()));
    double* out = a->GetPointer(0);
    for (std::size_t i = 0; i < C.size(); ++i) {
        double* o = out + 9 * i;
        o[0] = C[i](0, 0); o[1] = C[i](0, 1); o[2] = 0.0;
        o[3] = C[i](1, 0); o[4] = C[i](1, 1); o[5] = 0.0;
        o[6] = 0.0;        o[7] = 0.0;        o[8] = 0.0;
    }
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
    auto stress = tensorArray("stress", p.sigma);
    if (p.polar.enabled())  // a Cosserat stress is not symmetric: yx holds sigma21
        for (std::size_t i = 0; i < n; ++i) stress->SetComponent(static_cast<vtkIdType>(i), 3, p.polar.sigma21[i]);
    pd->AddArray(stress);
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
    if (p.hasAffine()) {  // APIC's C_p and the kinetic energy it carries
        pd->AddArray(affineArray("affineVelocity", p.affine));
        pd->AddArray(scalarArray("affineKineticEnergy", p.affineEnergy));
    }
    if (p.polar.enabled()) {  // Cosserat state (CosseratParticles.H), only in polar scenes
        pd->AddArray(scalarArray("microRotation", p.polar.w));
        pd->AddArray(scalarArray("microRotationRate", p.polar.omega));
        pd->AddArray(vectorArray("coupleStress", p.polar.mu, 3));
        pd->AddArray(vectorArray("curvature", p.polar.kappa, 3));
    }

    // "TimeValue" is the field ParaView shows as the dataset time.
    vtkFieldData* fd = poly->GetFieldData();
    auto timeValue = doubleArray("TimeValue", 1, 1);
    timeValue->SetValue(0, time);
    fd->AddArray(timeValue);
    fd->AddArray(stringArray("materialNames", materialNames));
    fd->AddArray(stringArray("bodyNames", bodyNames));

    vtkNew<vtkXMLPolyDataWriter> writer;
    detail::writeXmlAtomically(writer, poly, path, "particles");
}

} // namespace gpic
