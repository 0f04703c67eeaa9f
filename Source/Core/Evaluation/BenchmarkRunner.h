// The benchmark runner: one method on one model, scored against the humans by its protocol, as a results.csv row.
#pragma once

#include "Evaluation/BenchmarkCase.h"
#include "Evaluation/BenchmarkResults.h"
#include "Evaluation/SegmentationMethods.h"

#include <map>
#include <string>
#include <vector>

namespace kerf
{

/// What a method did on one model: the mean of every metric over its comparisons, and what to
/// show in its picture.
struct ModelScores
{
  std::map<std::string, double> values; ///< every column of benchmarkMetricColumns()
  std::vector<int> shownMethod;         ///< the method's segmentation (per face)
  std::vector<int> shownHuman;          ///< the human it is shown beside
};

/// Runs `method` with `parameters` on one model; throws kerf::Error naming the model.
BenchmarkRow runBenchmarkModel(const BenchmarkCase& benchmarkCase, const SegmentationMethod& method,
  const std::string& parameters, ModelScores* scores = nullptr);

} // namespace kerf
