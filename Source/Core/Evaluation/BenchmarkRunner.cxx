// The benchmark runner: a method run on a model and scored by its protocol (human baseline, automatic,
// interactive), the metrics averaged over the comparisons.
#include "Evaluation/BenchmarkRunner.h"

#include "Evaluation/SegmentationMetrics.h"

#include <chrono>
#include <cstddef>
#include <iterator>
#include <limits>
#include <utility>

namespace kerf
{

namespace
{
// The benchmark's metrics (Chen et al. 2009) in results.csv's order.
const char* const MetricNames[] = { "CutDiscrepancy", "HammingDistance", "MissingRate", "FalseAlarmRate",
  "RandIndexError", "GlobalConsistencyError", "LocalConsistencyError" };

// Sums the metrics of comparisons, to be averaged.
struct MetricSums
{
  std::map<std::string, double> sums;
  int comparisons = 0;

  void add(const SegmentationScores& s, const SegmentationScores* reverse)
  {
    const double values[] = { s.cutDiscrepancy, s.hammingDistance,
      reverse ? 0.5 * (s.missingRate + reverse->missingRate) : s.missingRate,
      reverse ? 0.5 * (s.falseAlarmRate + reverse->falseAlarmRate) : s.falseAlarmRate, s.randIndexError,
      s.globalConsistencyError, s.localConsistencyError };
    for (std::size_t m = 0; m < std::size(MetricNames); ++m)
    {
      this->sums[MetricNames[m]] += values[m];
    }
    ++this->comparisons;
  }

  ModelScores scores(double segments, double seconds) const
  {
    ModelScores result;
    for (const char* name : MetricNames)
    {
      const auto found = this->sums.find(name);
      result.values[name] =
        this->comparisons > 0 && found != this->sums.end() ? found->second / this->comparisons : 0.0;
    }
    result.values["Comparisons"] = this->comparisons;
    result.values["Segments"] = segments;
    result.values["Seconds"] = seconds;
    return result;
  }
};

// The benchmark's human baseline: every unordered pair of human segmentations.
ModelScores scoreHumans(const BenchmarkCase& c)
{
  const SegmentationEvaluator evaluator(c.surface->mesh());
  std::vector<PreparedSegmentation> humans;
  double segments = 0.0;
  for (const std::vector<int>& labels : c.humans)
  {
    humans.push_back(evaluator.prepare(labels));
    segments += humans.back().segmentCount;
  }
  MetricSums sums;
  for (std::size_t a = 0; a < humans.size(); ++a)
  {
    for (std::size_t b = a + 1; b < humans.size(); ++b)
    {
      const SegmentationScores forward = evaluator.compare(humans[a], humans[b]);
      const SegmentationScores backward = evaluator.compare(humans[b], humans[a]);
      sums.add(forward, &backward);
    }
  }
  ModelScores result = sums.scores(segments / static_cast<double>(humans.size()), 0.0);
  for (const char* column : { "Fidelity", "FidelityHamming", "Inputs", "InputSegmentsMatched" })
  {
    result.values[column] = std::numeric_limits<double>::quiet_NaN();
  }
  result.shownMethod = c.humans[0];
  result.shownHuman = c.humans[1];
  return result;
}

// Automatic methods: the mesh and the number of segments only, scored against every human.
ModelScores scoreAutomatic(const BenchmarkCase& c, const SegmentationMethod& method, const MethodParameters& parameters)
{
  const SegmentationEvaluator evaluator(c.surface->mesh());
  const auto start = std::chrono::steady_clock::now();
  const MethodOutput output = method.segment(c, nullptr, parameters);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const PreparedSegmentation prepared = evaluator.prepare(output.labels);
  MetricSums sums;
  for (const std::vector<int>& human : c.humans)
  {
    sums.add(evaluator.compare(prepared, evaluator.prepare(human)), nullptr);
  }
  ModelScores result = sums.scores(prepared.segmentCount, seconds);
  for (const char* column : { "Fidelity", "FidelityHamming", "Inputs", "InputSegmentsMatched" })
  {
    result.values[column] = std::numeric_limits<double>::quiet_NaN();
  }
  result.shownMethod = output.labels;
  result.shownHuman = c.humans[0];
  return result;
}

// Interactive methods: every human in turn gives the input, the others are the references.
ModelScores scoreInteractive(
  const BenchmarkCase& c, const SegmentationMethod& method, const MethodParameters& parameters)
{
  const SegmentationEvaluator evaluator(c.surface->mesh());
  std::vector<PreparedSegmentation> humans;
  for (const std::vector<int>& labels : c.humans)
  {
    humans.push_back(evaluator.prepare(labels));
  }
  MetricSums sums;
  double segments = 0.0, seconds = 0.0, inputs = 0.0, fidelity = 0.0, fidelityHamming = 0.0, matched = 0.0;
  ModelScores result;
  for (std::size_t input = 0; input < c.humans.size(); ++input)
  {
    const auto start = std::chrono::steady_clock::now();
    const MethodOutput output = method.segment(c, &c.humans[input], parameters);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const PreparedSegmentation prepared = evaluator.prepare(output.labels);
    for (std::size_t h = 0; h < humans.size(); ++h)
    {
      if (h != input)
      {
        sums.add(evaluator.compare(prepared, humans[h]), nullptr);
      }
    }
    const SegmentationScores self = evaluator.compare(prepared, humans[input]);
    fidelity += self.randIndexError;
    fidelityHamming += self.hammingDistance;
    segments += prepared.segmentCount;
    inputs += output.inputs;
    matched += prepared.segmentCount == humans[input].segmentCount ? 1.0 : 0.0;
    if (input == 0)
    {
      result.shownMethod = output.labels;
      result.shownHuman = c.humans[0];
    }
  }
  const double runs = static_cast<double>(c.humans.size());
  ModelScores scores = sums.scores(segments / runs, seconds / runs);
  scores.values["Fidelity"] = fidelity / runs;
  scores.values["FidelityHamming"] = fidelityHamming / runs;
  scores.values["Inputs"] = inputs / runs;
  scores.values["InputSegmentsMatched"] = matched / runs;
  scores.shownMethod = std::move(result.shownMethod);
  scores.shownHuman = std::move(result.shownHuman);
  return scores;
}

} // namespace

BenchmarkRow runBenchmarkModel(const BenchmarkCase& benchmarkCase, const SegmentationMethod& method,
  const std::string& parameters, ModelScores* scores)
{
  const MethodParameters parsed(parameters, method.parameters);
  ModelScores result;
  switch (method.protocol)
  {
    case SegmentationMethod::Protocol::HumanBaseline:
      result = scoreHumans(benchmarkCase);
      break;
    case SegmentationMethod::Protocol::Interactive:
      result = scoreInteractive(benchmarkCase, method, parsed);
      break;
    case SegmentationMethod::Protocol::Automatic:
      result = scoreAutomatic(benchmarkCase, method, parsed);
      break;
  }
  BenchmarkRow row;
  row.model = benchmarkCase.model.id;
  row.category = benchmarkCase.model.category;
  row.method = method.name;
  row.parameters = parameters;
  row.values = result.values;
  if (scores)
  {
    *scores = std::move(result);
  }
  return row;
}

} // namespace kerf
