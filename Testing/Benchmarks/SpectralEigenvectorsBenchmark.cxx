// Benchmarks of the spectral segmentation's leading eigenvectors: Kerf's tridiagonal route, its Lanczos route and
// Spectra's solvers alone, on the affinities the segmentation builds.
//
// Each matrix is kerf::spectralAffinity on kerf::spectralPatches with the segmentation's defaults
// (400 patches, so 400 x 400 on every mesh above 400 faces), built once outside the timed loops;
// k is the segment count the psb-dev runner asks for:
//   /psb125    psb-dev model 125 (2,682 triangles, k = 5), the benchmark's smallest
//   /psb297    psb-dev model 297 (30,626 triangles, k = 13), its largest
//   /22k       the cube dumbbell of 22,188 triangles (k = 6)
//   /100k      the cube dumbbell of 99,372 triangles (k = 6)
//   /100k-1000 the same with PatchCount 1000: a 1000 x 1000 matrix
// (the psb-dev ones only when KERF_SHARED_DATA_DIR/psb-dev exists). Families:
//   BM_LeadingEigenvectorsTridiagonal/<case>  kerf::tridiagonalLeadingEigenvectors (Householder
//                                         tridiagonalization, inverse iteration): the reference
//   BM_LeadingEigenvectors/<case>         kerf::leadingEigenvectors (Spectra's SymEigsSolver to
//                                         1e-12, checked), what the segmentation calls
//   BM_LeadingEigenvectorsSpectra/<case>  Spectra::SymEigsSolver alone on the dense product, the
//                                         k largest algebraic eigenvalues, tolerance 1e-10
//   BM_LeadingEigenvectorsSpectraShift/<case>  Spectra::SymEigsShiftSolver (dense LDLT of
//                                         N - sigma I, sigma = 1.001 above N's largest eigenvalue 1)
// Each result but the reference is checked against it: the same eigenvalues to 1e-9 and the same
// invariant subspace (the projectors' difference below 1e-6); the counters give both differences
// and the gap after the k-th eigenvalue.
#include "BenchmarkMeshes.h"
#include "KerfBenchmarks.h"

#include "IO/MeshFormats.h"
#include "Mesh/SurfaceConversion.h"
#include "Segmentation/FaceGraph.h"
#include "Segmentation/SpectralSegmentation.h"

#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>

#include <Spectra/MatOp/DenseSymMatProd.h>
#include <Spectra/MatOp/DenseSymShiftSolve.h>
#include <Spectra/SymEigsShiftSolver.h>
#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace
{

struct AffinityCase
{
  const char* label;
  int psbModel; // 0: the dumbbell of `cells`
  int cells;
  int patchCount;
  int k;
};

const AffinityCase Cases[] = {
  { "psb125", 125, 0, 400, 5 },
  { "psb297", 297, 0, 400, 13 },
  { "22k", 0, 43, 400, 6 },
  { "100k", 0, 91, 400, 6 },
  { "100k-1000", 0, 91, 1000, 6 },
};

const std::string PsbDirectory = std::string(KERF_SHARED_DATA_DIR) + "/psb-dev";

struct AffinityScene
{
  int triangles = 0;
  int k = 0;
  Eigen::MatrixXd affinity;
  // The tridiagonal route's result, which the other solvers are checked against.
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};

const AffinityScene& sceneOf(const AffinityCase& c)
{
  static std::map<std::string, std::unique_ptr<AffinityScene>> scenes;
  std::unique_ptr<AffinityScene>& scene = scenes[c.label];
  if (!scene)
  {
    const kerf::TriangleMesh mesh = c.psbModel > 0
      ? kerf::convertPolygons(kerf::readOFF(PsbDirectory + "/off/" + std::to_string(c.psbModel) + ".off")).mesh
      : kerf::benchmarks::MakeBenchmarkDumbbell(c.cells);
    const kerf::FaceGraph graph(mesh);
    kerf::SpectralSegmentationOptions options;
    options.patchCount = c.patchCount;
    auto built = std::make_unique<AffinityScene>();
    built->triangles = mesh.faceCount();
    built->k = c.k;
    std::vector<double> area;
    built->affinity = kerf::spectralAffinity(graph, kerf::spectralPatches(graph, options), options, area);
    built->vectors = kerf::tridiagonalLeadingEigenvectors(built->affinity, c.k, built->values);
    scene = std::move(built);
  }
  return *scene;
}

void setCounters(benchmark::State& state, const AffinityScene& scene)
{
  state.counters["triangles"] = scene.triangles;
  state.counters["n"] = static_cast<double>(scene.affinity.rows());
  state.counters["k"] = scene.k;
}

// `values` and `vectors` in ascending order, as Kerf gives them.
void checkAgainstReference(
  benchmark::State& state, const AffinityScene& scene, const Eigen::VectorXd& values, const Eigen::MatrixXd& vectors)
{
  const double valueError = (values - scene.values).cwiseAbs().maxCoeff();
  const double subspaceError = (vectors * vectors.transpose() - scene.vectors * scene.vectors.transpose()).norm();
  const Eigen::VectorXd all =
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scene.affinity, Eigen::EigenvaluesOnly).eigenvalues();
  state.counters["value_error"] = valueError;
  state.counters["subspace_error"] = subspaceError;
  state.counters["gap"] = all[all.size() - scene.k] - all[all.size() - scene.k - 1];
  if (!(valueError <= 1e-9) || !(subspaceError <= 1e-6))
  {
    kerf::benchmarks::Fail(state,
      "the eigenpairs differ from the tridiagonal route's: eigenvalues by " + std::to_string(valueError) +
        ", subspace by " + std::to_string(subspaceError));
  }
}

int subspaceSize(const AffinityScene& scene)
{
  return std::min<int>(static_cast<int>(scene.affinity.rows()), std::max(2 * scene.k + 1, 20));
}

// Runs a built solver to the tolerance and keeps its eigenpairs; false (the benchmark failed) if
// it did not converge.
template <typename Solver>
bool solveAndKeep(
  benchmark::State& state, Solver& solver, Spectra::SortRule rule, Eigen::VectorXd& values, Eigen::MatrixXd& vectors)
{
  solver.init();
  solver.compute(rule, 1000, 1e-10);
  if (solver.info() != Spectra::CompInfo::Successful)
  {
    kerf::benchmarks::Fail(state, "Spectra's eigensolver did not converge");
    return false;
  }
  values = solver.eigenvalues();
  vectors = solver.eigenvectors();
  state.counters["products"] = static_cast<double>(solver.num_operations());
  return true;
}

// kerf::tridiagonalLeadingEigenvectors or kerf::leadingEigenvectors.
void kerfBenchmark(benchmark::State& state, const AffinityCase* c, bool tridiagonal)
{
  kerf::benchmarks::RunOnScene(
    state, [c]() -> const AffinityScene& { return sceneOf(*c); },
    [tridiagonal](benchmark::State& s, const AffinityScene& scene) {
      Eigen::VectorXd values;
      Eigen::MatrixXd vectors;
      for (auto _ : s)
      {
        vectors = tridiagonal ? kerf::tridiagonalLeadingEigenvectors(scene.affinity, scene.k, values)
                              : kerf::leadingEigenvectors(scene.affinity, scene.k, values);
      }
      if (!tridiagonal)
      {
        checkAgainstReference(s, scene, values, vectors);
      }
    },
    setCounters);
}

void tridiagonalBenchmark(benchmark::State& state, const AffinityCase* c)
{
  kerfBenchmark(state, c, true);
}

void leadingBenchmark(benchmark::State& state, const AffinityCase* c)
{
  kerfBenchmark(state, c, false);
}

void spectraBenchmark(benchmark::State& state, const AffinityCase* c)
{
  kerf::benchmarks::RunOnScene(
    state, [c]() -> const AffinityScene& { return sceneOf(*c); },
    [](benchmark::State& s, const AffinityScene& scene) {
      Spectra::DenseSymMatProd<double> product(scene.affinity);
      Eigen::VectorXd values;
      Eigen::MatrixXd vectors;
      for (auto _ : s)
      {
        Spectra::SymEigsSolver<Spectra::DenseSymMatProd<double>> solver(product, scene.k, subspaceSize(scene));
        if (!solveAndKeep(s, solver, Spectra::SortRule::LargestAlge, values, vectors))
        {
          return;
        }
      }
      // Spectra returns the largest first.
      checkAgainstReference(s, scene, values.reverse(), vectors.rowwise().reverse());
    },
    setCounters);
}

void spectraShiftBenchmark(benchmark::State& state, const AffinityCase* c)
{
  kerf::benchmarks::RunOnScene(
    state, [c]() -> const AffinityScene& { return sceneOf(*c); },
    [](benchmark::State& s, const AffinityScene& scene) {
      Eigen::VectorXd values;
      Eigen::MatrixXd vectors;
      for (auto _ : s)
      {
        // The factorization of N - sigma I is part of the cost, so the operator is built each time.
        Spectra::DenseSymShiftSolve<double> shiftSolve(scene.affinity);
        Spectra::SymEigsShiftSolver<Spectra::DenseSymShiftSolve<double>> solver(
          shiftSolve, scene.k, subspaceSize(scene), 1.001);
        if (!solveAndKeep(s, solver, Spectra::SortRule::LargestMagn, values, vectors))
        {
          return;
        }
      }
      // Spectra returns the largest first.
      checkAgainstReference(s, scene, values.reverse(), vectors.rowwise().reverse());
    },
    setCounters);
}
} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterSpectralEigenvectorsBenchmarks(bool useSizeMinimumTimes)
{
  const bool psb = std::filesystem::is_directory(PsbDirectory + "/off");
  using Function = void (*)(benchmark::State&, const AffinityCase*);
  const std::pair<const char*, Function> families[] = {
    { "BM_LeadingEigenvectorsTridiagonal/", tridiagonalBenchmark },
    { "BM_LeadingEigenvectors/", leadingBenchmark },
    { "BM_LeadingEigenvectorsSpectra/", spectraBenchmark },
    { "BM_LeadingEigenvectorsSpectraShift/", spectraShiftBenchmark },
  };
  // Interleaved by case, so that the solvers of one matrix run side by side.
  for (const AffinityCase& c : Cases)
  {
    if (c.psbModel > 0 && !psb)
    {
      continue;
    }
    for (const auto& [family, function] : families)
    {
      benchmark::internal::Benchmark* registered =
        benchmark::RegisterBenchmark((std::string(family) + c.label).c_str(), function, &c);
      registered->Unit(benchmark::kMillisecond)->UseRealTime();
      if (useSizeMinimumTimes)
      {
        registered->MinTime(0.5);
      }
    }
  }
}

} // namespace benchmarks
} // namespace kerf
