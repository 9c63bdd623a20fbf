#include "io/ParticlesVtk.H"

#include "io/ParticlesVtkCheck.H"
#include "io/ParticlesVtkFormat.H"
#include "io/VtkErrorGuard.H"
#include "particles/Particles.H"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <exception>
#include <filesystem>
#include <system_error>

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
    // Cosserat state: all four arrays or none.
    vtkDataArray* rotationA = pd->GetArray("microRotation") ? required(pd, "microRotation", 1, nv, path) : nullptr;
    vtkDataArray* rotationRateA = rotationA ? required(pd, "microRotationRate", 1, nv, path) : nullptr;
    vtkDataArray* coupleA = rotationA ? required(pd, "coupleStress", 3, nv, path) : nullptr;
    vtkDataArray* curvatureA = rotationA ? required(pd, "curvature", 3, nv, path) : nullptr;

    vtkDataArray* affineA = pd->GetArray("affineVelocity") ? required(pd, "affineVelocity", 9, nv, path) : nullptr;
    vtkDataArray* affineEnergyA = affineA ? required(pd, "affineKineticEnergy", 1, nv, path) : nullptr;

    vtkFieldData* fd = poly->GetFieldData();
    vtkDataArray* timeA = fd ? fd->GetArray("TimeValue") : nullptr;
    if (!timeA || timeA->GetNumberOfTuples() < 1)
        cannotReadParticles(path, "missing field 'TimeValue'");

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
    if (affineA) {
        result.enableAffine();
        for (std::size_t i = 0; i < n; ++i) {
            const auto t = static_cast<vtkIdType>(i);
            result.affine[i] << affineA->GetComponent(t, 0), affineA->GetComponent(t, 1),
                                affineA->GetComponent(t, 3), affineA->GetComponent(t, 4);
        }
        readScalars(affineEnergyA, result.affineEnergy);
    }
    if (rotationA) {
        result.polar.enable(n);
        readScalars(rotationA, result.polar.w);
        readScalars(rotationRateA, result.polar.omega);
        readVectors(coupleA, result.polar.mu);
        readVectors(curvatureA, result.polar.kappa);
        for (std::size_t i = 0; i < n; ++i) result.polar.sigma21[i] = stressA->GetComponent(static_cast<vtkIdType>(i), 3);
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
