// The KerfBenchmarks program: registers every benchmark family and runs the selected ones.
//
// Families, each in its own file (see there for what is measured):
//   SurfaceDescriptorsBenchmark.cxx     descriptors filter, vtkCurvatures, Core steps (/10k /100k /1M)
//   HarmonicCutBenchmark.cxx            harmonic cuts from strokes: factorization, solve, isolines,
//                                       scoring, the filter pipeline (/22k /100k /1M)
//   HarmonicSolverBenchmark.cxx         the solver at the Core level: cuts from stroke to labels,
//                                       orderings, low-rank routes (/22k /100k /1M)
//   SegmentationEvaluationBenchmark.cxx segmentation metrics (/50k) and the human baseline over
//                                       psb-dev (/1model /all; only when the folder exists)
//   MeshReaderBenchmark.cxx             reading each file format, Kerf beside VTK (/10k /100k /1M)
//   SpectralEigenvectorsBenchmark.cxx   the spectral segmentation's leading eigenvectors, Kerf beside
//                                       Spectra (/psb125 /psb297 /22k /100k /100k-1000)
// Run from the build directory with OPENBLAS_NUM_THREADS=1 (CHOLMOD's BLAS on one thread, like
// everything else), for example:
//   bin/KerfBenchmarks
//   bin/KerfBenchmarks --benchmark_filter=/100k --benchmark_format=json
// and the full run (one command; about 20 minutes, most of it the 1M factorizations, which run
// once per repetition; under 7 GB of memory):
//   bin/KerfBenchmarks --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//     --benchmark_min_time=0.2
// Each size has its own minimum time (longer for larger sizes, so that they run several
// iterations); --benchmark_min_time=<seconds> replaces it for every benchmark. The exit code is
// 1 if a benchmark failed (a filter error, a wrong result), which the ctest smoke test uses.
#include "KerfBenchmarks.h"

#include "Numerics/SparseCholesky.h"
#include "Threads.h"

#include <vtkSMPTools.h>
#include <vtkVersion.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>

namespace
{
bool Failed = false;
} // namespace

namespace kerf
{
namespace benchmarks
{

void Fail(benchmark::State& state, const std::string& message)
{
  Failed = true;
  state.SkipWithError(message.c_str());
}

ThreadsFor::ThreadsFor(bool hardware)
{
  kerf::setThreadLimit(hardware ? kerf::hardwareThreads() : 1);
}

ThreadsFor::~ThreadsFor()
{
  kerf::setThreadLimit(1);
}

bool AnyBenchmarkFailed()
{
  return Failed;
}

} // namespace benchmarks
} // namespace kerf

int main(int argc, char** argv)
{
  // A per-benchmark MinTime overrides the flag, so the sizes' own times apply only without it.
  bool minimumTimeGiven = false;
  for (int i = 1; i < argc; ++i)
  {
    minimumTimeGiven = minimumTimeGiven || std::strncmp(argv[i], "--benchmark_min_time", 20) == 0;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return 1;
  }
  benchmark::AddCustomContext("vtk_version", vtkVersion::GetVTKVersionFull());
  benchmark::AddCustomContext("vtk_smp_backend", vtkSMPTools::GetBackend());
  benchmark::AddCustomContext("sparse_cholesky", kerf::SparseCholesky::backend());
  // One thread, whatever KERF_NUM_THREADS says, so that the figures compare run to run; the
  // benchmarks named *-threads set the hardware's cores for their own run.
  kerf::setThreadLimit(1);
  benchmark::AddCustomContext(
    "kerf_threads", "1 (the *-threads benchmarks: " + std::to_string(kerf::hardwareThreads()) + ")");
  // The processor's model, for the benchmark log (Utilities/benchmark-log.py): the same core
  // count and clock can be an Intel Xeon or an AMD EPYC, with or without AVX-512.
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
  {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
    {
      benchmark::AddCustomContext("cpu_model", line.substr(line.find(':') + 2));
      break;
    }
  }
  kerf::benchmarks::RegisterSurfaceDescriptorsBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterHarmonicCutBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterHarmonicSolverBenchmarks();
  kerf::benchmarks::RegisterSegmentationEvaluationBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterMeshReaderBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterGeodesicsBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterGeometrySeamsBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterCurveExportBenchmarks();
  kerf::benchmarks::RegisterChartParameterizationBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterEasyMeshCuttingBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterAutomaticSegmentationBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterSpectralEigenvectorsBenchmarks(!minimumTimeGiven);
  kerf::benchmarks::RegisterSketchBenchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return kerf::benchmarks::AnyBenchmarkFailed() ? 1 : 0;
}
