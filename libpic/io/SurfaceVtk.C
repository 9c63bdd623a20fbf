#include "io/SurfaceVtk.H"

#include "core/error.H"
#include "io/AtomicVtkWrite.H"
#include "io/VtkErrorGuard.H"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <filesystem>
#include <system_error>

namespace gpic {

void writeSurface(const std::string& path, const std::vector<Space<3>::Vector>& corners,
                  const std::vector<std::array<int, 3>>& facets, double time, const std::vector<FacetField>& fields)
{
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(corners.size()));
    for (std::size_t i = 0; i < corners.size(); ++i)
        points->SetPoint(static_cast<vtkIdType>(i), corners[i].x(), corners[i].y(), corners[i].z());
    vtkNew<vtkCellArray> triangles;
    for (const auto& f : facets) {
        const vtkIdType ids[3] = {f[0], f[1], f[2]};
        triangles->InsertNextCell(3, ids);
    }
    vtkNew<vtkPolyData> surface;
    surface->SetPoints(points);
    surface->SetPolys(triangles);
    vtkNew<vtkDoubleArray> timeValue;
    timeValue->SetName("TimeValue");
    timeValue->SetNumberOfValues(1);
    timeValue->SetValue(0, time);
    surface->GetFieldData()->AddArray(timeValue);
    for (const FacetField& field : fields) {
        vtkNew<vtkDoubleArray> values;
        values->SetName(field.name.c_str());
        values->SetNumberOfValues(static_cast<vtkIdType>(field.values.size()));
        for (std::size_t f = 0; f < field.values.size(); ++f) values->SetValue(static_cast<vtkIdType>(f), field.values[f]);
        surface->GetCellData()->AddArray(values);
    }
    vtkNew<vtkXMLPolyDataWriter> writer;
    detail::writeXmlAtomically(writer, surface, path, "surface");
}

SurfaceVtkInfo readSurface(const std::string& path)
{
    const vtkSmartPointer<vtkPolyData> surface = detail::readXml<vtkXMLPolyDataReader>(path, "surface", "PolyData");
    SurfaceVtkInfo info;
    for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i) {
        double p[3];
        surface->GetPoint(i, p);
        info.corners.emplace_back(p[0], p[1], p[2]);
    }
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c) {
        surface->GetCellPoints(c, ids);
        if (ids->GetNumberOfIds() != 3) throw InputError(path, 0, "cannot read surface: a facet is not a triangle");
        info.facets.push_back({int(ids->GetId(0)), int(ids->GetId(1)), int(ids->GetId(2))});
    }
    vtkFieldData* fd = surface->GetFieldData();
    vtkDataArray* timeA = fd ? fd->GetArray("TimeValue") : nullptr;
    if (timeA && timeA->GetNumberOfTuples() > 0) info.time = timeA->GetComponent(0, 0);
    if (vtkCellData* cd = surface->GetCellData())
        for (int a = 0; a < cd->GetNumberOfArrays(); ++a) {
            vtkDataArray* array = cd->GetArray(a);
            if (!array || !array->GetName()) continue;
            FacetField field{array->GetName(), {}};
            for (vtkIdType c = 0; c < array->GetNumberOfTuples(); ++c) field.values.push_back(array->GetComponent(c, 0));
            info.fields.push_back(std::move(field));
        }
    return info;
}

} // namespace gpic
