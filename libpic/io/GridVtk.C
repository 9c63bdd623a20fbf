#include "io/GridVtk.H"
#include "io/GridVtkRead.H"

#include "core/error.H"
#include "grid/Grid.H"
#include "io/AtomicVtkWrite.H"
#include "io/VtkErrorGuard.H"

#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>

#include <filesystem>
#include <system_error>

namespace gpic {

namespace {

template <class Vector>
vtkSmartPointer<vtkDoubleArray> nodalVectors(const char* name, const std::vector<Vector>& v)
{
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(static_cast<vtkIdType>(v.size()));
    double* out = a->GetPointer(0);
    for (std::size_t i = 0; i < v.size(); ++i) {
        out[3 * i] = v[i].x();
        out[3 * i + 1] = v[i].y();
        out[3 * i + 2] = Vector::SizeAtCompileTime == 3 ? v[i][Vector::SizeAtCompileTime - 1] : 0.0;
    }
    return a;
}

} // namespace

template <int D> void writeGrid(const std::string& path, const Grid<D>& g, double time)
{
    vtkNew<vtkImageData> image;
    const bool solid = D == 3;
    image->SetOrigin(g.origin().x(), g.origin().y(), solid ? g.origin()[D - 1] : 0.0);
    image->SetSpacing(g.cellSize().x(), g.cellSize().y(), solid ? g.cellSize()[D - 1] : 1.0);
    image->SetExtent(0, g.cells(0), 0, g.cells(1), 0, solid ? g.cells(D - 1) : 0);

    vtkNew<vtkDoubleArray> mass;
    mass->SetName("mass");
    mass->SetNumberOfComponents(1);
    mass->SetNumberOfTuples(static_cast<vtkIdType>(g.mass.size()));
    std::copy(g.mass.begin(), g.mass.end(), mass->GetPointer(0));
    vtkPointData* pd = image->GetPointData();
    pd->AddArray(mass);
    pd->AddArray(nodalVectors("velocity", g.velocity));
    pd->AddArray(nodalVectors("internalForce", g.fInt));
    pd->AddArray(nodalVectors("externalForce", g.fExt));
    if (!g.fContact.empty()) pd->AddArray(nodalVectors("contactForce", g.fContact));

    vtkNew<vtkDoubleArray> timeValue;
    timeValue->SetName("TimeValue");
    timeValue->SetNumberOfValues(1);
    timeValue->SetValue(0, time);
    image->GetFieldData()->AddArray(timeValue);

    vtkNew<vtkXMLImageDataWriter> writer;
    detail::writeXmlAtomically(writer, image, path, "grid");
}

template void writeGrid(const std::string&, const Grid<2>&, double);
#if GPIC_WITH_3D
template void writeGrid(const std::string&, const Grid<3>&, double);
#endif

vtkSmartPointer<vtkImageData> readGridImage(const std::string& path, const std::string& hint)
{
    return detail::readXml<vtkXMLImageDataReader>(path, "grid", "ImageData", hint);
}

GridVtkInfo readGridInfo(const std::string& path)
{
    vtkSmartPointer<vtkImageData> image = readGridImage(path);
    GridVtkInfo info;
    image->GetDimensions(info.dimensions.data());
    image->GetOrigin(info.origin.data());
    image->GetSpacing(info.spacing.data());
    vtkFieldData* fd = image->GetFieldData();
    vtkDataArray* timeA = fd ? fd->GetArray("TimeValue") : nullptr;
    if (timeA && timeA->GetNumberOfTuples() > 0) info.time = timeA->GetComponent(0, 0);
    vtkPointData* pd = image->GetPointData();
    for (int k = 0; pd && k < pd->GetNumberOfArrays(); ++k)
        if (pd->GetArrayName(k)) info.pointArrays.emplace_back(pd->GetArrayName(k));
    return info;
}

} // namespace gpic
