// A filter's inputs read into Core's terms: selected and named arrays, labels, points, polylines and vertex cells,
// points and lines placed on the surface.
#include "KerfInputArrays.h"

#include "KerfFilterBorder.h"

#include "Error.h"
#include "Geodesic/SurfaceLocation.h"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkInformation.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>

#include <cmath>
#include <limits>

namespace kerf
{

namespace
{
// The values of a one-component array with `expected` tuples; throws naming it otherwise.
std::vector<double> checkedValues(vtkDataArray* array, const std::string& name, vtkIdType expected, const char* kind)
{
  if (array->GetNumberOfComponents() != 1)
  {
    throw Error(name + " has " + std::to_string(array->GetNumberOfComponents()) + " components; one is needed");
  }
  if (array->GetNumberOfTuples() != expected)
  {
    throw Error(name + " has " + std::to_string(array->GetNumberOfTuples()) + " values for " +
      std::to_string(expected) + " " + kind + "s");
  }
  std::vector<double> values;
  CopyToDoubles(array, 1, values);
  return values;
}
} // namespace

std::vector<SurfacePoint> ProjectPointsOntoSurface(
  const Surface& surface, vtkPointSet* points, double maximumDistance, const std::string& noun)
{
  const std::vector<Vector3> positions = ReadPoints(points);
  std::vector<SurfacePoint> projected;
  projected.reserve(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    projected.push_back(projectOntoSurface(surface, positions[i], maximumDistance, noun + " " + std::to_string(i)));
  }
  return projected;
}

std::vector<double> ReadInputArray(vtkAlgorithm* algorithm, int index, vtkIdType expected, const std::string& owner)
{
  vtkInformation* selection = algorithm->GetInputArrayInformation(index);
  const char* requested =
    selection && selection->Has(vtkDataObject::FIELD_NAME()) ? selection->Get(vtkDataObject::FIELD_NAME()) : nullptr;
  const int association = selection && selection->Has(vtkDataObject::FIELD_ASSOCIATION())
    ? selection->Get(vtkDataObject::FIELD_ASSOCIATION())
    : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  const char* kind = association == vtkDataObject::FIELD_ASSOCIATION_CELLS ? "cell" : "point";
  const std::string where = " (input array " + std::to_string(index) + ")";
  vtkDataArray* array = nullptr;
  const int port =
    selection && selection->Has(vtkAlgorithm::INPUT_PORT()) ? selection->Get(vtkAlgorithm::INPUT_PORT()) : 0;
  const int connection = selection && selection->Has(vtkAlgorithm::INPUT_CONNECTION())
    ? selection->Get(vtkAlgorithm::INPUT_CONNECTION())
    : 0;
  if (auto* data = vtkDataSet::SafeDownCast(algorithm->GetInputDataObject(port, connection)))
  {
    vtkDataSetAttributes* attributes = association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? static_cast<vtkDataSetAttributes*>(data->GetCellData())
      : static_cast<vtkDataSetAttributes*>(data->GetPointData());
    // No name selected: the active scalars, as VTK's own filters do.
    array = requested && *requested ? attributes->GetArray(requested) : attributes->GetScalars();
  }
  if (!array)
  {
    if (!requested || !*requested)
    {
      throw Error("no array is selected for " + owner + " and it has no active " + kind + " scalars" + where);
    }
    throw Error(owner + " has no one-component " + kind + " array named '" + requested + "'" + where);
  }
  return checkedValues(array,
    "the " + std::string(kind) + " array '" + (array->GetName() ? array->GetName() : "") + "' of " + owner + where,
    expected, kind);
}

std::vector<int> ReadTriangleLabels(
  vtkAlgorithm* algorithm, int index, const SurfaceInput& surface, vtkIdType cells, const std::string& owner)
{
  const std::vector<double> perCell = ReadInputArray(algorithm, index, cells, owner);
  std::vector<int> labels(perCell.size());
  for (std::size_t c = 0; c < perCell.size(); ++c)
  {
    const double value = perCell[c];
    if (!std::isfinite(value) || value != std::floor(value) || value < -1.0 || value > std::numeric_limits<int>::max())
    {
      throw Error("cell " + std::to_string(c) + " of " + owner + " holds " + std::to_string(value) +
        ", which is not a label (an integer >= -1)");
    }
    labels[c] = static_cast<int>(value);
  }
  return surface.CellValuesToTriangles(labels);
}

InputLabels LoadLabelledSurface(
  vtkAlgorithm* algorithm, SurfaceInput& surface, vtkPolyData* input, const MeshRequirements& requirements)
{
  LoadSurface(surface, input, requirements);
  InputLabels read;
  read.labels = ReadTriangleLabels(algorithm, 0, surface, input->GetNumberOfCells(), "the surface's labels");
  // The array ReadInputArray read: the selected name, else the active cell scalars.
  vtkInformation* selection = algorithm->GetInputArrayInformation(0);
  const char* requested =
    selection && selection->Has(vtkDataObject::FIELD_NAME()) ? selection->Get(vtkDataObject::FIELD_NAME()) : nullptr;
  vtkDataArray* scalars = input->GetCellData()->GetScalars();
  read.arrayName =
    requested && *requested ? requested : (scalars && scalars->GetName() ? scalars->GetName() : "Segment");
  return read;
}

std::vector<double> ReadNamedPointArray(vtkPointSet* points, const char* name, const std::string& owner)
{
  vtkDataArray* array = name && *name ? points->GetPointData()->GetArray(name) : nullptr;
  if (!array)
  {
    throw Error(owner + " have no one-component point array named '" + (name ? name : "") + "'");
  }
  return checkedValues(
    array, "the point array '" + std::string(name) + "' of " + owner, points->GetNumberOfPoints(), "point");
}

std::vector<double> ReadNamedCellArray(vtkPolyData* cells, const char* name, const std::string& owner)
{
  vtkDataArray* array = name && *name ? cells->GetCellData()->GetArray(name) : nullptr;
  if (!array)
  {
    throw Error(owner + " have no one-component cell array named '" + (name ? name : "") + "'");
  }
  return checkedValues(
    array, "the cell array '" + std::string(name) + "' of " + owner, cells->GetNumberOfCells(), "cell");
}

std::vector<Vector3> ReadPoints(vtkPointSet* points)
{
  std::vector<Vector3> coordinates(static_cast<std::size_t>(points ? points->GetNumberOfPoints() : 0));
  for (std::size_t i = 0; i < coordinates.size(); ++i)
  {
    points->GetPoint(static_cast<vtkIdType>(i), coordinates[i].data());
  }
  return coordinates;
}

namespace
{
// The points of each cell of one of a poly data's cell arrays (`kind` names its cells in errors).
std::vector<std::vector<Vector3>> ReadCellPoints(
  vtkPolyData* lines, vtkCellArray* array, const std::string& owner, const std::string& kind)
{
  std::vector<std::vector<Vector3>> polylines;
  if (!array)
  {
    return polylines;
  }
  auto cells = vtk::TakeSmartPointer(array->NewIterator());
  const vtkIdType pointCount = lines->GetNumberOfPoints();
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    std::vector<Vector3> polyline(static_cast<std::size_t>(size));
    for (vtkIdType k = 0; k < size; ++k)
    {
      if (ids[k] < 0 || ids[k] >= pointCount)
      {
        throw Error(kind + " " + std::to_string(cells->GetCurrentCellId()) + " of " + owner + " uses point " +
          std::to_string(ids[k]) + ", but " + owner + " has " + std::to_string(pointCount) + " points");
      }
      lines->GetPoint(ids[k], polyline[static_cast<std::size_t>(k)].data());
    }
    polylines.push_back(std::move(polyline));
  }
  return polylines;
}
} // namespace

std::vector<std::vector<Vector3>> ReadPolylines(vtkPolyData* lines, const std::string& owner)
{
  return lines ? ReadCellPoints(lines, lines->GetLines(), owner, "line") : std::vector<std::vector<Vector3>>();
}

std::vector<std::vector<Vector3>> ReadVertexCells(vtkPolyData* vertices, const std::string& owner)
{
  return vertices ? ReadCellPoints(vertices, vertices->GetVerts(), owner, "vertex cell")
                  : std::vector<std::vector<Vector3>>();
}

std::vector<SurfaceCurve> PlaceLinesOnSurface(
  const Surface& surface, vtkPolyData* lines, double maximumDistance, const std::string& owner)
{
  std::vector<SurfaceCurve> curves;
  std::vector<std::vector<Vector3>> polylines = ReadPolylines(lines, owner);
  for (std::size_t i = 0; i < polylines.size(); ++i)
  {
    std::vector<Vector3>& points = polylines[i];
    const bool closed = points.size() > 2 && points.front() == points.back();
    if (closed)
    {
      points.pop_back();
    }
    curves.push_back(
      placeCurveOnSurface(surface, points, closed, maximumDistance, owner + " line " + std::to_string(i)));
  }
  if (curves.empty())
  {
    throw Error(owner + " holds no line");
  }
  return curves;
}

} // namespace kerf
