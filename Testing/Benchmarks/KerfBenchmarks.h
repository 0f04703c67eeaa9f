// What the files of the KerfBenchmarks program share: failure reporting and each family's registration.
#pragma once

#include <benchmark/benchmark.h>

#include <string>

namespace kerf
{
namespace benchmarks
{

/// Skips the benchmark with `message` and makes the program exit with 1 (the smoke test's check).
void Fail(benchmark::State& state, const std::string& message);

/// True once any benchmark has called Fail.
bool AnyBenchmarkFailed();

/// Register one family each, in the order they run. With `useSizeMinimumTimes`, each size gets
/// its own minimum time; without it, --benchmark_min_time applies to all.
void RegisterSurfaceDescriptorsBenchmarks(bool useSizeMinimumTimes);
void RegisterHarmonicCutBenchmarks(bool useSizeMinimumTimes);
void RegisterSegmentationEvaluationBenchmarks(bool useSizeMinimumTimes);
void RegisterGeodesicsBenchmarks(bool useSizeMinimumTimes);

} // namespace benchmarks
} // namespace kerf
