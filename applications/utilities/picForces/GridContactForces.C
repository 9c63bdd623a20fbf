#include "GridContactForces.H"

#include "core/error.H"
#include "io/GridVtkRead.H"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

namespace gpic {

GridContactForces readGridContactForces(const std::string& path)
{
    vtkSmartPointer<vtkImageData> image = readGridImage(path, "set writeGrid yes in system/controlDict");
    vtkDataArray* f = image->GetPointData() ? image->GetPointData()->GetArray("contactForce") : nullptr;
    if (!f || f->GetNumberOfComponents() < 2)
        throw InputError(path, 0, "the grid has no contactForce: the case needs a rigid body (constant/rigidBodies)");

    GridContactForces g;
    double spacing[3];
    image->GetSpacing(spacing);
    g.spacing = Vector2(spacing[0], spacing[1]);
    const vtkIdType n = image->GetNumberOfPoints();
    g.position.resize(static_cast<std::size_t>(n));
    g.force.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i) {
        double x[3];
        image->GetPoint(i, x);
        g.position[static_cast<std::size_t>(i)] = Vector2(x[0], x[1]);
        g.force[static_cast<std::size_t>(i)] = Vector2(f->GetComponent(i, 0), f->GetComponent(i, 1));
    }
    vtkFieldData* fd = image->GetFieldData();
    vtkDataArray* t = fd ? fd->GetArray("TimeValue") : nullptr;
    if (t && t->GetNumberOfTuples() > 0) g.time = t->GetComponent(0, 0);
    return g;
}

} // namespace gpic
