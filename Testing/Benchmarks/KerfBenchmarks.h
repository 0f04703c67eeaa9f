// What the files of the KerfBenchmarks program share: failure reporting and each family's registration.
#pragma once

#include <benchmark/benchmark.h>

#include <exception>
#include <string>

namespace kerf
{
namespace benchmarks
{

/// Skips the benchmark with `message` and makes the program exit with 1 (the smoke test's check).
void Fail(benchmark::State& state, const std::string& message);

/// Kerf's thread limit for a benchmark's run: the hardware's cores with `hardware`, else 1; back to
/// 1 (the program's setting) at the end of the scope.
struct ThreadsFor
{
  explicit ThreadsFor(bool hardware);
  ~ThreadsFor();
  ThreadsFor(const ThreadsFor&) = delete;
  ThreadsFor& operator=(const ThreadsFor&) = delete;
};

/// True once any benchmark has called Fail.
bool AnyBenchmarkFailed();

/// Runs function(state, scene) on the scene getScene() returns (built on first use), then
/// setCounters(state, scene); an exception fails the benchmark with its message.
template <typename GetScene, typename Function, typename SetCounters>
void RunOnScene(benchmark::State& state, GetScene getScene, Function function, SetCounters setCounters)
{
  decltype(&getScene()) scene = nullptr;
  try
  {
    scene = &getScene();
    function(state, *scene);
  }
  catch (const std::exception& e)
  {
    Fail(state, e.what());
  }
  if (scene)
  {
    setCounters(state, *scene);
  }
}

/// Register one family each, in the order they run. With `useSizeMinimumTimes`, each size gets
/// its own minimum time; without it, --benchmark_min_time applies to all.
void RegisterSurfaceDescriptorsBenchmarks(bool useSizeMinimumTimes);
void RegisterHarmonicCutBenchmarks(bool useSizeMinimumTimes);
void RegisterHarmonicSolverBenchmarks();
void RegisterSegmentationEvaluationBenchmarks(bool useSizeMinimumTimes);
void RegisterMeshReaderBenchmarks(bool useSizeMinimumTimes);
void RegisterCurveExportBenchmarks();
void RegisterGeodesicsBenchmarks(bool useSizeMinimumTimes);
void RegisterGeometrySeamsBenchmarks(bool useSizeMinimumTimes);
void RegisterChartParameterizationBenchmarks(bool useSizeMinimumTimes);
void RegisterEasyMeshCuttingBenchmarks(bool useSizeMinimumTimes);
void RegisterAutomaticSegmentationBenchmarks(bool useSizeMinimumTimes);
void RegisterSpectralEigenvectorsBenchmarks(bool useSizeMinimumTimes);
void RegisterSketchBenchmarks();

} // namespace benchmarks
} // namespace kerf
