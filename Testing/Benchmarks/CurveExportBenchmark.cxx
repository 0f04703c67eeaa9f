// Benchmarks of the curve export operators (scissor, snap, inverse snap) with 10 isolines on a dumbbell.
//
// The surface is the benchmarks' cube dumbbell (kerf::benchmarks::MakeBenchmarkDumbbell) with
// 22,188, 99,372 and 1,002,252 triangles; the curves are the 10 isolines of the height z at evenly spaced
// levels between the caps (closed loops around the axis), extracted once per size outside the
// timed loops. For each size:
//   BM_CoreExtractTenIsolines/<size>   kerf::extractIsolines at the 10 levels, for reference (the
//                                      cost of making the curves the operators export)
//   BM_CurveExportScissor/<size>       kerf::exportCurves, Scissor
//   BM_CurveExportSnap/<size>          kerf::exportCurves, Snap
//   BM_CurveExportInverseSnap/<size>   kerf::exportCurves, InverseSnap
// Each export checks that the 10 loops give 11 charts; the counters report the output mesh's triangles.
#include "BenchmarkMeshes.h"
#include "KerfBenchmarks.h"

#include "Export/CurveExport.h"
#include "Harmonic/Isolines.h"

#include <array>
#include <memory>
#include <string>

namespace
{

struct ExportSize
{
  const char* name;
  int cells;
};
const std::array<ExportSize, 3> Sizes = { { { "22k", 43 }, { "100k", 91 }, { "1M", 289 } } };
constexpr int CurveCount = 10;

struct ExportScene
{
  const ExportSize* size = nullptr;
  kerf::TriangleMesh mesh;
  std::vector<double> height;
  std::vector<double> levels;
  std::vector<kerf::SurfaceCurve> curves;
};

std::unique_ptr<ExportScene> Current;

ExportScene& sceneFor(const ExportSize& size)
{
  if (!Current || Current->size != &size)
  {
    Current.reset();
    auto scene = std::make_unique<ExportScene>();
    scene->size = &size;
    scene->mesh = kerf::benchmarks::MakeBenchmarkDumbbell(size.cells);
    for (const kerf::Vector3& p : scene->mesh.points())
    {
      scene->height.push_back(p.z());
    }
    // Levels strictly inside (-0.9, 0.9) of the half length, off the vertices' rings.
    for (int i = 0; i < CurveCount; ++i)
    {
      scene->levels.push_back(kerf::benchmarks::DumbbellHalfLength * (-0.9 + 1.8 * (i + 0.5) / CurveCount) + 1e-4);
    }
    for (double level : scene->levels)
    {
      for (const kerf::Isoline& isoline : kerf::extractIsolines(scene->mesh, scene->height, level))
      {
        scene->curves.push_back(kerf::SurfaceCurve{ isoline.points, isoline.faces, isoline.closed });
      }
    }
    if (static_cast<int>(scene->curves.size()) != CurveCount)
    {
      throw std::runtime_error("expected 10 isolines, got " + std::to_string(scene->curves.size()));
    }
    Current = std::move(scene);
  }
  return *Current;
}

void runExport(benchmark::State& state, const ExportSize* size, kerf::CurveExportMode mode)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> ExportScene& { return sceneFor(*size); },
    [&](benchmark::State& s, ExportScene& scene) {
      kerf::CurveExportOptions options;
      options.mode = mode;
      int charts = 0, triangles = 0;
      for (auto _ : s)
      {
        const kerf::CurveExportResult result = kerf::exportCurves(scene.mesh, scene.curves, options);
        charts = result.chartCount;
        triangles = kerf::exportedMesh(result, scene.mesh).faceCount();
        benchmark::DoNotOptimize(result.charts.data());
      }
      if (charts != CurveCount + 1)
      {
        kerf::benchmarks::Fail(s, "the 10 loops gave " + std::to_string(charts) + " charts instead of 11");
      }
      s.counters["outputTriangles"] = triangles;
    },
    [](benchmark::State& s, ExportScene& scene) {
      s.counters["triangles"] = scene.mesh.faceCount();
      std::size_t points = 0;
      for (const auto& curve : scene.curves)
      {
        points += curve.points.size();
      }
      s.counters["curvePoints"] = static_cast<double>(points);
    });
}

void runIsolines(benchmark::State& state, const ExportSize* size)
{
  kerf::benchmarks::RunOnScene(
    state, [&]() -> ExportScene& { return sceneFor(*size); },
    [&](benchmark::State& s, ExportScene& scene) {
      for (auto _ : s)
      {
        for (double level : scene.levels)
        {
          benchmark::DoNotOptimize(kerf::extractIsolines(scene.mesh, scene.height, level).size());
        }
      }
    },
    [](benchmark::State& s, ExportScene& scene) { s.counters["triangles"] = scene.mesh.faceCount(); });
}

} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterCurveExportBenchmarks()
{
  for (const ExportSize& size : Sizes)
  {
    const std::string suffix = std::string("/") + size.name;
    benchmark::RegisterBenchmark(("BM_CoreExtractTenIsolines" + suffix).c_str(), runIsolines, &size)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
    const std::array<std::pair<const char*, CurveExportMode>, 3> modes = { {
      { "BM_CurveExportScissor", CurveExportMode::Scissor },
      { "BM_CurveExportSnap", CurveExportMode::Snap },
      { "BM_CurveExportInverseSnap", CurveExportMode::InverseSnap },
    } };
    for (const auto& mode : modes)
    {
      benchmark::RegisterBenchmark((mode.first + suffix).c_str(), runExport, &size, mode.second)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    }
  }
}

} // namespace benchmarks
} // namespace kerf
