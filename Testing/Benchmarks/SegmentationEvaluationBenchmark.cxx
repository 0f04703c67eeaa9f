// Benchmarks of segmentation evaluation: the metrics filter and Core evaluator, and the human baseline over psb-dev.
//
//   BM_SegmentationMetricsFilter/50k    vtkSegmentationMetrics (every metric, cut discrepancy
//                                       included) comparing two cell arrays of one mesh
//   BM_CoreSegmentationEvaluator/50k    the Core steps the filter runs: kerf::SegmentationEvaluator
//                                       constructor, prepare() of both segmentations, compare()
//   BM_CoreSegmentationCompare/50k      compare() alone, on prepared segmentations (the cost of one
//                                       more comparison when a benchmark compares many)
// on a torus (kerf::makeTorus, 224 x 112 vertices, 50,176 triangles) cut into 10 bands about its
// axis, evaluated against 10 bands turned by 0.3 band. Then
//   BM_HumanBaseline/1model, /all       vtkSegmentationBenchmark, method "human" (every pair of
//                                       human segmentations), on the first model and on every
//                                       model of KERF_SHARED_DATA_DIR/psb-dev
// registered only when that folder exists (the program's context says when it was not found).
#include "BenchmarkPolyData.h"
#include "KerfBenchmarks.h"
#include "vtkSegmentationBenchmark.h"
#include "vtkSegmentationMetrics.h"

#include "Evaluation/SegmentationMetrics.h"
#include "Mesh/MeshGenerators.h"
#include "Mesh/TriangleMesh.h"

#include <benchmark/benchmark.h>

#include <vtkCellData.h>
#include <vtkDataObject.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkVariant.h>

#include <cmath>
#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace
{

using kerf::benchmarks::Fail;

constexpr double Pi = 3.14159265358979323846;
constexpr int Bands = 10;
constexpr int TorusAround = 224; // 2 * 224 * 112 = 50,176 triangles
constexpr int TorusTube = 112;

/// The metrics' mesh and its two segmentations.
struct SegmentedTorus
{
  kerf::TriangleMesh mesh;
  std::vector<int> evaluated;            ///< Bands bands about the axis
  std::vector<int> reference;            ///< the same bands turned by 0.3 band
  vtkSmartPointer<vtkPolyData> polyData; ///< with the cell arrays "Segment" and "Reference"
};

// Band of each face about the z axis, from its centroid's angle, starting `shift` bands on.
std::vector<int> bandsAboutAxis(const kerf::TriangleMesh& mesh, double shift)
{
  std::vector<int> labels(static_cast<std::size_t>(mesh.faceCount()));
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const kerf::Triangle& t = mesh.triangle(f);
    const kerf::Vector3 centroid = (mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0;
    const double turns = (std::atan2(centroid.y(), centroid.x()) + Pi) / (2.0 * Pi);
    labels[f] = static_cast<int>(std::floor(Bands * turns + shift)) % Bands;
  }
  return labels;
}

vtkSmartPointer<vtkIntArray> labelArray(const char* name, const std::vector<int>& labels)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(labels.size()));
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    array->SetValue(static_cast<vtkIdType>(f), labels[f]);
  }
  return array;
}

// Built on first use, so that a run without the metrics never builds it.
const SegmentedTorus& segmentedTorus()
{
  static std::unique_ptr<SegmentedTorus> torus;
  if (!torus)
  {
    auto built = std::make_unique<SegmentedTorus>();
    built->mesh = kerf::makeTorus(2.0, 1.0, TorusAround, TorusTube);
    built->evaluated = bandsAboutAxis(built->mesh, 0.0);
    built->reference = bandsAboutAxis(built->mesh, 0.3);
    built->polyData = kerf::benchmarks::MakePolyData(built->mesh);
    built->polyData->GetCellData()->AddArray(labelArray("Segment", built->evaluated));
    built->polyData->GetCellData()->AddArray(labelArray("Reference", built->reference));
    torus = std::move(built);
  }
  return *torus;
}

void setCounters(benchmark::State& state, const SegmentedTorus& torus)
{
  state.counters["triangles"] = torus.mesh.faceCount();
  state.counters["vertices"] = torus.mesh.vertexCount();
  state.SetLabel(
    "torus " + std::to_string(TorusAround) + "x" + std::to_string(TorusTube) + ", " + std::to_string(Bands) + " bands");
}

// Empty if the scores are those of two different 10-band segmentations of the whole torus.
std::string checkScores(const kerf::SegmentationScores& scores, int faces)
{
  if (scores.segments1 != Bands || scores.segments2 != Bands || scores.comparedFaces != faces || !scores.cutsCompared ||
    !(scores.cutDiscrepancy > 0.0) || !(scores.randIndexError > 0.0))
  {
    return "unexpected scores: " + std::to_string(scores.segments1) + " and " + std::to_string(scores.segments2) +
      " segments, " + std::to_string(scores.comparedFaces) + " faces compared, cut discrepancy " +
      std::to_string(scores.cutDiscrepancy) + ", 1 - Rand index " + std::to_string(scores.randIndexError);
  }
  return "";
}

void segmentationMetricsFilter(benchmark::State& state)
{
  const SegmentedTorus& torus = segmentedTorus();
  vtkNew<vtkSegmentationMetrics> metrics;
  metrics->SetInputData(torus.polyData);
  metrics->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Reference");
  for (auto _ : state)
  {
    metrics->Modified();
    metrics->Update();
  }
  // The filter's table must hold the Core's scores.
  const kerf::SegmentationScores expected = kerf::compareSegmentations(torus.mesh, torus.evaluated, torus.reference);
  vtkTable* table = metrics->GetOutput();
  const std::string problem = checkScores(expected, torus.mesh.faceCount());
  const double cutDiscrepancy =
    table->GetNumberOfRows() == 1 ? table->GetValueByName(0, "CutDiscrepancy").ToDouble() : -1.0;
  if (!problem.empty())
  {
    Fail(state, problem);
  }
  else if (!(std::abs(cutDiscrepancy - expected.cutDiscrepancy) <= 1e-9 * expected.cutDiscrepancy))
  {
    Fail(state,
      "vtkSegmentationMetrics' CutDiscrepancy " + std::to_string(cutDiscrepancy) + " differs from the Core's " +
        std::to_string(expected.cutDiscrepancy));
  }
  setCounters(state, torus);
}

void coreSegmentationEvaluator(benchmark::State& state)
{
  const SegmentedTorus& torus = segmentedTorus();
  kerf::SegmentationScores scores;
  for (auto _ : state)
  {
    const kerf::SegmentationEvaluator evaluator(torus.mesh);
    scores = evaluator.compare(evaluator.prepare(torus.evaluated), evaluator.prepare(torus.reference));
    benchmark::DoNotOptimize(scores);
  }
  const std::string problem = checkScores(scores, torus.mesh.faceCount());
  if (!problem.empty())
  {
    Fail(state, problem);
  }
  setCounters(state, torus);
}

void coreSegmentationCompare(benchmark::State& state)
{
  const SegmentedTorus& torus = segmentedTorus();
  const kerf::SegmentationEvaluator evaluator(torus.mesh);
  const kerf::PreparedSegmentation evaluated = evaluator.prepare(torus.evaluated);
  const kerf::PreparedSegmentation reference = evaluator.prepare(torus.reference);
  kerf::SegmentationScores scores;
  for (auto _ : state)
  {
    scores = evaluator.compare(evaluated, reference);
    benchmark::DoNotOptimize(scores);
  }
  const std::string problem = checkScores(scores, torus.mesh.faceCount());
  if (!problem.empty())
  {
    Fail(state, problem);
  }
  setCounters(state, torus);
}

// Runs a metrics benchmark; any exception fails it.
void guarded(benchmark::State& state, void (*function)(benchmark::State&))
{
  try
  {
    function(state);
  }
  catch (const std::exception& e)
  {
    Fail(state, e.what());
  }
}

const std::string PsbDirectory = std::string(KERF_SHARED_DATA_DIR) + "/psb-dev";

void humanBaseline(benchmark::State& state, const std::vector<int>* models)
{
  vtkNew<vtkSegmentationBenchmark> baseline;
  baseline->SetDataDirectory(PsbDirectory.c_str());
  baseline->SetMethod("human");
  for (int id : *models)
  {
    baseline->AddModel(id);
  }
  for (auto _ : state)
  {
    baseline->Modified();
    baseline->Update();
  }
  // One row per model, each from at least one pair of humans, with finite scores. The filter
  // reports its own errors with vtkErrorMacro.
  vtkTable* table = baseline->GetOutput();
  double comparisons = 0.0;
  bool finite = true;
  for (vtkIdType row = 0; row < table->GetNumberOfRows(); ++row)
  {
    comparisons += table->GetValueByName(row, "Comparisons").ToDouble();
    finite = finite && std::isfinite(table->GetValueByName(row, "RandIndexError").ToDouble()) &&
      std::isfinite(table->GetValueByName(row, "CutDiscrepancy").ToDouble());
  }
  if (table->GetNumberOfRows() != static_cast<vtkIdType>(models->size()) || comparisons < models->size() || !finite)
  {
    Fail(state,
      "the human baseline has " + std::to_string(table->GetNumberOfRows()) + " rows for " +
        std::to_string(models->size()) + " models, " + std::to_string(comparisons) + " comparisons" +
        (finite ? "" : ", and NaN scores"));
  }
  state.counters["models"] = static_cast<double>(models->size());
  state.counters["comparisons"] = comparisons;
}

} // namespace

namespace kerf
{
namespace benchmarks
{

void RegisterSegmentationEvaluationBenchmarks(bool useSizeMinimumTimes)
{
  const std::pair<const char*, void (*)(benchmark::State&)> metrics[] = {
    { "BM_SegmentationMetricsFilter/50k", segmentationMetricsFilter },
    { "BM_CoreSegmentationEvaluator/50k", coreSegmentationEvaluator },
    { "BM_CoreSegmentationCompare/50k", coreSegmentationCompare },
  };
  for (const auto& [name, function] : metrics)
  {
    benchmark::internal::Benchmark* registered = benchmark::RegisterBenchmark(name, guarded, function);
    registered->Unit(benchmark::kMillisecond)->UseRealTime();
    if (useSizeMinimumTimes)
    {
      registered->MinTime(0.5);
    }
  }

  std::string error;
  static const std::vector<int> all = vtkSegmentationBenchmark::FindModels(PsbDirectory, error);
  if (all.empty())
  {
    benchmark::AddCustomContext(
      "psb_dev", (error.empty() ? PsbDirectory + " holds no model" : error) + "; BM_HumanBaseline not registered");
    return;
  }
  benchmark::AddCustomContext("psb_dev", PsbDirectory);
  static const std::vector<int> first = { all.front() };
  const std::pair<const char*, const std::vector<int>*> sizes[] = {
    { "BM_HumanBaseline/1model", &first },
    { "BM_HumanBaseline/all", &all },
  };
  for (const auto& [name, models] : sizes)
  {
    benchmark::internal::Benchmark* registered = benchmark::RegisterBenchmark(name, humanBaseline, models);
    registered->Unit(benchmark::kMillisecond)->UseRealTime();
    if (useSizeMinimumTimes)
    {
      // One run of all models takes seconds; the minimum asks for one run per repetition.
      registered->MinTime(0.1);
    }
  }
}

} // namespace benchmarks
} // namespace kerf
