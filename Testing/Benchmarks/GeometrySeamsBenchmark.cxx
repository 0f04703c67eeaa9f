// Benchmarks of the geometry-seam preprocessing: the filter, Core, and the paper's exhaustive candidate loop.
//
// Every benchmark runs on a generated cylinder with a ring of eight bumps in the middle
// (kerf::makeBumpyCylinder, nearly square quads), the handle on the lower 35% of its height, the
// fixed region on the upper 35% and the modeling region (30% of the triangles) between. Sizes:
// about 10k and 100k triangles (the 100k one has a 30k-triangle modeling region), and
// 100k-region: 125,200 triangles with the handle on the lower 10% and the fixed region on the
// upper 10%, so that the modeling region holds 100k triangles. For each size:
//   BM_GeometrySeamsFilter/<size>      vtkGeometrySeams, 15 rings, the whole RequestData path
//                                      (conversion, validation, descriptors, Core, output arrays)
//   BM_GeometrySeamsCore/<size>        kerf::computeGeometrySeams, 15 rings (global cut first)
//   BM_GeometrySeamsExhaustive/<size>  the same with the paper's loop, one max-flow per edge of
//                                      the sector contour, for the first ring only (15 rings take
//                                      about 15 times as long: each ring repeats the loop)
//   BM_SeamCarvingSurface/<size>       kerf::GeometrySeamCarving's set-up on the 15 rings (rest
//                                      OpenMesh copy, rungs and sides, first factorization)
//   BM_SeamCarvingUpdate/<size>        one handle update that changes no seam: the handle
//                                      moves by +-1e-4 around a stretch of one ring height
//                                      (the Laplace solve and the output surface)
//   BM_SeamCarvingSeamStep/<size>      one handle update that executes seams: the handle moves
//                                      between the identity and a stretch of 1.5 ring heights,
//                                      so each update splits (or undoes) a ring segment in
//                                      every sector, rebuilds the mesh and factors again
// The meshes, normal-cone angles and vtkPolyData are built once per size, outside the timed loops.
#include "BenchmarkPolyData.h"
#include "KerfBenchmarks.h"
#include "vtkGeometrySeams.h"

#include "Geometry/SurfaceDescriptors.h"
#include "Mesh/MeshGenerators.h"
#include "SeamCarving/GeometrySeamCarving.h"
#include "SeamCarving/GeometrySeams.h"

#include <benchmark/benchmark.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <array>
#include <map>
#include <memory>
#include <string>

namespace
{

struct CylinderSize
{
  const char* label;
  int around;
  int rings;
  double height;
  double minimumSeconds;
  double handleFraction; // the handle below this fraction of the height, the fixed region above 1 - it
  bool editingOnly;      // only the Geometry Seam Carving benchmarks
};

// 2 * 64 * 79 = 10,112, 2 * 200 * 250 = 100,000 and 2 * 200 * 313 = 125,200 triangles; the height
// keeps the quads square.
const std::array<CylinderSize, 3> Sizes = { {
  { "10k", 64, 80, 7.85, 0.5, 0.35, false },
  { "100k", 200, 251, 7.85, 2.0, 0.35, false },
  { "100k-region", 200, 314, 9.83, 2.0, 0.1, true },
} };

struct SeamScene
{
  kerf::TriangleMesh mesh;
  std::vector<double> regions;
  std::vector<double> normalConeAngle;
  vtkSmartPointer<vtkPolyData> polyData;
  int modelingTriangles = 0;
  double rowHeight = 0.0;
  kerf::GeometrySeamsResult seams; // 15 rings, for the editing benchmarks
};

const SeamScene& sceneOfSize(const CylinderSize& size)
{
  static std::map<std::string, std::unique_ptr<SeamScene>> scenes;
  std::unique_ptr<SeamScene>& scene = scenes[size.label];
  if (!scene)
  {
    auto built = std::make_unique<SeamScene>();
    built->mesh = kerf::makeBumpyCylinder(1.0, size.height, size.around, size.rings, 8, 0.5 * size.height, 0.4, 0.2);
    built->regions = kerf::heightBandRegions(
      built->mesh, size.handleFraction * size.height, (1.0 - size.handleFraction) * size.height);
    built->normalConeAngle = kerf::computeSurfaceDescriptors(built->mesh).normalConeAngle;
    built->modelingTriangles = static_cast<int>(kerf::checkSeamRegions(built->mesh, built->regions).size());
    built->polyData = kerf::benchmarks::MakePolyData(built->mesh);
    vtkNew<vtkDoubleArray> array;
    array->SetName("Region");
    for (double value : built->regions)
    {
      array->InsertNextValue(value);
    }
    built->polyData->GetPointData()->AddArray(array);
    built->rowHeight = size.height / (size.rings - 1);
    kerf::GeometrySeamsOptions options;
    built->seams = kerf::computeGeometrySeams(built->mesh, built->regions, built->normalConeAngle, options);
    scene = std::move(built);
  }
  return *scene;
}

void setCounters(benchmark::State& state, const SeamScene& scene)
{
  state.counters["triangles"] = scene.mesh.faceCount();
  state.counters["modeling_triangles"] = scene.modelingTriangles;
}

void geometrySeamsFilter(benchmark::State& state, const CylinderSize& size)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const SeamScene& { return sceneOfSize(size); },
    [](benchmark::State& st, const SeamScene& scene) {
      vtkNew<vtkGeometrySeams> filter;
      filter->SetInputData(scene.polyData);
      for (auto _ : st)
      {
        // New coordinates as far as every cache can tell: each run pays the whole path.
        scene.polyData->GetPoints()->GetData()->Modified();
        scene.polyData->Modified();
        filter->Update();
      }
      vtkDataArray* count = filter->GetOutput()->GetFieldData()->GetArray("RingCount");
      if (!count || count->GetComponent(0, 0) != 15.0)
      {
        kerf::benchmarks::Fail(st, "vtkGeometrySeams did not find 15 rings");
      }
    },
    setCounters);
}

void geometrySeamsCore(benchmark::State& state, const CylinderSize& size, kerf::RingCandidateSearch search, int rings)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const SeamScene& { return sceneOfSize(size); },
    [&](benchmark::State& st, const SeamScene& scene) {
      kerf::GeometrySeamsOptions options;
      options.search = search;
      options.ringCount = rings;
      std::size_t found = 0;
      int flows = 0;
      for (auto _ : st)
      {
        const kerf::GeometrySeamsResult result =
          kerf::computeGeometrySeams(scene.mesh, scene.regions, scene.normalConeAngle, options);
        found = result.ringCost.size();
        flows = result.maxFlowCount;
        benchmark::DoNotOptimize(result.ring.data());
      }
      if (found != static_cast<std::size_t>(rings))
      {
        kerf::benchmarks::Fail(st, "kerf::computeGeometrySeams found " + std::to_string(found) + " rings");
      }
      st.counters["max_flows"] = flows;
    },
    setCounters);
}

kerf::SeamCarvingInput carvingInput(const SeamScene& scene)
{
  kerf::SeamCarvingInput input;
  input.mesh = &scene.mesh;
  input.region = scene.regions;
  input.faceRing = scene.seams.ring;
  input.faceSector = scene.seams.faceSector;
  input.faceCost = scene.seams.faceCost;
  input.normalConeAngle = scene.normalConeAngle;
  return input;
}

Eigen::Matrix4d stretch(double dz)
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(2, 3) = -dz; // the handle lies below the modeling region
  return m;
}

void seamCarvingSession(benchmark::State& state, const CylinderSize& size)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const SeamScene& { return sceneOfSize(size); },
    [](benchmark::State& st, const SeamScene& scene) {
      const kerf::SeamCarvingInput input = carvingInput(scene);
      for (auto _ : st)
      {
        kerf::GeometrySeamCarving carving(input, kerf::SeamCarvingOptions());
        benchmark::DoNotOptimize(carving.deform(Eigen::Matrix4d::Identity()).points.data());
      }
    },
    setCounters);
}

// One deform() per iteration, alternating between two handle positions.
void seamCarvingUpdate(benchmark::State& state, const CylinderSize& size, double first, double second)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const SeamScene& { return sceneOfSize(size); },
    [&](benchmark::State& st, const SeamScene& scene) {
      kerf::GeometrySeamCarving carving(carvingInput(scene), kerf::SeamCarvingOptions());
      carving.deform(stretch(first * scene.rowHeight));
      bool toSecond = true;
      int factorizations = 0, updates = 0, split = 0;
      for (auto _ : st)
      {
        const kerf::SeamCarvingResult& result = carving.deform(stretch((toSecond ? second : first) * scene.rowHeight));
        factorizations += result.factorizations;
        split = std::max(split, result.splitSegments);
        ++updates;
        toSecond = !toSecond;
      }
      st.counters["factorizations_per_update"] = static_cast<double>(factorizations) / std::max(updates, 1);
      st.counters["split_segments"] = split;
    },
    setCounters);
}

} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterGeometrySeamsBenchmarks(bool useSizeMinimumTimes)
{
  for (const CylinderSize& size : Sizes)
  {
    const std::string label = size.label;
    std::vector<benchmark::internal::Benchmark*> registered;
    if (!size.editingOnly)
    {
      registered = {
        benchmark::RegisterBenchmark(("BM_GeometrySeamsFilter/" + label).c_str(), geometrySeamsFilter, size),
        benchmark::RegisterBenchmark(("BM_GeometrySeamsCore/" + label).c_str(),
          [size](benchmark::State& state) { geometrySeamsCore(state, size, RingCandidateSearch::GlobalCutFirst, 15); }),
        benchmark::RegisterBenchmark(("BM_GeometrySeamsExhaustive/" + label).c_str(),
          [size](benchmark::State& state) { geometrySeamsCore(state, size, RingCandidateSearch::Exhaustive, 1); }),
      };
    }
    registered.push_back(
      benchmark::RegisterBenchmark(("BM_SeamCarvingSurface/" + label).c_str(), seamCarvingSession, size));
    registered.push_back(
      benchmark::RegisterBenchmark(("BM_SeamCarvingUpdate/" + label).c_str(), [size](benchmark::State& state) {
        seamCarvingUpdate(state, size, 1.0, 1.0 + 1e-4 / (size.height / (size.rings - 1)));
      }));
    registered.push_back(benchmark::RegisterBenchmark(("BM_SeamCarvingSeamStep/" + label).c_str(),
      [size](benchmark::State& state) { seamCarvingUpdate(state, size, 0.0, 1.0); }));
    for (benchmark::internal::Benchmark* benchmark : registered)
    {
      benchmark->Unit(benchmark::kMillisecond)->UseRealTime();
      if (useSizeMinimumTimes)
      {
        benchmark->MinTime(size.minimumSeconds);
      }
    }
  }
}

} // namespace benchmarks
} // namespace kerf
