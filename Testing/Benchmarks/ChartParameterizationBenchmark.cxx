// Benchmarks of kerf::parameterizeCharts (split, LSCM or LinABF per chart, distortion, packing, overlap count) with
// each solver.
//
// The surfaces are the benchmarks' cube dumbbells (BenchmarkMeshes.h) of 22,188, 99,372 and
// 1,002,252 triangles (1M with the default solver only), cut into 12 charts: each of the six cube faces it is made from
// (2 cells^2 consecutive triangles, row by row) cut in two halves of rows, each a disk.
//   BM_ChartParameterization/<size>/<solver>   the whole of parameterizeCharts with LSCM, one
//                                               thread, with CHOLMOD or Eigen's SimplicialLDLT
//                                               (at 1M the complex forms only)
//   BM_ChartParameterization/<size>/LinABF     the same with LinABF (its angle system, then the
//                                               reconstruction with the default ComplexCHOLMOD)
//   BM_ChartSplit/<size>                       its first step alone: splitAlongFaceLabels into the
//                                               12 pieces (LabelFans::Separate)
//   BM_ChartSeams/<size>                       one closed chart, a sphere with five fingers
//                                               (kerf::makeProtrusions, 20,480 and 81,920
//                                               triangles): cut into a disk (cutToDisk), then up
//                                               to 10 seams added where the map is worst, each
//                                               followed by a new LSCM solve (ComplexCHOLMOD)
//   BM_ChartSeams/<size>/LinABF                the same with LinABF
// The reference is libigl's igl::lscm, about 475 ms at 100k triangles on this machine (not
// installed here, so not run beside).
#include "BenchmarkMeshes.h"
#include "KerfBenchmarks.h"

#include "Mesh/MeshGenerators.h"
#include "Mesh/SplitAlongFaceLabels.h"
#include "Parameterization/ChartParameterization.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace
{

struct ChartScene
{
  kerf::TriangleMesh mesh;
  std::vector<int> labels;
};

const ChartScene& chartScene(int cells)
{
  static std::map<int, ChartScene> scenes;
  auto found = scenes.find(cells);
  if (found == scenes.end())
  {
    ChartScene scene;
    scene.mesh = kerf::benchmarks::MakeBenchmarkDumbbell(cells);
    for (int f = 0; f < scene.mesh.faceCount(); ++f)
    {
      scene.labels.push_back(f / (cells * cells));
    }
    found = scenes.emplace(cells, std::move(scene)).first;
  }
  return found->second;
}

// FNV-1a (32 bits, exact as a counter) of the texture coordinates' bytes: equal checksums from two
// builds (--benchmark_format=json prints them whole) mean the same atlas, bit for bit.
double uvChecksum(const std::vector<kerf::Vector2>& uv)
{
  std::uint32_t hash = 2166136261u;
  for (const kerf::Vector2& p : uv)
  {
    unsigned char bytes[2 * sizeof(double)];
    std::memcpy(bytes, p.data(), sizeof bytes);
    for (unsigned char b : bytes)
    {
      hash = (hash ^ b) * 16777619u;
    }
  }
  return static_cast<double>(hash);
}

void chartParameterization(benchmark::State& state, int cells, kerf::ChartMethod method, kerf::ChartSolver solver)
{
  kerf::ChartParameterizationResult result;
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const ChartScene& { return chartScene(cells); },
    [&](benchmark::State& s, const ChartScene& scene) {
      kerf::ChartParameterizationOptions options;
      options.method = method;
      options.solver = solver;
      for (auto _ : s)
      {
        result = kerf::parameterizeCharts(scene.mesh, scene.labels, options);
        benchmark::DoNotOptimize(result.uv.data());
      }
      if (result.charts.size() != 12 || result.overlappingChartPairs != 0 || result.distortion.flippedFaces != 0)
      {
        kerf::benchmarks::Fail(s,
          "expected 12 charts without overlaps or flips, got " + std::to_string(result.charts.size()) + " charts, " +
            std::to_string(result.overlappingChartPairs) + " overlapping pairs, " +
            std::to_string(result.distortion.flippedFaces) + " flipped triangles");
      }
    },
    [&](benchmark::State& s, const ChartScene& scene) {
      s.counters["triangles"] = scene.mesh.faceCount();
      s.counters["charts"] = static_cast<double>(result.charts.size());
      s.counters["L2stretch"] = result.distortion.surfaceStretch;
      s.counters["meanShear"] = result.distortion.meanShear;
      s.counters["flipped"] = result.distortion.flippedFaces;
      s.counters["uvChecksum"] = uvChecksum(result.uv);
    });
}

// The first step of parameterizeCharts alone: the mesh cut open along the charts' borders.
void chartSplit(benchmark::State& state, int cells)
{
  kerf::SplitMesh split;
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const ChartScene& { return chartScene(cells); },
    [&](benchmark::State& s, const ChartScene& scene) {
      for (auto _ : s)
      {
        split = kerf::splitAlongFaceLabels(scene.mesh, scene.labels, kerf::LabelFans::Separate);
        benchmark::DoNotOptimize(split.mesh.triangles().data());
      }
      if (split.mesh.componentCount() != 12)
      {
        kerf::benchmarks::Fail(s, "expected 12 pieces, got " + std::to_string(split.mesh.componentCount()));
      }
    },
    [&](benchmark::State& s, const ChartScene& scene) {
      s.counters["triangles"] = scene.mesh.faceCount();
      s.counters["vertices"] = split.mesh.vertexCount();
    });
}

const kerf::TriangleMesh& fingers(int levels)
{
  static std::map<int, kerf::TriangleMesh> meshes;
  auto found = meshes.find(levels);
  if (found == meshes.end())
  {
    found = meshes.emplace(levels, kerf::makeProtrusions(5, 1.5, 0.25, levels)).first;
  }
  return found->second;
}

void chartSeams(benchmark::State& state, int levels, kerf::ChartMethod method)
{
  kerf::ChartParameterizationResult result;
  kerf::benchmarks::RunOnScene(
    state, [&]() -> const kerf::TriangleMesh& { return fingers(levels); },
    [&](benchmark::State& s, const kerf::TriangleMesh& mesh) {
      kerf::ChartParameterizationOptions options;
      options.method = method;
      options.maximumSeams = 10;
      const std::vector<int> labels(static_cast<std::size_t>(mesh.faceCount()), 0);
      for (auto _ : s)
      {
        result = kerf::parameterizeCharts(mesh, labels, options);
        benchmark::DoNotOptimize(result.uv.data());
      }
      if (result.cutCharts != 1 || result.charts.size() != 1 || result.overlappingChartPairs != 0)
      {
        kerf::benchmarks::Fail(s, "expected one chart cut into a disk, without overlaps");
      }
    },
    [&](benchmark::State& s, const kerf::TriangleMesh& mesh) {
      s.counters["triangles"] = mesh.faceCount();
      s.counters["seams"] = result.charts.empty() ? 0 : result.charts[0].seams;
      s.counters["uvChecksum"] = uvChecksum(result.uv);
      s.counters["L2stretch"] = result.distortion.surfaceStretch;
      s.counters["meanShear"] = result.distortion.meanShear;
      s.counters["flipped"] = result.distortion.flippedFaces;
    });
}

} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterChartParameterizationBenchmarks(bool useSizeMinimumTimes)
{
  const std::pair<const char*, int> sizes[] = { { "22k", 43 }, { "100k", 91 }, { "1M", 289 } };
  struct Variant
  {
    const char* name;
    ChartMethod method;
    ChartSolver solver;
  };
  const Variant variants[] = { { "ComplexCHOLMOD", ChartMethod::LSCM, ChartSolver::ComplexCHOLMOD },
    { "ComplexLDLT", ChartMethod::LSCM, ChartSolver::ComplexLDLT },
    { "RealCHOLMOD", ChartMethod::LSCM, ChartSolver::RealCHOLMOD },
    { "RealLDLT", ChartMethod::LSCM, ChartSolver::RealLDLT },
    { "LinABF", ChartMethod::LinABF, ChartSolver::ComplexCHOLMOD } };
  for (const auto& [label, cells] : sizes)
  {
    for (const Variant& variant : variants)
    {
      if (cells > 100 && variant.solver != ChartSolver::ComplexLDLT && variant.solver != ChartSolver::ComplexCHOLMOD)
      {
        continue; // at 1M the complex form only, with either method
      }
      const std::string name = std::string("BM_ChartParameterization/") + label + "/" + variant.name;
      benchmark::internal::Benchmark* registered =
        benchmark::RegisterBenchmark(name.c_str(), [cells = cells, variant](benchmark::State& state) {
          chartParameterization(state, cells, variant.method, variant.solver);
        });
      registered->Unit(benchmark::kMillisecond)->UseRealTime();
      if (useSizeMinimumTimes)
      {
        registered->MinTime(1.0);
      }
    }
  }
  for (const auto& [label, cells] : sizes)
  {
    const std::string name = std::string("BM_ChartSplit/") + label;
    benchmark::internal::Benchmark* registered = benchmark::RegisterBenchmark(
      name.c_str(), [cells = cells](benchmark::State& state) { chartSplit(state, cells); });
    registered->Unit(benchmark::kMillisecond)->UseRealTime();
    if (useSizeMinimumTimes)
    {
      registered->MinTime(1.0);
    }
  }
  for (const auto& [label, levels] :
    { std::pair<const char*, int>{ "20k", 5 }, std::pair<const char*, int>{ "82k", 6 } })
  {
    for (ChartMethod method : { ChartMethod::LSCM, ChartMethod::LinABF })
    {
      const std::string name = std::string("BM_ChartSeams/") + label + (method == ChartMethod::LinABF ? "/LinABF" : "");
      benchmark::internal::Benchmark* registered = benchmark::RegisterBenchmark(
        name.c_str(), [levels = levels, method](benchmark::State& state) { chartSeams(state, levels, method); });
      registered->Unit(benchmark::kMillisecond)->UseRealTime();
      if (useSizeMinimumTimes)
      {
        registered->MinTime(1.0);
      }
    }
  }
}

} // namespace benchmarks
} // namespace kerf
