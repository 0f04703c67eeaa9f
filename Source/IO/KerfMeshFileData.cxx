// Conversion of kerf::MeshFileData into vtkPolyData for vtkKerfMeshFileReader.
#include "KerfMeshFileData.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf
{

namespace
{
// A double as a float; values beyond float's range become infinities (a plain cast is undefined).
float narrow(double value)
{
  constexpr double largest = std::numeric_limits<float>::max();
  return value > largest ? std::numeric_limits<float>::infinity()
                         : (value < -largest ? -std::numeric_limits<float>::infinity() : static_cast<float>(value));
}

vtkSmartPointer<vtkCellArray> toCellArray(const CellList& cells)
{
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(cells.offsets.size()));
  std::copy(cells.offsets.begin(), cells.offsets.end(), offsets->GetPointer(0));
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(cells.indices.size()));
  std::copy(cells.indices.begin(), cells.indices.end(), connectivity->GetPointer(0));
  auto array = vtkSmartPointer<vtkCellArray>::New();
  array->SetData(offsets, connectivity);
  return array;
}

vtkSmartPointer<vtkDataArray> toDataArray(const MeshFileArray& source)
{
  vtkSmartPointer<vtkDataArray> array;
  if (source.role == MeshFileArray::Role::Colors)
  {
    auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colors->SetNumberOfValues(static_cast<vtkIdType>(source.values.size()));
    for (std::size_t i = 0; i < source.values.size(); ++i)
    {
      const double v = source.values[i];
      colors->SetValue(
        static_cast<vtkIdType>(i), static_cast<unsigned char>(std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 255.0)));
    }
    array = colors;
  }
  else
  {
    auto values = vtkSmartPointer<vtkFloatArray>::New();
    values->SetNumberOfValues(static_cast<vtkIdType>(source.values.size()));
    std::transform(source.values.begin(), source.values.end(), values->GetPointer(0), narrow);
    array = values;
  }
  array->SetNumberOfComponents(source.components);
  array->SetName(source.name.c_str());
  return array;
}

void addArrays(const std::vector<MeshFileArray>& arrays, vtkDataSetAttributes* attributes)
{
  for (const MeshFileArray& a : arrays)
  {
    vtkSmartPointer<vtkDataArray> array = toDataArray(a);
    switch (a.role)
    {
      case MeshFileArray::Role::Normals:
        attributes->SetNormals(array);
        break;
      case MeshFileArray::Role::TextureCoordinates:
        attributes->SetTCoords(array);
        break;
      case MeshFileArray::Role::Colors:
        if (!attributes->GetScalars())
        {
          attributes->SetScalars(array);
          break;
        }
        attributes->AddArray(array);
        break;
      default:
        attributes->AddArray(array);
    }
  }
}
} // namespace

vtkSmartPointer<vtkPolyData> MeshFileDataToPolyData(const MeshFileData& data)
{
  vtkSmartPointer<vtkDataArray> coordinates;
  if (data.singlePrecision)
  {
    auto floats = vtkSmartPointer<vtkFloatArray>::New();
    floats->SetNumberOfComponents(3);
    floats->SetNumberOfTuples(static_cast<vtkIdType>(data.pointCount()));
    // The values came from floats, so narrowing them back is exact.
    std::transform(data.points.begin(), data.points.end(), floats->GetPointer(0), narrow);
    coordinates = floats;
  }
  else
  {
    auto doubles = vtkSmartPointer<vtkDoubleArray>::New();
    doubles->SetNumberOfComponents(3);
    doubles->SetNumberOfTuples(static_cast<vtkIdType>(data.pointCount()));
    std::copy(data.points.begin(), data.points.end(), doubles->GetPointer(0));
    coordinates = doubles;
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->SetPoints(points);
  if (data.vertices.size() > 0)
  {
    output->SetVerts(toCellArray(data.vertices));
  }
  if (data.lines.size() > 0)
  {
    output->SetLines(toCellArray(data.lines));
  }
  output->SetPolys(toCellArray(data.polygons));
  addArrays(data.pointArrays, output->GetPointData());
  if (data.vertices.size() == 0 && data.lines.size() == 0)
  {
    addArrays(data.polygonArrays, output->GetCellData());
  }
  return output;
}

} // namespace kerf
