// Benchmarks of the harmonic-cut solver at the Core level: factorizations, low-rank routes, and cuts from stroke to
// labels.
//
// Every benchmark runs on HarmonicCutBenchmark.cxx's cube dumbbells (22,188, 99,372 and
// 1,002,252 triangles), cotangent weights and strokes: a closed stroke around the neck (64
// constraints) alternating with a shifted, tilted one, and a half-loop refinement stroke (64 more,
// at iso-value 0.25) alternating with its mirror image. For each size, in this order, and for
// each soft-constraint formulation (leastSquares, pointValues):
//   BM_SolverFirstCut/<size>/<formulation>   a cut on a fresh mesh, every Core step: TriangleMesh
//                                            from points and triangles, inspectMesh, cotangent
//                                            weights, closest-point locator and vertex normals,
//                                            strokeConstraints, HarmonicFieldSolver::solve
//                                            (factorization included), extractIsolines at 0,
//                                            nearestIsoline to the stroke, labelCuts
//   BM_SolverFirstCut/<size>/automatic       the same with the formulation the filters take by
//                                            default (kerf::automaticFormulation, chosen inside
//                                            the timed loop; counter pointValues 1 when it takes
//                                            point values)
//   BM_SolverFirstCutAMD/<size>/<formulation>  the same with the factorization ordered by AMD at
//                                            every size (the solver's geometric nested
//                                            dissection from GeometricOrderingRows rows, from
//                                            GeometricOrderingRowsSquared for least squares)
//   BM_SolverNewCut/<size>/<formulation>     a new stroke on the factored mesh, stroke to labels
//                                            (work: update)
//   BM_SolverRefinement/<size>/<formulation> a refinement stroke appended to the first stroke's
//                                            constraints, stroke to labels at 0.25 (work: update)
// then, on SparseCholesky directly:
//   BM_SolverFactorization/<size>/<matrix>/<ordering>
//                                            SparseCholesky::factor of the solver's matrices:
//                                            squared (L_F^T L_F, least squares) and laplacian
//                                            (L_FF), with AMD and METIS
//   BM_SolverNewStroke/<size>/<matrix>/<ordering>
//                                            on that factor: prepare() for a new stroke's 64
//                                            columns, then apply()
//   BM_SolverRefinementStroke/<size>/<matrix>/<ordering>
//                                            prepare() for the 64 stroke columns and 64 new
//                                            refinement columns (the stroke's kept)
//   BM_LowRank<route>/<size>/<matrix>/<k>    prepare() of k = 64 or 128 constraint columns with
//                                            each route (Sweep, CholmodSolve2, CholmodSpsolve) on
//                                            one factor (AMD), the Gram matrix included
//   BM_Apply/<size>/<matrix>                 apply() for 64 columns: Y s and one backward solve
//   BM_SolveOne/<size>/<matrix>/<route>      one right-hand side on that factor: solve() (route
//                                            kerf, Kerf's supernodal kernels) or solveColumns()
//                                            with one column (route cholmod, CHOLMOD's solve
//                                            with the BLAS)
//   BM_SolveThree/<size>/<matrix>/<route>    three right-hand sides (x, y and z, as Geometry Seam
//                                            Carving solves them): solveBlock() (route kerf, one
//                                            sweep with Kerf's kernels) or solveColumns() (route
//                                            cholmod)
//   BM_SupernodalFactorization/<size>/<matrix>/<route>
//                                            the numeric factorization by CHOLMOD (route cholmod,
//                                            with its BLAS) or by Kerf's driver with Eigen's
//                                            kernels for the processor (route kerf), with the
//                                            solver's ordering for the size, computed once
//   BM_LocatorBuild/<size>                   kerf::ClosestPointLocator on the surface, then the
//                                            closest points of the stroke's 9 points
// The scene of a size (mesh, weights, strokes, factors) is built once, outside the timed loops.
#include "BenchmarkMeshes.h"
#include "KerfBenchmarks.h"

#include "Error.h"
#include "Geometry/ClosestPoint.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/Isolines.h"
#include "Harmonic/StrokeConstraints.h"
#include "Mesh/MeshValidation.h"
#include "Numerics/LaplacianWeights.h"
#include "Numerics/NestedDissection.h"
#include "Numerics/SparseCholesky.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{

using kerf::benchmarks::Fail;
using Cholesky = kerf::SparseCholesky;

constexpr double RefinementValue = 0.25;

struct SolverSize
{
  const char* label;
  int cells;
};

// 12 * 43^2 = 22,188; 12 * 91^2 = 99,372; 12 * 289^2 = 1,002,252 triangles.
const std::array<SolverSize, 3> Sizes = { { { "22k", 43 }, { "100k", 91 }, { "1M", 289 } } };

/// What a cut needs from its surface, built once per surface.
struct SurfaceData
{
  kerf::TriangleMesh mesh;
  std::vector<double> weights;
  double meanDiagonal = 1.0;
  std::unique_ptr<kerf::ClosestPointLocator> locator;
  std::vector<kerf::Vector3> normals;
};

void prepareSurface(SurfaceData& surface)
{
  const kerf::MeshReport report = kerf::inspectMesh(surface.mesh);
  const std::string problems = kerf::describeProblems(report, kerf::MeshRequirements());
  if (!problems.empty())
  {
    throw kerf::Error(problems);
  }
  surface.weights = kerf::computeLaplacianWeights(surface.mesh, kerf::LaplacianWeightOptions());
  surface.meanDiagonal = kerf::laplacianMeanDiagonal(surface.mesh, surface.weights);
  surface.locator = std::make_unique<kerf::ClosestPointLocator>(surface.mesh);
  surface.normals = kerf::computeVertexNormals(surface.mesh);
}

/// The constraints of strokes drawn at `isoValue`, with the defaults of vtkStrokeConstraints
/// (offset 1%, projection limit 5% of the diagonal) and vtkHarmonicField (weight 1 relative to
/// the mean diagonal).
std::vector<kerf::SoftConstraint> constraintsOf(
  const SurfaceData& surface, const std::vector<kerf::Vector3>& stroke, double isoValue)
{
  kerf::StrokeOptions options;
  options.offset = 0.01 * surface.mesh.boundingBoxDiagonal();
  options.maximumDistance = 0.05 * surface.mesh.boundingBoxDiagonal();
  options.isoValue = isoValue;
  return kerf::strokeConstraints(surface.mesh, *surface.locator, surface.normals, { stroke }, options).constraints;
}

/// A cut from the constraints to the labels: the solve, the isoline at `value` nearest to the
/// stroke, and the faces' labels. Returns the number of segments (0 if there is no isoline).
int cutToLabels(kerf::HarmonicFieldSolver& solver, const SurfaceData& surface,
  const kerf::FieldConstraints& constraints, const std::vector<kerf::Vector3>& stroke, double value,
  kerf::HarmonicFieldSolution& solution)
{
  solution = solver.solve(surface.mesh, surface.weights, constraints);
  const std::vector<kerf::Isoline> isolines = kerf::extractIsolines(surface.mesh, solution.field, value);
  const int nearest = kerf::nearestIsoline(isolines, stroke);
  if (nearest < 0)
  {
    return 0;
  }
  const std::vector<int> labels = kerf::labelCuts(
    surface.mesh, { kerf::FieldCut{ &solution.field, value, { &isolines[static_cast<std::size_t>(nearest)] } } });
  return 1 + *std::max_element(labels.begin(), labels.end());
}

kerf::FieldConstraints fieldConstraints(
  const SurfaceData& surface, std::vector<kerf::SoftConstraint> soft, kerf::SoftConstraintFormulation formulation)
{
  kerf::FieldConstraints constraints;
  constraints.soft = std::move(soft);
  constraints.softWeight = surface.meanDiagonal;
  constraints.formulation = formulation;
  return constraints;
}

/// The matrices the solver factors for soft constraints on one connected surface without hard
/// values (vertex 0 pinned), and constraint columns as it builds them.
struct SolverMatrices
{
  Eigen::SparseMatrix<double> squared;   ///< L_F^T L_F, F all vertices but the pin
  Eigen::SparseMatrix<double> laplacian; ///< L_FF
  std::vector<int> column;               ///< vertex -> column, -1 for the pin
};

SolverMatrices solverMatrices(const SurfaceData& surface)
{
  const kerf::TriangleMesh& mesh = surface.mesh;
  SolverMatrices matrices;
  const Eigen::SparseMatrix<double> laplacian = kerf::assembleLaplacian(mesh, surface.weights);
  const int n = mesh.vertexCount();
  matrices.column.assign(n, -1);
  for (int v = 1; v < n; ++v)
  {
    matrices.column[v] = v - 1;
  }
  const Eigen::SparseMatrix<double> rows = laplacian.rightCols(n - 1);
  matrices.squared = Eigen::SparseMatrix<double>(rows.transpose()) * rows;
  matrices.squared.makeCompressed();
  matrices.laplacian = laplacian.bottomRightCorner(n - 1, n - 1);
  matrices.laplacian.makeCompressed();
  return matrices;
}

/// w C_F^T: one column per constraint, its barycentric weights on the free corners.
Eigen::SparseMatrix<double> constraintColumns(
  const SurfaceData& surface, const std::vector<int>& column, const std::vector<kerf::SoftConstraint>& soft)
{
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t i = 0; i < soft.size(); ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const int c = column[surface.mesh.triangle(soft[i].face)[j]];
      if (c >= 0 && soft[i].barycentric[j] != 0.0)
      {
        entries.emplace_back(c, static_cast<int>(i), surface.meanDiagonal * soft[i].barycentric[j]);
      }
    }
  }
  Eigen::SparseMatrix<double> u(
    static_cast<Eigen::Index>(surface.mesh.vertexCount() - 1), static_cast<Eigen::Index>(soft.size()));
  u.setFromTriplets(entries.begin(), entries.end());
  u.makeCompressed();
  return u;
}

std::vector<kerf::SoftConstraint> joined(
  std::vector<kerf::SoftConstraint> a, const std::vector<kerf::SoftConstraint>& b)
{
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// Everything one size's benchmarks share.
struct SolverScene
{
  const SolverSize* size = nullptr;
  std::vector<kerf::Vector3> points;
  std::vector<kerf::Triangle> triangles;
  SurfaceData surface;
  std::array<std::vector<kerf::Vector3>, 2> strokes;     ///< around the neck
  std::array<std::vector<kerf::Vector3>, 2> refinements; ///< half loops near the cut
  std::array<std::vector<kerf::SoftConstraint>, 2> strokeConstraints;
  std::array<std::vector<kerf::SoftConstraint>, 2> refinementConstraints;
  /// Solvers factored for strokes[0], one per formulation.
  std::map<kerf::SoftConstraintFormulation, std::unique_ptr<kerf::HarmonicFieldSolver>> solvers;
  std::unique_ptr<SolverMatrices> matrices;
  /// Factors of the solver's matrices: key "<matrix>/<ordering>".
  std::map<std::string, std::unique_ptr<Cholesky>> factors;
};

std::unique_ptr<SolverScene> buildScene(const SolverSize& size)
{
  auto scene = std::make_unique<SolverScene>();
  scene->size = &size;
  const kerf::TriangleMesh mesh = kerf::benchmarks::MakeBenchmarkDumbbell(size.cells);
  scene->points = mesh.points();
  scene->triangles = mesh.triangles();
  scene->surface.mesh = mesh;
  prepareSurface(scene->surface);
  const kerf::benchmarks::DumbbellStrokes strokes = kerf::benchmarks::MakeDumbbellStrokes();
  scene->strokes = strokes.around;
  scene->refinements = strokes.refinement;
  for (int i = 0; i < 2; ++i)
  {
    scene->strokeConstraints[i] = constraintsOf(scene->surface, scene->strokes[i], 0.0);
    scene->refinementConstraints[i] = constraintsOf(scene->surface, scene->refinements[i], RefinementValue);
  }
  return scene;
}

SolverScene& sceneOfSize(const SolverSize& size)
{
  static std::unique_ptr<SolverScene> scene;
  if (!scene || scene->size != &size)
  {
    scene.reset();
    scene = buildScene(size);
  }
  return *scene;
}

void setCounters(benchmark::State& state, const SolverScene& scene)
{
  state.counters["triangles"] = static_cast<double>(scene.triangles.size());
  state.counters["vertices"] = static_cast<double>(scene.points.size());
}

// ---------------------------------------------------------------------------------------------
// Cuts from stroke to labels.

using Formulation = kerf::SoftConstraintFormulation;

void firstCut(
  benchmark::State& state, SolverScene& scene, Formulation formulation, bool alwaysAMD = false, bool automatic = false)
{
  int segments = 0;
  kerf::HarmonicFieldSolution solution;
  for (auto _ : state)
  {
    SurfaceData surface;
    surface.mesh = kerf::TriangleMesh(scene.points, scene.triangles);
    if (automatic)
    {
      formulation = kerf::automaticFormulation(surface.mesh);
    }
    prepareSurface(surface);
    kerf::HarmonicFieldSolver solver;
    if (alwaysAMD)
    {
      solver.setGeometricOrderingRows(std::numeric_limits<int>::max());
    }
    const kerf::FieldConstraints constraints =
      fieldConstraints(surface, constraintsOf(surface, scene.strokes[0], 0.0), formulation);
    segments = cutToLabels(solver, surface, constraints, scene.strokes[0], 0.0, solution);
  }
  if (segments != 2 || solution.work != kerf::HarmonicFieldSolution::Work::Factorization)
  {
    Fail(state, "the first cut gave " + std::to_string(segments) + " segments");
  }
  state.counters["residual"] = solution.relativeResidual;
  if (automatic)
  {
    state.counters["pointValues"] = formulation == Formulation::PointValues ? 1.0 : 0.0;
  }
}

kerf::HarmonicFieldSolver& strokeSolver(SolverScene& scene, Formulation formulation)
{
  std::unique_ptr<kerf::HarmonicFieldSolver>& solver = scene.solvers[formulation];
  if (!solver)
  {
    solver = std::make_unique<kerf::HarmonicFieldSolver>();
    solver->solve(scene.surface.mesh, scene.surface.weights,
      fieldConstraints(scene.surface, scene.strokeConstraints[0], formulation));
  }
  return *solver;
}

// Times cuts alternating between two strokes (`refine`: refinement strokes appended to
// strokes[0]); each must cost an update and split the surface in two.
void alternateCuts(benchmark::State& state, SolverScene& scene, Formulation formulation, bool refine)
{
  kerf::HarmonicFieldSolver& solver = strokeSolver(scene, formulation);
  const SurfaceData& surface = scene.surface;
  const auto& strokes = refine ? scene.refinements : scene.strokes;
  const double value = refine ? RefinementValue : 0.0;
  // Start from the other stroke, so that the first timed cut is a new one too.
  solver.solve(surface.mesh, surface.weights,
    fieldConstraints(surface,
      refine ? joined(scene.strokeConstraints[0], scene.refinementConstraints[1]) : scene.strokeConstraints[1],
      formulation));
  bool updated = true;
  int segments = 2;
  std::size_t which = 0;
  kerf::HarmonicFieldSolution solution;
  for (auto _ : state)
  {
    std::vector<kerf::SoftConstraint> soft = constraintsOf(surface, strokes[which], value);
    if (refine)
    {
      soft = joined(scene.strokeConstraints[0], soft);
    }
    const int cut = cutToLabels(
      solver, surface, fieldConstraints(surface, std::move(soft), formulation), strokes[which], value, solution);
    segments = std::min(segments, cut);
    updated = updated && solution.work == kerf::HarmonicFieldSolution::Work::Update;
    which = 1 - which;
  }
  if (!updated || segments != 2)
  {
    Fail(state,
      std::string(updated ? "" : "a cut cost more than an update; ") + "fewest segments " + std::to_string(segments));
  }
  state.counters["residual"] = solution.relativeResidual;
}

const char* formulationName(Formulation formulation)
{
  switch (formulation)
  {
    case Formulation::LeastSquares:
      return "leastSquares";
    case Formulation::PointValues:
      return "pointValues";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------
// The factorizations and the low-rank routes.

enum class Matrix
{
  Squared,
  Laplacian
};

const char* matrixName(Matrix matrix)
{
  return matrix == Matrix::Squared ? "squared" : "laplacian";
}

const char* orderingName(Cholesky::Ordering ordering)
{
  return ordering == Cholesky::Ordering::AMD ? "AMD" : "METIS";
}

const Eigen::SparseMatrix<double>& matrixOf(SolverScene& scene, Matrix matrix)
{
  if (!scene.matrices)
  {
    scene.matrices = std::make_unique<SolverMatrices>(solverMatrices(scene.surface));
  }
  return matrix == Matrix::Squared ? scene.matrices->squared : scene.matrices->laplacian;
}

Cholesky& factorOf(SolverScene& scene, Matrix matrix, Cholesky::Ordering ordering)
{
  std::unique_ptr<Cholesky>& factor = scene.factors[std::string(matrixName(matrix)) + "/" + orderingName(ordering)];
  if (!factor)
  {
    factor = std::make_unique<Cholesky>();
    if (!factor->factor(matrixOf(scene, matrix), ordering))
    {
      throw kerf::Error("the matrix could not be factored");
    }
  }
  return *factor;
}

void factorization(benchmark::State& state, SolverScene& scene, Matrix matrix, Cholesky::Ordering ordering)
{
  const Eigen::SparseMatrix<double>& a = matrixOf(scene, matrix);
  std::unique_ptr<Cholesky>& kept = scene.factors[std::string(matrixName(matrix)) + "/" + orderingName(ordering)];
  bool factored = true;
  for (auto _ : state)
  {
    auto factor = std::make_unique<Cholesky>();
    factored = factored && factor->factor(a, ordering);
    kept = std::move(factor);
  }
  if (!factored)
  {
    Fail(state, "the matrix could not be factored");
  }
  state.counters["factorNonZeros"] = static_cast<double>(kept->factorNonZeros());
}

// The factorization with the solver's ordering for the size (geometric nested dissection from
// GeometricOrderingRows rows for the Laplacian and GeometricOrderingRowsSquared for the squared
// Laplacian, else AMD), computed once outside the loop, by one numeric route.
void supernodalFactorization(benchmark::State& state, SolverScene& scene, Matrix matrix, kerf::SupernodalRoute route)
{
  const Eigen::SparseMatrix<double>& a = matrixOf(scene, matrix);
  std::vector<int> permutation;
  if (a.rows() >= (matrix == Matrix::Squared ? kerf::GeometricOrderingRowsSquared : kerf::GeometricOrderingRows))
  {
    // The free rows are the vertices but the first (solverMatrices).
    const std::vector<kerf::Vector3>& points = scene.surface.mesh.points();
    permutation = kerf::geometricNestedDissection(std::vector<kerf::Vector3>(points.begin() + 1, points.end()), a);
  }
  else
  {
    Cholesky amd;
    if (!amd.factor(a, Cholesky::Ordering::AMD))
    {
      Fail(state, "the matrix could not be factored");
      return;
    }
    permutation = amd.permutation();
  }
  bool factored = true;
  Eigen::VectorXd x;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 1.0);
  std::size_t nonZeros = 0;
  for (auto _ : state)
  {
    Cholesky factor;
    factor.setSupernodalRoute(route);
    factored = factored && factor.factor(a, permutation);
    state.PauseTiming();
    x = factor.solve(b);
    nonZeros = factor.factorNonZeros();
    state.ResumeTiming();
  }
  const Eigen::SparseMatrix<double> full = a.selfadjointView<Eigen::Lower>();
  const double residual = (full * x - b).norm() / b.norm();
  if (!factored || !(residual < 1e-6))
  {
    Fail(state, "the factorization failed or its solve is off by " + std::to_string(residual));
  }
  state.counters["factorNonZeros"] = static_cast<double>(nonZeros);
  state.counters["residual"] = residual;
  state.counters["route"] =
    static_cast<double>(route == kerf::SupernodalRoute::Automatic ? kerf::automaticSupernodalRoute() : route);
}

// Relative error of apply(prepare(U), s) against U's columns solved one by one with solve().
double checkAgainstSolve(const Cholesky& factor, const Eigen::SparseMatrix<double>& u, const Cholesky::LowRank& lowRank)
{
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(u.cols(), -1.0, 1.0);
  const Eigen::VectorXd reference = factor.solve(u * s);
  return (factor.apply(lowRank, s) - reference).norm() / reference.norm();
}

// prepare() alternating between two sets of columns that share `kept` leading ones.
void alternatePrepare(benchmark::State& state, const Cholesky& factor,
  const std::array<Eigen::SparseMatrix<double>, 2>& u, Cholesky::LowRankRoute route, bool apply)
{
  std::size_t which = 0;
  Cholesky::LowRank lowRank = factor.prepare(u[1], route);
  const Eigen::VectorXd s = Eigen::VectorXd::Ones(u[0].cols());
  for (auto _ : state)
  {
    lowRank = factor.prepare(u[which], route);
    if (apply)
    {
      benchmark::DoNotOptimize(factor.apply(lowRank, s).data());
    }
    which = 1 - which;
  }
  const double error = checkAgainstSolve(factor, u[1 - which], lowRank);
  if (!(error < 1e-8))
  {
    Fail(state, "apply() differs from solve() by " + std::to_string(error));
  }
  state.counters["columns"] = static_cast<double>(u[0].cols());
  state.counters["reachRows"] = static_cast<double>(lowRank.reachRows);
  state.counters["gramProducts"] = static_cast<double>(lowRank.gramProducts);
}

void newStroke(benchmark::State& state, SolverScene& scene, Matrix matrix, Cholesky::Ordering ordering)
{
  const Cholesky& factor = factorOf(scene, matrix, ordering);
  const std::vector<int>& column = scene.matrices->column;
  const std::array<Eigen::SparseMatrix<double>, 2> u = { { constraintColumns(
                                                             scene.surface, column, scene.strokeConstraints[0]),
    constraintColumns(scene.surface, column, scene.strokeConstraints[1]) } };
  alternatePrepare(state, factor, u, Cholesky::LowRankRoute::SupernodalSweep, true);
}

void refinementStroke(benchmark::State& state, SolverScene& scene, Matrix matrix, Cholesky::Ordering ordering)
{
  const Cholesky& factor = factorOf(scene, matrix, ordering);
  const std::vector<int>& column = scene.matrices->column;
  std::array<Eigen::SparseMatrix<double>, 2> u;
  for (int i = 0; i < 2; ++i)
  {
    u[i] = constraintColumns(scene.surface, column, joined(scene.strokeConstraints[0], scene.refinementConstraints[i]));
  }
  alternatePrepare(state, factor, u, Cholesky::LowRankRoute::SupernodalSweep, true);
}

void lowRankRoute(benchmark::State& state, SolverScene& scene, Matrix matrix, int k, Cholesky::LowRankRoute route)
{
  const Cholesky& factor = factorOf(scene, matrix, Cholesky::Ordering::AMD);
  const std::vector<int>& column = scene.matrices->column;
  std::array<Eigen::SparseMatrix<double>, 2> u;
  for (int i = 0; i < 2; ++i)
  {
    const std::vector<kerf::SoftConstraint>& stroke = scene.strokeConstraints[i];
    u[i] = constraintColumns(scene.surface, column, k == 64 ? stroke : joined(stroke, scene.refinementConstraints[i]));
  }
  if (route == Cholesky::LowRankRoute::CholmodSolve2)
  {
    factor.prepare(u[0], route); // the simplicial copy, made once per factorization
  }
  alternatePrepare(state, factor, u, route, false);
}

void locatorBuild(benchmark::State& state, SolverScene& scene)
{
  double distance = 0.0;
  for (auto _ : state)
  {
    const kerf::ClosestPointLocator locator(scene.surface.mesh);
    distance = 0.0;
    for (const kerf::Vector3& point : scene.strokes[0])
    {
      distance += locator.closest(point).distance;
    }
    benchmark::DoNotOptimize(distance);
  }
  state.counters["distance"] = distance;
}

void solveOne(benchmark::State& state, SolverScene& scene, Matrix matrix, bool library)
{
  const Cholesky& factor = factorOf(scene, matrix, Cholesky::Ordering::AMD);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(factor.permutation().size(), -1.0, 1.0);
  Eigen::VectorXd x;
  for (auto _ : state)
  {
    x = library ? Eigen::VectorXd(factor.solveColumns(b)) : factor.solve(b);
    benchmark::DoNotOptimize(x.data());
  }
  const Eigen::VectorXd other = library ? factor.solve(b) : Eigen::VectorXd(factor.solveColumns(b));
  const double difference = (x - other).norm() / other.norm();
  if (!(difference < 1e-12))
  {
    Fail(state, "the two solves differ by " + std::to_string(difference));
  }
}

void solveThree(benchmark::State& state, SolverScene& scene, Matrix matrix, bool library)
{
  const Cholesky& factor = factorOf(scene, matrix, Cholesky::Ordering::AMD);
  const Eigen::Index n = static_cast<Eigen::Index>(factor.permutation().size());
  Eigen::MatrixXd b(n, 3);
  b.col(0) = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  b.col(1) = Eigen::VectorXd::LinSpaced(n, 2.0, -3.0);
  b.col(2) = b.col(0).cwiseProduct(b.col(1));
  Eigen::MatrixXd x;
  for (auto _ : state)
  {
    x = library ? factor.solveColumns(b) : factor.solveBlock(b);
    benchmark::DoNotOptimize(x.data());
  }
  const Eigen::MatrixXd other = library ? factor.solveBlock(b) : factor.solveColumns(b);
  const double difference = (x - other).norm() / other.norm();
  if (!(difference < 1e-12))
  {
    Fail(state, "the two solves differ by " + std::to_string(difference));
  }
}

void applyLowRank(benchmark::State& state, SolverScene& scene, Matrix matrix)
{
  const Cholesky& factor = factorOf(scene, matrix, Cholesky::Ordering::AMD);
  const Eigen::SparseMatrix<double> u =
    constraintColumns(scene.surface, scene.matrices->column, scene.strokeConstraints[0]);
  const Cholesky::LowRank lowRank = factor.prepare(u);
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(u.cols(), -1.0, 1.0);
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(factor.apply(lowRank, s).data());
  }
  const double error = checkAgainstSolve(factor, u, lowRank);
  if (!(error < 1e-8))
  {
    Fail(state, "apply() differs from solve() by " + std::to_string(error));
  }
}

template <typename Function>
void run(benchmark::State& state, const SolverSize* size, Function function)
{
  kerf::benchmarks::RunOnScene(
    state, [size]() -> SolverScene& { return sceneOfSize(*size); }, function, setCounters);
}

template <typename Function>
void add(const std::string& name, const SolverSize& size, Function function)
{
  benchmark::RegisterBenchmark(
    name.c_str(), [&size, function](benchmark::State& state) { run(state, &size, function); })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
}

} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterHarmonicSolverBenchmarks()
{
  const Matrix matrices[] = { Matrix::Squared, Matrix::Laplacian };
  const Cholesky::Ordering orderings[] = { Cholesky::Ordering::AMD, Cholesky::Ordering::METIS };
  const std::pair<const char*, Cholesky::LowRankRoute> routes[] = {
    { "Sweep", Cholesky::LowRankRoute::SupernodalSweep },
    { "CholmodSolve2", Cholesky::LowRankRoute::CholmodSolve2 },
    { "CholmodSpsolve", Cholesky::LowRankRoute::CholmodSpsolve },
  };
  for (const SolverSize& size : Sizes)
  {
    const std::string label = std::string("/") + size.label;
    for (Formulation formulation : { Formulation::LeastSquares, Formulation::PointValues })
    {
      const std::string suffix = label + "/" + formulationName(formulation);
      add("BM_SolverFirstCut" + suffix, size,
        [formulation](benchmark::State& state, SolverScene& scene) { firstCut(state, scene, formulation); });
      add("BM_SolverFirstCutAMD" + suffix, size,
        [formulation](benchmark::State& state, SolverScene& scene) { firstCut(state, scene, formulation, true); });
      add("BM_SolverNewCut" + suffix, size, [formulation](benchmark::State& state, SolverScene& scene) {
        alternateCuts(state, scene, formulation, false);
      });
      add("BM_SolverRefinement" + suffix, size,
        [formulation](benchmark::State& state, SolverScene& scene) { alternateCuts(state, scene, formulation, true); });
    }
    add("BM_SolverFirstCut" + label + "/automatic", size, [](benchmark::State& state, SolverScene& scene) {
      firstCut(state, scene, Formulation::LeastSquares, false, true);
    });
    add("BM_LocatorBuild" + label, size, locatorBuild);
    for (Matrix matrix : matrices)
    {
      for (Cholesky::Ordering ordering : orderings)
      {
        const std::string suffix = label + "/" + matrixName(matrix) + "/" + orderingName(ordering);
        add("BM_SolverFactorization" + suffix, size, [matrix, ordering](benchmark::State& state, SolverScene& scene) {
          factorization(state, scene, matrix, ordering);
        });
        add("BM_SolverNewStroke" + suffix, size, [matrix, ordering](benchmark::State& state, SolverScene& scene) {
          newStroke(state, scene, matrix, ordering);
        });
        add(
          "BM_SolverRefinementStroke" + suffix, size, [matrix, ordering](benchmark::State& state, SolverScene& scene) {
            refinementStroke(state, scene, matrix, ordering);
          });
      }
      for (int k : { 64, 128 })
      {
        for (const auto& [name, route] : routes)
        {
          const Cholesky::LowRankRoute r = route;
          add(std::string("BM_LowRank") + name + label + "/" + matrixName(matrix) + "/" + std::to_string(k), size,
            [matrix, k, r](benchmark::State& state, SolverScene& scene) { lowRankRoute(state, scene, matrix, k, r); });
        }
      }
      // The squared matrix (least squares) is the default on coarse meshes only, and measured at
      // 22k and 100k; at 1M its solve is too ill-conditioned for the residual check.
      for (kerf::SupernodalRoute route : { kerf::SupernodalRoute::CHOLMOD, kerf::SupernodalRoute::Automatic })
      {
        if (matrix == Matrix::Squared && std::string(size.label) == "1M")
        {
          continue;
        }
        add(std::string("BM_SupernodalFactorization") + label + "/" + matrixName(matrix) +
            (route == kerf::SupernodalRoute::CHOLMOD ? "/cholmod" : "/kerf"),
          size, [matrix, route](benchmark::State& state, SolverScene& scene) {
            supernodalFactorization(state, scene, matrix, route);
          });
      }
      add(std::string("BM_Apply") + label + "/" + matrixName(matrix), size,
        [matrix](benchmark::State& state, SolverScene& scene) { applyLowRank(state, scene, matrix); });
      for (bool library : { false, true })
      {
        add(std::string("BM_SolveOne") + label + "/" + matrixName(matrix) + (library ? "/cholmod" : "/kerf"), size,
          [matrix, library](benchmark::State& state, SolverScene& scene) { solveOne(state, scene, matrix, library); });
        add(std::string("BM_SolveThree") + label + "/" + matrixName(matrix) + (library ? "/cholmod" : "/kerf"), size,
          [matrix, library](
            benchmark::State& state, SolverScene& scene) { solveThree(state, scene, matrix, library); });
      }
    }
  }
}

} // namespace benchmarks
} // namespace kerf
