// Converts vtkPolyData to kerf::TriangleMesh (triangulating polygons and strips) and back.
#include "KerfSurfaceInput.h"

#include "Error.h"
#include "Mesh/PolygonMesh.h"
#include "Mesh/SurfaceConversion.h"

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

#include <algorithm>
#include <cstring>
#include <limits>
#include <mutex>
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
    appendCells(cells->GetOffsetsArray64(), cells->GetConnectivityArray64(), firstCellId, strips, pointCount, polygons,
      polygonCell);
  }
  else
  {
    appendCells(cells->GetOffsetsArray32(), cells->GetConnectivityArray32(), firstCellId, strips, pointCount, polygons,
      polygonCell);
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

/// One conversion of a vtkPolyData's geometry, shared by every SurfaceInput that loads it.
struct ConvertedSurface
{
  std::shared_ptr<const Surface> surface;
  MeshReport report;
  std::vector<vtkIdType> source;
  std::vector<int> representatives;
  int welded = 0;
  bool rebuild = false;
  /// The geometry it came from: objects and modification times of the point array and the four
  /// cell arrays (the coordinates are compared as well).
  std::vector<std::pair<const void*, vtkMTimeType>> key;
};

namespace
{
std::vector<std::pair<const void*, vtkMTimeType>> geometryKey(vtkPolyData* input)
{
  std::vector<std::pair<const void*, vtkMTimeType>> key;
  vtkDataArray* points = input->GetPoints() ? input->GetPoints()->GetData() : nullptr;
  key.emplace_back(points, points ? points->GetMTime() : 0);
  for (vtkCellArray* cells : { input->GetVerts(), input->GetLines(), input->GetPolys(), input->GetStrips() })
  {
    key.emplace_back(cells, cells ? cells->GetMTime() : 0);
  }
  return key;
}

// Whether the input's coordinates are, bit for bit, those of the converted mesh. Points edited in
// place without vtkPoints::Modified() keep their modification time: the coordinates themselves
// are compared (the mesh keeps every input point, unreferenced ones included).
bool samePoints(vtkPolyData* input, const ConvertedSurface& converted)
{
  const std::vector<Vector3>& loaded = converted.surface->mesh().points();
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
  std::vector<double> copied;
  auto* doubles = vtkDoubleArray::SafeDownCast(points);
  if (!doubles && !CopyToDoubles(points, 3, copied))
  {
    return false;
  }
  const double* coordinates = doubles ? doubles->GetPointer(0) : copied.data();
  return std::memcmp(coordinates, loaded.data(), loaded.size() * sizeof(Vector3)) == 0;
}

// Triangulates, welds and validates the input; throws kerf::Error or std::bad_alloc.
std::shared_ptr<ConvertedSurface> convert(vtkPolyData* input)
{
  auto converted = std::make_shared<ConvertedSurface>();
  PolygonMesh polygons;
  const vtkIdType pointCount = input->GetNumberOfPoints();
  if (pointCount > std::numeric_limits<int>::max())
  {
    throw Error("the input has more points than Kerf indexes (2^31 - 1)");
  }
  if (pointCount > 0)
  {
    std::vector<double> coordinates;
    if (!CopyToDoubles(input->GetPoints()->GetData(), 3, coordinates))
    {
      throw Error("the input points do not have 3 components");
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

  ConvertedPolygons triangles = convertPolygons(std::move(polygons));
  converted->rebuild = verts > 0 || lines > 0 || strips > 0 || !triangles.allTriangles;
  converted->source.resize(triangles.sourcePolygon.size());
  for (std::size_t t = 0; t < converted->source.size(); ++t)
  {
    converted->source[t] = polygonCell[triangles.sourcePolygon[t]];
  }
  converted->representatives = std::move(triangles.representatives);
  converted->welded = triangles.welded;
  converted->surface = std::make_shared<const Surface>(std::move(triangles.mesh));
  converted->report = inspectMesh(converted->surface->mesh());
  return converted;
}

// The conversions alive in this process, found by their geometry key.
std::mutex RegistryMutex;
std::vector<std::weak_ptr<const ConvertedSurface>> Registry;

std::shared_ptr<const ConvertedSurface> findConverted(
  vtkPolyData* input, const std::vector<std::pair<const void*, vtkMTimeType>>& key)
{
  std::lock_guard<std::mutex> lock(RegistryMutex);
  for (const auto& entry : Registry)
  {
    std::shared_ptr<const ConvertedSurface> converted = entry.lock();
    if (converted && converted->key == key && samePoints(input, *converted))
    {
      return converted;
    }
  }
  return nullptr;
}

void registerConverted(const std::shared_ptr<const ConvertedSurface>& converted)
{
  std::lock_guard<std::mutex> lock(RegistryMutex);
  Registry.erase(std::remove_if(Registry.begin(), Registry.end(),
                   [](const std::weak_ptr<const ConvertedSurface>& entry) { return entry.expired(); }),
    Registry.end());
  Registry.push_back(converted);
}
} // namespace

SurfaceInput::SurfaceInput() = default;
SurfaceInput::~SurfaceInput() = default;

bool SurfaceInput::Load(vtkPolyData* input, const MeshRequirements& requirements, std::string& error)
{
  if (!input)
  {
    error = "the input is not a vtkPolyData";
    return false;
  }
  try
  {
    const std::vector<std::pair<const void*, vtkMTimeType>> key = geometryKey(input);
    std::shared_ptr<const ConvertedSurface> converted;
    if (this->Current && this->Current->key == key && samePoints(input, *this->Current))
    {
      converted = this->Current;
    }
    else
    {
      converted = findConverted(input, key);
    }
    if (!converted)
    {
      std::shared_ptr<ConvertedSurface> fresh = convert(input);
      fresh->key = key;
      registerConverted(fresh);
      converted = std::move(fresh);
    }
    this->Current = converted;
  }
  catch (const Error& e)
  {
    this->Current.reset();
    error = std::string("the input surface is not accepted: ") + e.what() + ".";
    return false;
  }
  catch (const std::bad_alloc&)
  {
    this->Current.reset();
    error = "out of memory while converting the input surface";
    return false;
  }
  const std::string problems = describeProblems(this->Current->report, requirements, &this->Current->source);
  if (!problems.empty())
  {
    error = "the input surface is not accepted: " + problems + ".";
    return false;
  }
  return true;
}

const std::shared_ptr<const Surface>& SurfaceInput::SharedSurface() const
{
  return this->Current->surface;
}

const MeshReport& SurfaceInput::Report() const
{
  return this->Current->report;
}

const std::vector<vtkIdType>& SurfaceInput::SourceCells() const
{
  return this->Current->source;
}

int SurfaceInput::WeldedPointCount() const
{
  return this->Current->welded;
}

int SurfaceInput::Representative(int point) const
{
  return this->Current->representatives[static_cast<std::size_t>(point)];
}

bool SurfaceInput::Rebuilt() const
{
  return this->Current->rebuild;
}

void SurfaceInput::MakeOutput(vtkPolyData* input, vtkPolyData* output) const
{
  if (!this->Rebuilt())
  {
    output->CopyStructure(input);
    output->GetPointData()->PassData(input->GetPointData());
    output->GetCellData()->PassData(input->GetCellData());
    output->GetFieldData()->PassData(input->GetFieldData());
    return;
  }
  output->SetPoints(input->GetPoints());
  vtkNew<vtkCellArray> triangles;
  const TriangleMesh& mesh = this->Mesh();
  triangles->AllocateExact(mesh.faceCount(), 3 * mesh.faceCount());
  for (const Triangle& t : mesh.triangles())
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  output->SetPolys(triangles);
  output->GetPointData()->PassData(input->GetPointData());
  vtkCellData* inCells = input->GetCellData();
  vtkCellData* outCells = output->GetCellData();
  outCells->CopyAllocate(inCells, mesh.faceCount());
  const std::vector<vtkIdType>& source = this->SourceCells();
  for (vtkIdType t = 0; t < static_cast<vtkIdType>(source.size()); ++t)
  {
    outCells->CopyData(inCells, source[t], t);
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

vtkSmartPointer<vtkUnsignedCharArray> MakeArray(const char* name, const std::vector<unsigned char>& flags)
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
