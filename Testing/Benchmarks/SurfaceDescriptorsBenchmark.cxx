// Benchmarks of the surface-descriptors filter, vtkCurvatures and the Core steps the filter runs.
//
// Every benchmark runs on generated closed tori (kerf::makeTorus, about twice as many vertices
// around as across the tube) of about 10k, 100k and 1M triangles; the exact triangle and vertex
// counts are printed as counters. For each size, in this order:
//   BM_SurfaceDescriptorsFilter/<size>    vtkSurfaceDescriptors, the whole RequestData path
//                                         (conversion, welding, validation, Core, output arrays)
//   BM_VTKCurvaturesMean/<size>           vtkCurvatures with SetCurvatureTypeToMean, for scale
//   BM_CoreSurfaceDescriptors/<size>      kerf::computeSurfaceDescriptors on a prebuilt mesh
//   BM_CoreMeshBuildAndValidation/<size>  kerf::TriangleMesh constructor + kerf::inspectMesh
// The meshes and their vtkPolyData are built once per size, outside the timed loops. Everything
// runs on one thread.
#include "BenchmarkPolyData.h"
#include "KerfBenchmarks.h"
#include "vtkSurfaceDescriptors.h"

#include "Geometry/SurfaceDescriptors.h"
#include "Mesh/MeshGenerators.h"
#include "Mesh/MeshValidation.h"
#include "Mesh/TriangleMesh.h"

#include <benchmark/benchmark.h>

#include <vtkCurvatures.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{

/// One benchmark size: a torus with `around` x `tube` vertices and 2 * around * tube triangles.
struct SurfaceSize
{
  const char* label;
  int around;
  int tube;
  double minimumSeconds; ///< per-benchmark minimum time unless --benchmark_min_time is given
};

// 2 * 100 * 50 = 10,000; 2 * 316 * 158 = 99,856; 2 * 1000 * 500 = 1,000,000 triangles.
// The 1M filter takes about a second per run, so its minimum time asks for several runs.
const std::array<SurfaceSize, 3> Sizes = { { { "10k", 100, 50, 0.5 }, { "100k", 316, 158, 1.0 },
  { "1M", 1000, 500, 4.0 } } };

/// The Core mesh and its vtkPolyData for one size.
struct BenchmarkSurface
{
  kerf::TriangleMesh mesh;
  vtkSmartPointer<vtkPolyData> polyData;
};

// Built on first use, so that a filtered run (the smoke test) never builds the 1M mesh.
const BenchmarkSurface& surfaceOfSize(const SurfaceSize& size)
{
  static std::map<std::string, std::unique_ptr<BenchmarkSurface>> surfaces;
  std::unique_ptr<BenchmarkSurface>& surface = surfaces[size.label];
  if (!surface)
  {
    auto built = std::make_unique<BenchmarkSurface>();
    // Tube radius 1 at distance 2 with twice the vertices around: nearly square quads.
    built->mesh = kerf::makeTorus(2.0, 1.0, size.around, size.tube);
    built->polyData = kerf::benchmarks::MakePolyData(built->mesh);
    surface = std::move(built);
  }
  return *surface;
}

using kerf::benchmarks::Fail;

// Fetches the surface, or marks the benchmark failed and returns null.
const BenchmarkSurface* surfaceOrFail(benchmark::State& state, const SurfaceSize& size)
{
  try
  {
    return &surfaceOfSize(size);
  }
  catch (const std::exception& e)
  {
    Fail(state, std::string("cannot build the ") + size.label + " torus: " + e.what());
    return nullptr;
  }
}

// Exact counts as counters (the console abbreviates them, e.g. 99.856k; JSON keeps integers) and
// the torus grid as the label.
void setCounters(benchmark::State& state, const BenchmarkSurface& surface, const SurfaceSize& size)
{
  state.counters["triangles"] = surface.mesh.faceCount();
  state.counters["vertices"] = surface.mesh.vertexCount();
  state.SetLabel("torus " + std::to_string(size.around) + "x" + std::to_string(size.tube));
}

// True if the output has a point array of that name with one tuple per point.
bool hasPointArray(vtkPolyData* output, const char* name)
{
  vtkDataArray* array = output ? output->GetPointData()->GetArray(name) : nullptr;
  return array && array->GetNumberOfTuples() == output->GetNumberOfPoints() && output->GetNumberOfPoints() > 0;
}

void surfaceDescriptorsFilter(benchmark::State& state, const SurfaceSize& size)
{
  const BenchmarkSurface* surface = surfaceOrFail(state, size);
  if (!surface)
  {
    return;
  }
  vtkNew<vtkSurfaceDescriptors> filter;
  filter->SetInputData(surface->polyData);
  for (auto _ : state)
  {
    // New coordinates as far as every cache can tell (the conversion shared between filters is
    // keyed by the arrays' modification times), so each run pays the whole path.
    surface->polyData->GetPoints()->GetData()->Modified();
    surface->polyData->Modified();
    filter->Update();
  }
  // Checked after the loop so that no extra untimed run is needed; the filter reports its own
  // errors with vtkErrorMacro, which prints "ERROR:".
  if (!hasPointArray(filter->GetOutput(), filter->GetMeanCurvatureArrayName()))
  {
    Fail(state, "vtkSurfaceDescriptors produced no MeanCurvature array");
  }
  setCounters(state, *surface, size);
}

void vtkCurvaturesMean(benchmark::State& state, const SurfaceSize& size)
{
  const BenchmarkSurface* surface = surfaceOrFail(state, size);
  if (!surface)
  {
    return;
  }
  vtkNew<vtkCurvatures> curvatures;
  curvatures->SetCurvatureTypeToMean();
  curvatures->SetInputData(surface->polyData);
  for (auto _ : state)
  {
    curvatures->Modified();
    curvatures->Update();
  }
  if (!hasPointArray(curvatures->GetOutput(), "Mean_Curvature"))
  {
    Fail(state, "vtkCurvatures produced no Mean_Curvature array");
  }
  setCounters(state, *surface, size);
}

void coreSurfaceDescriptors(benchmark::State& state, const SurfaceSize& size)
{
  const BenchmarkSurface* surface = surfaceOrFail(state, size);
  if (!surface)
  {
    return;
  }
  std::size_t computed = 0;
  for (auto _ : state)
  {
    kerf::SurfaceDescriptors descriptors = kerf::computeSurfaceDescriptors(surface->mesh);
    benchmark::DoNotOptimize(descriptors.meanCurvature.data());
    computed = descriptors.meanCurvature.size();
  }
  if (computed != static_cast<std::size_t>(surface->mesh.vertexCount()))
  {
    Fail(state, "kerf::computeSurfaceDescriptors returned the wrong number of values");
  }
  setCounters(state, *surface, size);
}

void coreMeshBuildAndValidation(benchmark::State& state, const SurfaceSize& size)
{
  const BenchmarkSurface* surface = surfaceOrFail(state, size);
  if (!surface)
  {
    return;
  }
  kerf::MeshReport report;
  for (auto _ : state)
  {
    // The constructor takes its vectors by value; copying them is not part of the build.
    state.PauseTiming();
    std::vector<kerf::Vector3> points = surface->mesh.points();
    std::vector<kerf::Triangle> triangles = surface->mesh.triangles();
    state.ResumeTiming();
    const kerf::TriangleMesh mesh(std::move(points), std::move(triangles));
    report = kerf::inspectMesh(mesh);
    benchmark::DoNotOptimize(report);
  }
  // A closed torus: no boundary, one component, Euler characteristic 0, no defects.
  const bool clean = report.faces == surface->mesh.faceCount() && report.boundaryEdges == 0 && report.components == 1 &&
    report.eulerCharacteristic == 0 && kerf::describeProblems(report, kerf::MeshRequirements()).empty();
  if (!clean)
  {
    Fail(state, "unexpected mesh report: " + report.summary());
  }
  setCounters(state, *surface, size);
}

} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterSurfaceDescriptorsBenchmarks(bool useSizeMinimumTimes)
{
  using Function = void (*)(benchmark::State&, const SurfaceSize&);
  const std::pair<const char*, Function> benchmarks[] = {
    { "BM_SurfaceDescriptorsFilter", surfaceDescriptorsFilter },
    { "BM_VTKCurvaturesMean", vtkCurvaturesMean },
    { "BM_CoreSurfaceDescriptors", coreSurfaceDescriptors },
    { "BM_CoreMeshBuildAndValidation", coreMeshBuildAndValidation },
  };
  for (const SurfaceSize& size : Sizes)
  {
    for (const auto& [name, function] : benchmarks)
    {
      const std::string fullName = std::string(name) + "/" + size.label;
      benchmark::internal::Benchmark* registered = benchmark::RegisterBenchmark(fullName.c_str(), function, size);
      registered->Unit(benchmark::kMillisecond)->UseRealTime();
      if (useSizeMinimumTimes)
      {
        registered->MinTime(size.minimumSeconds);
      }
    }
  }
}

} // namespace benchmarks
} // namespace kerf
