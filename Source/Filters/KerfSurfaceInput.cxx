// Converts vtkPolyData to kerf::TriangleMesh (triangulating polygons and strips) and back.
#include "KerfSurfaceInput.h"

#include "Error.h"
#include "Mesh/PolygonMesh.h"
#include "Mesh/PointWelding.h"
#include "Mesh/Triangulation.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <cstring>
#include <limits>
#include <new>
#include <string>

namespace kerf
{

namespace
{
// Appends every cell of a vtkCellArray as a polygon (or, for strips, as triangles); throws on a
// point id outside [0, pointCount).
template <typename OffsetArray>
void appendCells(OffsetArray* offsets, OffsetArray* connectivity, vtkIdType firstCellId, bool strips,
  vtkIdType pointCount, PolygonMesh& polygons, std::vector<vtkIdType>& polygonCell)
{
  const vtkIdType cells = offsets->GetNumberOfValues() - 1;
  const auto* off = offsets->GetPointer(0);
  const auto* conn = connectivity->GetPointer(0);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const vtkIdType begin = static_cast<vtkIdType>(off[c]);
    const vtkIdType size = static_cast<vtkIdType>(off[c + 1]) - begin;
    for (vtkIdType k = 0; k < size; ++k)
    {
      const vtkIdType id = static_cast<vtkIdType>(conn[begin + k]);
      if (id < 0 || id >= pointCount)
      {
        throw Error("cell " + std::to_string(firstCellId + c) + " uses point " + std::to_string(id) +
          ", but there are " + std::to_string(pointCount) + " points");
      }
    }
    if (!strips)
    {
      for (vtkIdType k = 0; k < size; ++k)
      {
        polygons.polygonIndices.push_back(static_cast<int>(conn[begin + k]));
      }
      polygons.polygonOffsets.push_back(static_cast<int>(polygons.polygonIndices.size()));
      polygonCell.push_back(firstCellId + c);
      continue;
    }
    // Strip triangle k is (k, k+1, k+2), with odd triangles flipped to keep the orientation.
    for (vtkIdType k = 0; k + 2 < size; ++k)
    {
      const int a = static_cast<int>(conn[begin + k]);
      const int b = static_cast<int>(conn[begin + k + 1]);
      const int d = static_cast<int>(conn[begin + k + 2]);
      if (k % 2 == 0)
      {
        polygons.polygonIndices.insert(polygons.polygonIndices.end(), { a, b, d });
      }
      else
      {
        polygons.polygonIndices.insert(polygons.polygonIndices.end(), { b, a, d });
      }
      polygons.polygonOffsets.push_back(static_cast<int>(polygons.polygonIndices.size()));
      polygonCell.push_back(firstCellId + c);
    }
  }
}

void appendCellArray(vtkCellArray* cells, vtkIdType firstCellId, bool strips, vtkIdType pointCount,
  PolygonMesh& polygons, std::vector<vtkIdType>& polygonCell)
{
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return;
  }
  if (cells->IsStorage64Bit())
  {
    appendCells(cells->GetOffsetsArray64(), cells->GetConnectivityArray64(), firstCellId, strips,
      pointCount, polygons, polygonCell);
  }
  else
  {
    appendCells(cells->GetOffsetsArray32(), cells->GetConnectivityArray32(), firstCellId, strips,
      pointCount, polygons, polygonCell);
  }
}

vtkIdType cellCount(vtkCellArray* cells)
{
  return cells ? cells->GetNumberOfCells() : 0;
}
} // namespace

bool CopyToDoubles(vtkDataArray* array, int components, std::vector<double>& values)
{
  if (!array || array->GetNumberOfComponents() != components)
  {
    return false;
  }
  const vtkIdType tuples = array->GetNumberOfTuples();
  values.resize(static_cast<std::size_t>(tuples) * components);
  if (auto* doubles = vtkDoubleArray::SafeDownCast(array))
  {
    if (tuples > 0)
    {
      std::memcpy(values.data(), doubles->GetPointer(0), values.size() * sizeof(double));
    }
    return true;
  }
  if (auto* floats = vtkFloatArray::SafeDownCast(array))
  {
    const float* data = floats->GetPointer(0);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
      values[i] = data[i];
    }
    return true;
  }
  for (vtkIdType t = 0; t < tuples; ++t)
  {
    for (int c = 0; c < components; ++c)
    {
      values[static_cast<std::size_t>(t) * components + c] = array->GetComponent(t, c);
    }
  }
  return true;
}

bool SurfaceInput::Load(vtkPolyData* input, const MeshRequirements& requirements, std::string& error)
{
  if (!input)
  {
    error = "the input is not a vtkPolyData";
    return false;
  }
  try
  {
    PolygonMesh polygons;
    const vtkIdType pointCount = input->GetNumberOfPoints();
    if (pointCount > std::numeric_limits<int>::max())
    {
      error = "the input has more points than Kerf indexes (2^31 - 1)";
      return false;
    }
    if (pointCount > 0)
    {
      std::vector<double> coordinates;
      if (!CopyToDoubles(input->GetPoints()->GetData(), 3, coordinates))
      {
        error = "the input points do not have 3 components";
        return false;
      }
      polygons.points.resize(static_cast<std::size_t>(pointCount));
      for (vtkIdType i = 0; i < pointCount; ++i)
      {
        polygons.points[i] = Vector3(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]);
      }
    }
    const vtkIdType verts = cellCount(input->GetVerts());
    const vtkIdType lines = cellCount(input->GetLines());
    const vtkIdType polys = cellCount(input->GetPolys());
    const vtkIdType strips = cellCount(input->GetStrips());
    std::vector<vtkIdType> polygonCell;
    polygonCell.reserve(static_cast<std::size_t>(polys + strips));
    polygons.polygonIndices.reserve(static_cast<std::size_t>(polys) * 3);
    polygons.polygonOffsets.reserve(static_cast<std::size_t>(polys + strips) + 1);
    appendCellArray(input->GetPolys(), verts + lines, false, pointCount, polygons, polygonCell);
    appendCellArray(input->GetStrips(), verts + lines + polys, true, pointCount, polygons, polygonCell);

    Triangulation triangulation = triangulatePolygons(polygons);
    this->Rebuild = verts > 0 || lines > 0 || strips > 0 || !triangulation.allTriangles;
    this->Source.resize(triangulation.sourcePolygon.size());
    for (std::size_t t = 0; t < this->Source.size(); ++t)
    {
      this->Source[t] = polygonCell[triangulation.sourcePolygon[t]];
    }
    TriangleMesh::checkIndices(triangulation.triangles, static_cast<int>(polygons.points.size()));
    this->Representatives = findCoincidentPoints(polygons.points);
    this->Welded = 0;
    for (std::size_t i = 0; i < this->Representatives.size(); ++i)
    {
      this->Welded += this->Representatives[i] != static_cast<int>(i) ? 1 : 0;
    }
    weldTriangles(this->Representatives, triangulation.triangles);
    this->Surface = TriangleMesh(std::move(polygons.points), std::move(triangulation.triangles));
    this->Inspection = inspectMesh(this->Surface);
    const std::string problems = describeProblems(this->Inspection, requirements);
    if (!problems.empty())
    {
      error = "the input surface is not accepted: " + problems + ".";
      return false;
    }
  }
  catch (const Error& e)
  {
    error = std::string("the input surface is not accepted: ") + e.what() + ".";
    return false;
  }
  catch (const std::bad_alloc&)
  {
    error = "out of memory while converting the input surface";
    return false;
  }
  return true;
}

namespace
{
std::vector<std::pair<const void*, vtkMTimeType>> geometryKey(vtkPolyData* input)
{
  std::vector<std::pair<const void*, vtkMTimeType>> key;
  vtkDataArray* points = input && input->GetPoints() ? input->GetPoints()->GetData() : nullptr;
  key.emplace_back(points, points ? points->GetMTime() : 0);
  for (vtkCellArray* cells : { input->GetVerts(), input->GetLines(), input->GetPolys(), input->GetStrips() })
  {
    key.emplace_back(cells, cells ? cells->GetMTime() : 0);
  }
  return key;
}
} // namespace

bool SurfaceInput::SamePoints(vtkPolyData* input) const
{
  // Points edited in place without vtkPoints::Modified() keep their modification time: compare
  // the coordinates themselves (the mesh keeps every input point, unreferenced ones included).
  const std::vector<Vector3>& loaded = this->Surface.points();
  vtkDataArray* points = input->GetPoints() ? input->GetPoints()->GetData() : nullptr;
  if (!points || points->GetNumberOfTuples() != static_cast<vtkIdType>(loaded.size()))
  {
    return loaded.empty() && (!points || points->GetNumberOfTuples() == 0);
  }
  if (loaded.empty())
  {
    return true;
  }
  static_assert(sizeof(Vector3) == 3 * sizeof(double), "Vector3 holds three packed doubles");
  std::vector<double> converted;
  auto* doubles = vtkDoubleArray::SafeDownCast(points);
  if (!doubles && !CopyToDoubles(points, 3, converted))
  {
    return false;
  }
  const double* coordinates = doubles ? doubles->GetPointer(0) : converted.data();
  return std::memcmp(coordinates, loaded.data(), loaded.size() * sizeof(Vector3)) == 0;
}

bool SurfaceInput::LoadIfChanged(
  vtkPolyData* input, const MeshRequirements& requirements, std::string& error, bool& reused)
{
  if (!input)
  {
    error = "the input is not a vtkPolyData";
    return false;
  }
  const std::vector<std::pair<const void*, vtkMTimeType>> key = geometryKey(input);
  reused = this->Loaded && key == this->LoadedGeometry && this->SamePoints(input);
  if (reused)
  {
    return true;
  }
  this->Loaded = false;
  if (!this->Load(input, requirements, error))
  {
    return false;
  }
  this->LoadedGeometry = key;
  this->Loaded = true;
  return true;
}

void SurfaceInput::MakeOutput(vtkPolyData* input, vtkPolyData* output) const
{
  if (!this->Rebuild)
  {
    output->CopyStructure(input);
    output->GetPointData()->PassData(input->GetPointData());
    output->GetCellData()->PassData(input->GetCellData());
    output->GetFieldData()->PassData(input->GetFieldData());
    return;
  }
  output->SetPoints(input->GetPoints());
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(this->Surface.faceCount(), 3 * this->Surface.faceCount());
  for (const Triangle& t : this->Surface.triangles())
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  output->SetPolys(triangles);
  output->GetPointData()->PassData(input->GetPointData());
  vtkCellData* inCells = input->GetCellData();
  vtkCellData* outCells = output->GetCellData();
  outCells->CopyAllocate(inCells, this->Surface.faceCount());
  for (vtkIdType t = 0; t < static_cast<vtkIdType>(this->Source.size()); ++t)
  {
    outCells->CopyData(inCells, this->Source[t], t);
  }
  output->GetFieldData()->PassData(input->GetFieldData());
}

vtkSmartPointer<vtkDoubleArray> MakeArray(const char* name, const std::vector<double>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  if (!values.empty())
  {
    std::memcpy(array->GetPointer(0), values.data(), values.size() * sizeof(double));
  }
  return array;
}

vtkSmartPointer<vtkDoubleArray> MakeArray(const char* name, const std::vector<Vector3>& vectors)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(vectors.size()));
  double* data = vectors.empty() ? nullptr : array->GetPointer(0);
  for (std::size_t i = 0; i < vectors.size(); ++i)
  {
    data[3 * i] = vectors[i].x();
    data[3 * i + 1] = vectors[i].y();
    data[3 * i + 2] = vectors[i].z();
  }
  return array;
}

vtkSmartPointer<vtkUnsignedCharArray> MakeArray(
  const char* name, const std::vector<unsigned char>& flags)
{
  auto array = vtkSmartPointer<vtkUnsignedCharArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(flags.size()));
  if (!flags.empty())
  {
    std::memcpy(array->GetPointer(0), flags.data(), flags.size());
  }
  return array;
}

} // namespace kerf
