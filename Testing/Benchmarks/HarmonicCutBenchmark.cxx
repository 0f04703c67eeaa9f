// Benchmarks of harmonic cuts from strokes: factorization, solve, isolines, scoring and the filter pipeline.
//
// Every benchmark runs on a dumbbell with kerf::makeDumbbell's shape (half length 2.2, lobe radii
// 1 and 0.8, neck at 0.3 pinched by 0.65) built from a subdivided cube
// (kerf::benchmarks::MakeCubeDumbbell) with 22,188, 99,372 and 1,002,252 triangles, and
// cotangent weights. A stroke is a closed polyline of 9 points around the neck on the smooth surface (8
// segments, 64 soft constraints); where the stroke must change, a second one, shifted, tilted
// and turned, alternates with it. A refinement stroke is a half loop of 9 points near the cut.
// For each size, in this order:
//   BM_HarmonicFactorization/<size>          a new kerf::HarmonicFieldSolver solving with the
//                                            stroke's soft constraints: factorization of the
//                                            squared Laplacian, the constraints' low-rank
//                                            term, solve
//   BM_HarmonicDirichletFactorization/<size> a new solver with hard values 0 and 1 on the two
//                                            caps (a harmonic field: the Laplacian's factorization)
//   BM_HarmonicSolve/<size>                  the stroke's solver again with only the constraint
//                                            values changed (work: back-substitution)
//   BM_CoreExtractIsolines/<size>            kerf::extractIsolines at 0 on the stroke's field
//   BM_VTKContourFilter/<size>               vtkContourFilter, one value (0), on the same field as
//                                            point scalars, for reference
//   BM_CoreScoreIsovalues/<size>             kerf::scoreIsovalues, 50 candidates
//   BM_HarmonicCutNewStroke/<size>           a new stroke through vtkStrokeConstraints ->
//                                            vtkHarmonicField -> vtkIsolineCut (NEAR_STROKE)
//                                            on an unchanged mesh (SolverWork "update")
//   BM_HarmonicCutSliding/<size>             only vtkIsolineCut's IsoValue changes
//   BM_HarmonicCutRefinement/<size>          a new refinement stroke at the slid cut's value,
//                                            its constraints appended to the first stroke's
//                                            (SolverWork "update"), and its cut
//   BM_StrokeCutDrawnStroke/<size>           a new stroke drawn in Stroke Cut's panel (its
//                                            DrawnStrokePoints, what the sketch widget sets):
//                                            vtkStrokeCut alone, with its defaults (the automatic
//                                            formulation), the segments and the cut
// Each size's surface, weights and constraints are built once, outside the timed loops, and kept
// while that size runs, with the last solver of BM_HarmonicFactorization (BM_HarmonicSolve
// solves with it; the next three read its field) and the filter pipeline (its mesh conversion
// and factorization made once, before the first pipeline benchmark's loop).
#include "BenchmarkMeshes.h"
#include "BenchmarkPolyData.h"
#include "KerfBenchmarks.h"
#include "vtkHarmonicField.h"
#include "vtkIsolineCut.h"
#include "vtkStrokeConstraints.h"
#include "vtkStrokeCut.h"

#include "Geometry/ClosestPoint.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/Isolines.h"
#include "Harmonic/StrokeConstraints.h"
#include "Mesh/MeshGenerators.h"
#include "Numerics/FieldGradient.h"
#include "Numerics/LaplacianWeights.h"

#include <benchmark/benchmark.h>

#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkContourFilter.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace
{

using kerf::benchmarks::Fail;

using kerf::benchmarks::DumbbellHalfLength;
using Strokes = kerf::benchmarks::DumbbellStrokes;

// The iso-value the cut is slid to and back from; the refinement starts from a cut at SlidValue.
constexpr double SlidValue = 0.25;
constexpr double SlidBackValue = -0.25;

/// One benchmark size: a cube dumbbell with `cells` x `cells` squares per cube face.
struct CutSize
{
  const char* label;
  int cells;
  double minimumSeconds; ///< per-benchmark minimum time unless --benchmark_min_time is given
};

// 12 * 43^2 = 22,188; 12 * 91^2 = 99,372; 12 * 289^2 = 1,002,252 triangles.
const std::array<CutSize, 3> Sizes = { { { "22k", 43, 0.5 }, { "100k", 91, 1.0 }, { "1M", 289, 2.0 } } };

// One polyline through the points.
vtkSmartPointer<vtkPolyData> makePolyline(const std::vector<kerf::Vector3>& stroke)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> line;
  line->InsertNextCell(static_cast<vtkIdType>(stroke.size()));
  for (const kerf::Vector3& p : stroke)
  {
    line->InsertCellPoint(points->InsertNextPoint(p.data()));
  }
  auto polyline = vtkSmartPointer<vtkPolyData>::New();
  polyline->SetPoints(points);
  polyline->SetLines(line);
  return polyline;
}

/// The filters of a cut, connected once; the benchmarks switch the strokes' points and the
/// connections between a new cut and a refinement.
struct CutPipeline
{
  vtkNew<vtkPolyData> stroke; ///< its points switch between the two strokes around the neck
  std::array<vtkSmartPointer<vtkPoints>, 2> strokePoints;
  vtkNew<vtkPolyData> refinementStroke; ///< its points switch between the two half loops
  std::array<vtkSmartPointer<vtkPoints>, 2> refinementPoints;
  vtkNew<vtkStrokeConstraints> constraints;
  vtkNew<vtkStrokeConstraints> refinementConstraints;
  vtkNew<vtkAppendPolyData> bothStrokesConstraints;
  vtkNew<vtkHarmonicField> field;
  vtkNew<vtkIsolineCut> cut;

  CutPipeline(vtkPolyData* surface, const Strokes& strokes)
  {
    for (int i = 0; i < 2; ++i)
    {
      this->strokePoints[i] = makePolyline(strokes.around[i])->GetPoints();
      this->refinementPoints[i] = makePolyline(strokes.refinement[i])->GetPoints();
    }
    this->stroke->DeepCopy(makePolyline(strokes.around[0]));
    this->refinementStroke->DeepCopy(makePolyline(strokes.refinement[0]));
    this->constraints->SetInputData(0, surface);
    this->constraints->SetInputData(1, this->stroke);
    this->refinementConstraints->SetInputData(0, surface);
    this->refinementConstraints->SetInputData(1, this->refinementStroke);
    this->refinementConstraints->SetIsoValue(SlidValue);
    this->bothStrokesConstraints->AddInputConnection(this->constraints->GetOutputPort());
    this->bothStrokesConstraints->AddInputConnection(this->refinementConstraints->GetOutputPort());
    this->field->SetInputData(0, surface);
    this->field->SetWeightingToCotangent();
    this->cut->SetInputConnection(0, this->field->GetOutputPort());
    this->cut->SetModeToNearStroke();
  }

  /// stroke -> constraints -> field -> cut near the stroke at `value`.
  void ConnectCut(double value)
  {
    this->field->SetInputConnection(1, this->constraints->GetOutputPort());
    this->cut->SetInputData(1, this->stroke);
    this->cut->SetIsoValue(value);
  }

  /// (stroke, refinement stroke) -> appended constraints -> field -> cut near the refinement
  /// stroke at SlidValue.
  void ConnectRefinement()
  {
    this->field->SetInputConnection(1, this->bothStrokesConstraints->GetOutputPort());
    this->cut->SetInputData(1, this->refinementStroke);
    this->cut->SetIsoValue(SlidValue);
  }

  std::string SolverWork()
  {
    vtkAbstractArray* work = this->field->GetOutput()->GetFieldData()->GetAbstractArray("SolverWork");
    vtkStringArray* strings = vtkStringArray::SafeDownCast(work);
    return strings && strings->GetNumberOfValues() == 1 ? strings->GetValue(0) : "(none)";
  }

  /// Empty if the cut is one closed isoline splitting the surface in two, else what is wrong.
  std::string CheckCut()
  {
    vtkPolyData* lines = this->cut->GetOutput();
    vtkDataArray* closed = lines->GetCellData()->GetArray("Closed");
    if (lines->GetNumberOfCells() != 1 || !closed || closed->GetComponent(0, 0) != 1)
    {
      return "the cut is not one closed isoline (" + std::to_string(lines->GetNumberOfCells()) + " polylines)";
    }
    vtkDataArray* segments = this->cut->GetLabelledSurface()->GetCellData()->GetArray("Segment");
    if (!segments || segments->GetRange()[0] != 0 || segments->GetRange()[1] != 1)
    {
      return "the cut does not split the surface into 2 segments";
    }
    return "";
  }
};

/// Everything one size's benchmarks share.
struct HarmonicScene
{
  const CutSize* size = nullptr;
  kerf::TriangleMesh mesh;
  vtkSmartPointer<vtkPolyData> polyData;
  Strokes strokes;
  std::vector<double> weights;
  kerf::FieldConstraints strokeConstraints;  ///< soft, from strokes.around[0], values -1 and +1
  kerf::FieldConstraints shiftedConstraints; ///< the same points with values SlidValue -/+ 1
  kerf::FieldConstraints capConstraints;     ///< hard 0 and 1 on the caps
  /// Factored for strokeConstraints' locations (the last BM_HarmonicFactorization solver).
  std::unique_ptr<kerf::HarmonicFieldSolver> solver;
  std::vector<double> field; ///< the solution for strokeConstraints
  std::vector<double> gradientMagnitudes;
  std::unique_ptr<CutPipeline> pipeline;
};

std::unique_ptr<HarmonicScene> buildScene(const CutSize& size)
{
  auto scene = std::make_unique<HarmonicScene>();
  scene->size = &size;
  scene->mesh = kerf::benchmarks::MakeBenchmarkDumbbell(size.cells);
  scene->polyData = kerf::benchmarks::MakePolyData(scene->mesh);
  scene->strokes = kerf::benchmarks::MakeDumbbellStrokes();
  const kerf::TriangleMesh& mesh = scene->mesh;

  kerf::LaplacianWeightOptions weighting;
  weighting.weighting = kerf::LaplacianWeighting::Cotangent;
  scene->weights = kerf::computeLaplacianWeights(mesh, weighting);

  // The constraints vtkStrokeConstraints and vtkHarmonicField make with their defaults: offset
  // 1% and projection limit 5% of the diagonal, soft weight 1 relative to the mean diagonal of
  // the Laplacian.
  const kerf::ClosestPointLocator locator(mesh);
  kerf::StrokeOptions options;
  options.samplesPerSegment = 4;
  options.offset = 0.01 * mesh.boundingBoxDiagonal();
  options.maximumDistance = 0.05 * mesh.boundingBoxDiagonal();
  const kerf::StrokeConstraintSet set =
    kerf::strokeConstraints(mesh, locator, kerf::computeVertexNormals(mesh), { scene->strokes.around[0] }, options);
  double diagonalSum = 0.0;
  for (double w : scene->weights)
  {
    diagonalSum += 2.0 * w;
  }
  scene->strokeConstraints.soft = set.constraints;
  scene->strokeConstraints.softWeight = diagonalSum / mesh.vertexCount();
  scene->shiftedConstraints = scene->strokeConstraints;
  for (kerf::SoftConstraint& c : scene->shiftedConstraints.soft)
  {
    c.value += SlidValue;
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const double z = mesh.point(v).z();
    if (std::abs(z) > 0.9 * DumbbellHalfLength)
    {
      scene->capConstraints.dirichletVertices.push_back(v);
      scene->capConstraints.dirichletValues.push_back(z > 0.0 ? 1.0 : 0.0);
    }
  }
  return scene;
}

// The scene of one size, built on first use; the previous size's is freed first, so that a 1M
// run never holds two sizes' factorizations (the benchmarks run size by size).
HarmonicScene& sceneOfSize(const CutSize& size)
{
  static std::unique_ptr<HarmonicScene> scene;
  if (!scene || scene->size != &size)
  {
    scene.reset();
    scene = buildScene(size);
  }
  return *scene;
}

// The stroke's solver, factored if BM_HarmonicFactorization did not run.
kerf::HarmonicFieldSolver& strokeSolver(HarmonicScene& scene)
{
  if (!scene.solver)
  {
    auto solver = std::make_unique<kerf::HarmonicFieldSolver>();
    solver->solve(scene.mesh, scene.weights, scene.strokeConstraints);
    scene.solver = std::move(solver);
  }
  return *scene.solver;
}

const std::vector<double>& strokeField(HarmonicScene& scene)
{
  if (scene.field.empty())
  {
    scene.field = strokeSolver(scene).solve(scene.mesh, scene.weights, scene.strokeConstraints).field;
    for (const kerf::Vector3& g : kerf::computeFaceGradients(scene.mesh, scene.field))
    {
      scene.gradientMagnitudes.push_back(g.norm());
    }
  }
  return scene.field;
}

CutPipeline& pipelineOf(HarmonicScene& scene)
{
  if (!scene.pipeline)
  {
    scene.pipeline = std::make_unique<CutPipeline>(scene.polyData, scene.strokes);
  }
  return *scene.pipeline;
}

void setCounters(benchmark::State& state, const HarmonicScene& scene)
{
  state.counters["triangles"] = scene.mesh.faceCount();
  state.counters["vertices"] = scene.mesh.vertexCount();
  state.SetLabel("cube dumbbell " + std::to_string(scene.size->cells));
}

using Work = kerf::HarmonicFieldSolution::Work;

void harmonicFactorization(benchmark::State& state, HarmonicScene& scene)
{
  kerf::HarmonicFieldSolution solution;
  bool factoredEveryTime = true;
  for (auto _ : state)
  {
    auto solver = std::make_unique<kerf::HarmonicFieldSolver>();
    solution = solver->solve(scene.mesh, scene.weights, scene.strokeConstraints);
    factoredEveryTime = factoredEveryTime && solution.work == Work::Factorization;
    // Kept for the next benchmarks; the previous solver is freed here, as it would be at the end
    // of the iteration.
    scene.solver = std::move(solver);
  }
  const auto range = std::minmax_element(solution.field.begin(), solution.field.end());
  if (!factoredEveryTime)
  {
    Fail(state, "a new solver did not report a factorization");
  }
  else if (!(solution.relativeResidual < 1e-6) || !(*range.first < -0.5 && *range.second > 0.5))
  {
    Fail(state,
      "unexpected field: relative residual " + std::to_string(solution.relativeResidual) + ", range " +
        std::to_string(*range.first) + " to " + std::to_string(*range.second));
  }
}

void harmonicDirichletFactorization(benchmark::State& state, HarmonicScene& scene)
{
  kerf::HarmonicFieldSolution solution;
  bool factoredEveryTime = true;
  for (auto _ : state)
  {
    kerf::HarmonicFieldSolver solver;
    solution = solver.solve(scene.mesh, scene.weights, scene.capConstraints);
    factoredEveryTime = factoredEveryTime && solution.work == Work::Factorization;
  }
  // The maximum principle: a harmonic field with values 0 and 1 stays within [0, 1].
  const auto range = std::minmax_element(solution.field.begin(), solution.field.end());
  if (!factoredEveryTime)
  {
    Fail(state, "a new solver did not report a factorization");
  }
  else if (!(solution.relativeResidual < 1e-6) || *range.first < -1e-9 || *range.second > 1.0 + 1e-9)
  {
    Fail(state,
      "unexpected field: relative residual " + std::to_string(solution.relativeResidual) + ", range " +
        std::to_string(*range.first) + " to " + std::to_string(*range.second));
  }
}

void harmonicSolve(benchmark::State& state, HarmonicScene& scene)
{
  kerf::HarmonicFieldSolver& solver = strokeSolver(scene);
  const std::array<const kerf::FieldConstraints*, 2> constraints = { { &scene.shiftedConstraints,
    &scene.strokeConstraints } };
  kerf::HarmonicFieldSolution solution;
  bool backSubstitutedEveryTime = true;
  std::size_t which = 0;
  for (auto _ : state)
  {
    solution = solver.solve(scene.mesh, scene.weights, *constraints[which]);
    backSubstitutedEveryTime = backSubstitutedEveryTime && solution.work == Work::BackSubstitution;
    which = 1 - which;
  }
  if (!backSubstitutedEveryTime)
  {
    Fail(state, "a change of values cost more than a back-substitution");
  }
  else if (!(solution.relativeResidual < 1e-6))
  {
    Fail(state, "relative residual " + std::to_string(solution.relativeResidual));
  }
}

std::size_t pointCount(const std::vector<kerf::Isoline>& isolines)
{
  std::size_t points = 0;
  for (const kerf::Isoline& line : isolines)
  {
    points += line.points.size();
  }
  return points;
}

void coreExtractIsolines(benchmark::State& state, HarmonicScene& scene)
{
  const std::vector<double>& field = strokeField(scene);
  std::vector<kerf::Isoline> isolines;
  for (auto _ : state)
  {
    isolines = kerf::extractIsolines(scene.mesh, field, 0.0);
    benchmark::DoNotOptimize(isolines.data());
  }
  const bool anyClosed =
    std::any_of(isolines.begin(), isolines.end(), [](const kerf::Isoline& line) { return line.closed; });
  if (!anyClosed)
  {
    Fail(state, "no closed isoline at 0");
  }
  state.counters["isolines"] = static_cast<double>(isolines.size());
  state.counters["points"] = static_cast<double>(pointCount(isolines));
}

void vtkContourFilterOneValue(benchmark::State& state, HarmonicScene& scene)
{
  const std::vector<double>& field = strokeField(scene);
  vtkNew<vtkPolyData> surface;
  surface->ShallowCopy(scene.polyData);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("HarmonicField");
  scalars->SetNumberOfValues(static_cast<vtkIdType>(field.size()));
  std::copy(field.begin(), field.end(), scalars->GetPointer(0));
  surface->GetPointData()->SetScalars(scalars);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(surface);
  contour->SetValue(0, 0.0);
  for (auto _ : state)
  {
    contour->Modified();
    contour->Update();
  }
  // Both extract every crossed edge once, so the point counts agree.
  vtkPolyData* output = contour->GetOutput();
  const std::size_t kerfPoints = pointCount(kerf::extractIsolines(scene.mesh, field, 0.0));
  if (output->GetNumberOfLines() == 0 || static_cast<std::size_t>(output->GetNumberOfPoints()) != kerfPoints)
  {
    Fail(state,
      "vtkContourFilter made " + std::to_string(output->GetNumberOfPoints()) + " points, kerf::extractIsolines " +
        std::to_string(kerfPoints));
  }
  state.counters["points"] = static_cast<double>(output->GetNumberOfPoints());
}

void coreScoreIsovalues(benchmark::State& state, HarmonicScene& scene)
{
  const std::vector<double>& field = strokeField(scene);
  std::vector<kerf::IsovalueScore> scores;
  for (auto _ : state)
  {
    scores = kerf::scoreIsovalues(scene.mesh, field, scene.gradientMagnitudes, 50);
    benchmark::DoNotOptimize(scores.data());
  }
  const bool scored =
    std::any_of(scores.begin(), scores.end(), [](const kerf::IsovalueScore& s) { return s.score > 0.0; });
  if (scores.size() != 50 || !scored)
  {
    Fail(state, "expected 50 candidates with positive scores, got " + std::to_string(scores.size()));
  }
}

// Times cuts that alternate `stroke` between its two point sets; each must cost a low-rank
// update of the cached factorization (`what` names the stroke in the failure message).
void alternateStrokes(benchmark::State& state, CutPipeline& pipeline, vtkPolyData* stroke,
  const std::array<vtkSmartPointer<vtkPoints>, 2>& points, const char* what)
{
  bool updatedEveryTime = true;
  std::string work;
  std::size_t which = 0;
  for (auto _ : state)
  {
    stroke->SetPoints(points[which]);
    pipeline.cut->Update();
    work = pipeline.SolverWork();
    updatedEveryTime = updatedEveryTime && work == "update";
    which = 1 - which;
  }
  const std::string problem = pipeline.CheckCut();
  if (!updatedEveryTime)
  {
    Fail(state, "SolverWork was \"" + work + "\", not \"update\", for " + what);
  }
  else if (!problem.empty())
  {
    Fail(state, problem);
  }
}

void harmonicCutNewStroke(benchmark::State& state, HarmonicScene& scene)
{
  CutPipeline& pipeline = pipelineOf(scene);
  pipeline.ConnectCut(0.0);
  pipeline.stroke->SetPoints(pipeline.strokePoints[1]);
  pipeline.cut->Update(); // the first time: mesh conversion and factorization
  alternateStrokes(state, pipeline, pipeline.stroke, pipeline.strokePoints, "a new stroke");
}

void strokeCutDrawnStroke(benchmark::State& state, HarmonicScene& scene)
{
  vtkNew<vtkStrokeCut> cut;
  cut->SetInputData(scene.polyData);
  auto draw = [&cut](const std::vector<kerf::Vector3>& stroke) {
    cut->SetNumberOfDrawnStrokePoints(static_cast<int>(stroke.size()));
    for (std::size_t i = 0; i < stroke.size(); ++i)
    {
      cut->SetDrawnStrokePoint(static_cast<int>(i), stroke[i].x(), stroke[i].y(), stroke[i].z());
    }
  };
  draw(scene.strokes.around[1]);
  cut->Update(); // the first time: mesh conversion and factorization
  bool updatedEveryTime = true;
  std::size_t which = 0;
  for (auto _ : state)
  {
    draw(scene.strokes.around[which]);
    cut->Update();
    vtkStringArray* work =
      vtkStringArray::SafeDownCast(cut->GetOutput()->GetFieldData()->GetAbstractArray("SolverWork"));
    updatedEveryTime = updatedEveryTime && work && work->GetValue(0) == "update";
    which = 1 - which;
  }
  vtkDataArray* sizes = cut->GetOutput()->GetFieldData()->GetArray("SegmentSizes");
  if (!updatedEveryTime)
  {
    Fail(state, "a new drawn stroke did not only update the factorization");
  }
  else if (!sizes || sizes->GetNumberOfTuples() != 2 || cut->GetCut()->GetNumberOfLines() != 1)
  {
    Fail(state, "the drawn stroke does not cut the dumbbell in two");
  }
}

void harmonicCutSliding(benchmark::State& state, HarmonicScene& scene)
{
  CutPipeline& pipeline = pipelineOf(scene);
  pipeline.ConnectCut(SlidBackValue);
  pipeline.stroke->SetPoints(pipeline.strokePoints[0]);
  pipeline.cut->Update();
  const vtkMTimeType fieldTime = pipeline.field->GetOutput()->GetMTime();
  const std::array<double, 2> values = { { SlidValue, SlidBackValue } };
  std::size_t which = 0;
  for (auto _ : state)
  {
    pipeline.cut->SetIsoValue(values[which]);
    pipeline.cut->Update();
    which = 1 - which;
  }
  const std::string problem = pipeline.CheckCut();
  if (pipeline.field->GetOutput()->GetMTime() != fieldTime)
  {
    Fail(state, "sliding re-executed vtkHarmonicField");
  }
  else if (!problem.empty())
  {
    Fail(state, problem);
  }
}

void harmonicCutRefinement(benchmark::State& state, HarmonicScene& scene)
{
  CutPipeline& pipeline = pipelineOf(scene);
  pipeline.ConnectRefinement();
  pipeline.stroke->SetPoints(pipeline.strokePoints[0]);
  pipeline.refinementStroke->SetPoints(pipeline.refinementPoints[1]);
  pipeline.cut->Update();
  alternateStrokes(state, pipeline, pipeline.refinementStroke, pipeline.refinementPoints, "a refinement stroke");
}

using Function = void (*)(benchmark::State&, HarmonicScene&);

// Runs one benchmark on its size's scene; any exception fails it.
void run(benchmark::State& state, const CutSize* size, Function function)
{
  kerf::benchmarks::RunOnScene(
    state, [size]() -> HarmonicScene& { return sceneOfSize(*size); }, function, setCounters);
}

} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterHarmonicCutBenchmarks(bool useSizeMinimumTimes)
{
  const std::pair<const char*, Function> benchmarks[] = {
    { "BM_HarmonicFactorization", harmonicFactorization },
    { "BM_HarmonicDirichletFactorization", harmonicDirichletFactorization },
    { "BM_HarmonicSolve", harmonicSolve },
    { "BM_CoreExtractIsolines", coreExtractIsolines },
    { "BM_VTKContourFilter", vtkContourFilterOneValue },
    { "BM_CoreScoreIsovalues", coreScoreIsovalues },
    { "BM_HarmonicCutNewStroke", harmonicCutNewStroke },
    { "BM_HarmonicCutSliding", harmonicCutSliding },
    { "BM_HarmonicCutRefinement", harmonicCutRefinement },
    { "BM_StrokeCutDrawnStroke", strokeCutDrawnStroke },
  };
  for (const CutSize& size : Sizes)
  {
    for (const auto& [name, function] : benchmarks)
    {
      const std::string fullName = std::string(name) + "/" + size.label;
      benchmark::internal::Benchmark* registered = benchmark::RegisterBenchmark(fullName.c_str(), run, &size, function);
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
