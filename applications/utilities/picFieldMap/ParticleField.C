#include "ParticleField.H"

#include "core/error.H"
#include "io/VtkErrorGuard.H"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkNew.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace gpic {

namespace {

//- Component index of `name` in an array of `n` components; -1 for the magnitude.
int componentIndex(const std::string& name, int n, const std::string& path, const std::string& array)
{
    if (name == "mag") return -1;
    static const char* vector[] = {"x", "y", "z"};
    static const char* tensor[] = {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"};
    if (n == 3 || n == 2)
        for (int c = 0; c < n; ++c)
            if (name == vector[c]) return c;
    if (n == 9)
        for (int c = 0; c < 9; ++c)
            if (name == tensor[c]) return c;
    try {
        std::size_t used = 0;
        const int c = std::stoi(name, &used);
        if (used == name.size() && c >= 0 && c < n) return c;
    } catch (const std::exception&) {
    }
    std::string valid = "mag, 0-" + std::to_string(n - 1);
    if (n == 2 || n == 3) valid += n == 2 ? ", x, y" : ", x, y, z";
    if (n == 9) valid += ", xx, xy, xz, yx, yy, yz, zx, zy, zz";
    throw InputError(path, 0, "component '" + name + "' of array '" + array + "' (" + std::to_string(n) +
                                  " components) does not exist; valid choices: " + valid);
}

} // namespace

ParticleField readParticleField(const std::string& vtpPath, const std::string& field, const Slice* slice)
{
    const vtkSmartPointer<vtkPolyData> data = detail::readXml<vtkXMLPolyDataReader>(vtpPath, "particles", "PolyData");
    if (!data->GetPoints()) throw InputError(vtpPath, 0, "cannot read particles: no points");

    const auto colon = field.find(':');
    const std::string arrayName = field.substr(0, colon);
    vtkDataArray* array = data->GetPointData()->GetArray(arrayName.c_str());
    if (!array) {
        std::string names;
        for (int a = 0; a < data->GetPointData()->GetNumberOfArrays(); ++a)
            names += std::string(names.empty() ? "" : ", ") + data->GetPointData()->GetArrayName(a);
        throw InputError(vtpPath, 0, "array '" + arrayName + "' does not exist; valid choices: " + names);
    }
    const int n = array->GetNumberOfComponents();
    const int component = colon == std::string::npos ? (n == 1 ? 0 : -1)
                                                     : componentIndex(field.substr(colon + 1), n, vtpPath, arrayName);
    vtkDataArray* halfSize = data->GetPointData()->GetArray("halfSize");

    ParticleField out;
    out.name = field;
    if (vtkDataArray* t = data->GetFieldData()->GetArray("TimeValue")) out.time = t->GetComponent(0, 0);
    const vtkIdType count = data->GetNumberOfPoints();
    for (vtkIdType q = 0; q < count; ++q) {
        double p[3];
        data->GetPoint(q, p);
        if (slice) {
            const double reach = halfSize ? halfSize->GetComponent(q, slice->axis) : 0.0;
            if (std::abs(p[slice->axis] - slice->position) > reach) continue;
            out.x.emplace_back(p[slice->first()], p[slice->second()]);
        } else {
            out.x.emplace_back(p[0], p[1]);
        }
        double v = 0;
        if (component >= 0) {
            v = array->GetComponent(q, component);
        } else {
            for (int c = 0; c < n; ++c) v += array->GetComponent(q, c) * array->GetComponent(q, c);
            v = std::sqrt(v);
        }
        out.value.push_back(v);
        out.halfWidth.push_back(halfSize ? halfSize->GetComponent(q, slice ? slice->first() : 0) : 0.0);
    }
    return out;
}

double middleAlong(const std::string& vtpPath, int axis)
{
    const vtkSmartPointer<vtkPolyData> data = detail::readXml<vtkXMLPolyDataReader>(vtpPath, "particles", "PolyData");
    if (!data->GetPoints() || data->GetNumberOfPoints() == 0) return 0.0;
    double lo = 1e300, hi = -1e300;
    for (vtkIdType q = 0; q < data->GetNumberOfPoints(); ++q) {
        double p[3];
        data->GetPoint(q, p);
        lo = std::min(lo, p[axis]);
        hi = std::max(hi, p[axis]);
    }
    return 0.5 * (lo + hi);
}

} // namespace gpic
