// Benchmarks of Easy Mesh Cutting's region growing and snake refinement, beside VTK's edge-connectivity labelling.
//
// The surface is the benchmarks' cube dumbbell (kerf::benchmarks::MakeBenchmarkDumbbell) with
// about 10k, 40k, 100k and 1M vertices (the sizes of Ji et al. 2006, Table 1: 0.172 s at 10k and
// 0.656 s at 40,706 vertices for the growing, on a 3 GHz Pentium IV). The strokes are one vertex
// at each end of the dumbbell (labels 0 and 1); the descriptors and the isophotic edge lengths are
// computed once per size outside the timed loops, as the filter caches them on its surface.
//   BM_RegionGrowing/<size>          kerf::growFromSeeds: every vertex labelled by its nearest
//                                    stroke under the metric (the growing the goals name)
//   BM_GrowingWithCuts/<size>        the growing with cut placement (band 0.3), as
//                                    kerf::growRegions runs it: kerf::nearestTwoLabels, then
//                                    kerf::placeCuts
//   BM_GrowingWithRandomWalks/<size> kerf::growRegions with its defaults on a surface whose
//                                    caches are filled: stroke snapping, the growing, the random
//                                    walks on the cached concavity-aware weights (one
//                                    factorization, two solves) and the cut through their band
//   BM_RandomWalksWithoutCut/<size>  the same with CutBand 0: the walks' boundary as it is
//   BM_RegionGrowingFirstRun/<size>  kerf::growRegions on a new surface: descriptors, metric,
//                                    stroke snapping, growing, the random walks and their cut (up to 100k)
//   BM_VTKEdgeConnectivity/<size>    vtkPolyDataEdgeConnectivityFilter labelling all regions of
//                                    the same mesh with the grown boundary's edges as barriers
//                                    (the same two regions): the reference for labelling speed
//   BM_SnakeRefinement/<size>        kerf::BoundarySnake of the grown labels, refined with the
//                                    default options (up to 100k)
// Each checks its result: two labels covering every vertex, two VTK regions, a converged snake.
#include "BenchmarkMeshes.h"
#include "BenchmarkPolyData.h"
#include "KerfBenchmarks.h"

#include "Segmentation/IsophoticMetric.h"
#include "Segmentation/RegionGrowing.h"
#include "Segmentation/SnakeRefinement.h"
#include "Surface/Surface.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataEdgeConnectivityFilter.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <memory>
#include <string>

namespace
{

struct GrowingSize
{
  const char* name;
  int cells;  ///< 6 cells^2 + 2 vertices
  bool small; ///< the first-run and snake cases run at this size
  double minimumSeconds;
};
const std::array<GrowingSize, 4> Sizes = { {
  { "10k", 41, true, 0.5 },
  { "40k", 82, true, 0.5 },
  { "100k", 129, true, 1.0 },
  { "1M", 408, false, 2.0 },
} };

struct GrowingScene
{
  const GrowingSize* size = nullptr;
  std::shared_ptr<kerf::Surface> surface;
  std::vector<double> edgeLengths;
  kerf::StrokeSeeds seeds;
  std::vector<kerf::LabelledStroke> strokes;
  std::vector<int> faceLabels;
  vtkSmartPointer<vtkPolyData> polyData;
  vtkSmartPointer<vtkPolyData> barriers;
};

std::unique_ptr<GrowingScene> Current;

GrowingScene& sceneFor(const GrowingSize& size)
{
  if (!Current || Current->size != &size)
  {
    Current.reset();
    auto scene = std::make_unique<GrowingScene>();
    scene->size = &size;
    scene->surface = std::make_shared<kerf::Surface>(kerf::benchmarks::MakeBenchmarkDumbbell(size.cells));
    const kerf::TriangleMesh& mesh = scene->surface->mesh();
    scene->edgeLengths = kerf::surfaceIsophoticEdgeLengths(*scene->surface, kerf::IsophoticMetricOptions());
    const auto byHeight = [&](int a, int b) { return mesh.point(a).z() < mesh.point(b).z(); };
    std::vector<int> vertices(static_cast<std::size_t>(mesh.vertexCount()));
    for (int v = 0; v < mesh.vertexCount(); ++v)
    {
      vertices[static_cast<std::size_t>(v)] = v;
    }
    const int bottom = *std::min_element(vertices.begin(), vertices.end(), byHeight);
    const int top = *std::max_element(vertices.begin(), vertices.end(), byHeight);
    scene->seeds.vertices = { bottom, top };
    scene->seeds.labels = { 0, 1 };
    scene->strokes = { { 0, { mesh.point(bottom) } }, { 1, { mesh.point(top) } } };
    std::vector<int> labels;
    std::vector<double> distances;
    kerf::growFromSeeds(mesh, scene->edgeLengths, scene->seeds, labels, distances);
    scene->faceLabels = kerf::faceLabelsFromVertices(mesh, labels, distances);
    // VTK's barriers: the edges between faces of the two grown labels.
    scene->polyData = kerf::benchmarks::MakePolyData(mesh);
    scene->barriers = vtkSmartPointer<vtkPolyData>::New();
    scene->barriers->SetPoints(scene->polyData->GetPoints());
    vtkNew<vtkCellArray> lines;
    for (int e = 0; e < mesh.edgeCount(); ++e)
    {
      const std::array<int, 2>& faces = mesh.edgeFaces(e);
      if (faces[1] >= 0 &&
        scene->faceLabels[static_cast<std::size_t>(faces[0])] != scene->faceLabels[static_cast<std::size_t>(faces[1])])
      {
        const vtkIdType ids[2] = { mesh.edgeVertices(e)[0], mesh.edgeVertices(e)[1] };
        lines->InsertNextCell(2, ids);
      }
    }
    scene->barriers->SetLines(lines);
    Current = std::move(scene);
  }
  return *Current;
}

void checkTwoLabels(benchmark::State& state, const std::vector<int>& labels)
{
  const bool both = std::find(labels.begin(), labels.end(), 0) != labels.end() &&
    std::find(labels.begin(), labels.end(), 1) != labels.end();
  if (!both || std::find(labels.begin(), labels.end(), -1) != labels.end())
  {
    kerf::benchmarks::Fail(state, "the growing did not label every vertex with one of the two strokes' labels");
  }
}

void growing(benchmark::State& state, GrowingScene& scene)
{
  std::vector<int> labels;
  std::vector<double> distances;
  for (auto _ : state)
  {
    kerf::growFromSeeds(scene.surface->mesh(), scene.edgeLengths, scene.seeds, labels, distances);
    benchmark::DoNotOptimize(labels.data());
  }
  checkTwoLabels(state, labels);
}

void growingWithCuts(benchmark::State& state, GrowingScene& scene)
{
  const kerf::TriangleMesh& mesh = scene.surface->mesh();
  std::vector<int> labels;
  std::vector<double> distances;
  for (auto _ : state)
  {
    const kerf::NearestLabels nearest = kerf::nearestTwoLabels(mesh, scene.edgeLengths, scene.seeds);
    labels.assign(static_cast<std::size_t>(mesh.vertexCount()), -1);
    for (int v = 0; v < mesh.vertexCount(); ++v)
    {
      labels[v] = nearest.first[v] >= 0 ? nearest.labels[nearest.first[v]] : -1;
    }
    distances = nearest.firstDistance;
    kerf::placeCuts(mesh, nearest, kerf::CutPlacementOptions(), labels, distances);
    benchmark::DoNotOptimize(labels.data());
  }
  checkTwoLabels(state, labels);
}

// kerf::growRegions with random walks on a surface whose caches (descriptors, metric lengths, the
// walks' weights) are filled before the timed loop, as a filter's surface keeps them between
// updates; `band` 0 leaves out the cut through the walks' band.
void timeRandomWalks(benchmark::State& state, GrowingScene& scene, double band)
{
  kerf::RegionGrowingOptions options;
  options.cutPlacement.band = band;
  kerf::RegionGrowingResult result = kerf::growRegions(*scene.surface, scene.strokes, options);
  for (auto _ : state)
  {
    result = kerf::growRegions(*scene.surface, scene.strokes, options);
    benchmark::DoNotOptimize(result.vertexLabels.data());
  }
  checkTwoLabels(state, result.vertexLabels);
}

void growingWithRandomWalks(benchmark::State& state, GrowingScene& scene)
{
  timeRandomWalks(state, scene, kerf::CutPlacementOptions().band);
}

void randomWalksWithoutCut(benchmark::State& state, GrowingScene& scene)
{
  timeRandomWalks(state, scene, 0.0);
}

void firstRun(benchmark::State& state, GrowingScene& scene)
{
  kerf::RegionGrowingResult result;
  for (auto _ : state)
  {
    state.PauseTiming();
    auto fresh = std::make_shared<kerf::Surface>(scene.surface->mesh());
    state.ResumeTiming();
    result = kerf::growRegions(*fresh, scene.strokes, kerf::RegionGrowingOptions());
    state.PauseTiming();
    fresh.reset(); // freed outside the timed part
    state.ResumeTiming();
  }
  checkTwoLabels(state, result.vertexLabels);
}

void vtkEdgeConnectivity(benchmark::State& state, GrowingScene& scene)
{
  int regions = 0;
  for (auto _ : state)
  {
    vtkNew<vtkPolyDataEdgeConnectivityFilter> connectivity;
    connectivity->SetInputData(scene.polyData);
    connectivity->SetSourceData(scene.barriers);
    connectivity->BarrierEdgesOn();
    connectivity->SetExtractionModeToAllRegions();
    connectivity->ColorRegionsOn();
    connectivity->Update();
    regions = connectivity->GetNumberOfExtractedRegions();
    benchmark::DoNotOptimize(connectivity->GetOutput());
  }
  if (regions != 2)
  {
    kerf::benchmarks::Fail(
      state, "vtkPolyDataEdgeConnectivityFilter found " + std::to_string(regions) + " regions, not 2");
  }
}

void snakeRefinement(benchmark::State& state, GrowingScene& scene)
{
  kerf::SnakeStatistics statistics;
  for (auto _ : state)
  {
    kerf::BoundarySnake snake(scene.surface, scene.faceLabels);
    statistics = snake.refine(kerf::SnakeOptions());
    benchmark::DoNotOptimize(statistics.slides);
  }
  if (!statistics.converged)
  {
    kerf::benchmarks::Fail(state, "the snake did not converge");
  }
  state.counters["sweeps"] = statistics.sweeps;
  state.counters["slides"] = statistics.slides;
}

using Body = void (*)(benchmark::State&, GrowingScene&);

void run(benchmark::State& state, const GrowingSize* size, Body body)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> GrowingScene& { return sceneFor(*size); }, body,
    [](benchmark::State& s, GrowingScene& scene) {
      s.counters["vertices"] = scene.surface->mesh().vertexCount();
      s.counters["triangles"] = scene.surface->mesh().faceCount();
    });
}

} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterEasyMeshCuttingBenchmarks(bool useSizeMinimumTimes)
{
  const std::array<std::pair<const char*, Body>, 7> cases = { {
    { "BM_RegionGrowing", growing },
    { "BM_GrowingWithCuts", growingWithCuts },
    { "BM_GrowingWithRandomWalks", growingWithRandomWalks },
    { "BM_RandomWalksWithoutCut", randomWalksWithoutCut },
    { "BM_RegionGrowingFirstRun", firstRun },
    { "BM_VTKEdgeConnectivity", vtkEdgeConnectivity },
    { "BM_SnakeRefinement", snakeRefinement },
  } };
  for (const GrowingSize& size : Sizes)
  {
    for (const auto& [name, body] : cases)
    {
      if (!size.small && (body == firstRun || body == snakeRefinement))
      {
        continue;
      }
      benchmark::internal::Benchmark* registered =
        benchmark::RegisterBenchmark((std::string(name) + "/" + size.name).c_str(), run, &size, body);
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
