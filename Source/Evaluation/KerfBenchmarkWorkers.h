// The benchmark's worker processes: models spread over forked workers, their results.csv rows gathered through pipes.
#pragma once

#include "Evaluation/BenchmarkResults.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace kerf
{

/// Runs `work` for every model in `jobs` worker processes (fork; 1 runs in this process), each
/// sending one results.csv line per model back through a pipe, and calls `finished` as rows
/// arrive. Returns the rows sorted by model; throws kerf::Error if any model failed (with the
/// first failure's message).
std::vector<BenchmarkRow> runInWorkers(const std::vector<int>& models, int jobs,
  const std::function<BenchmarkRow(int)>& work,
  const std::function<void(std::size_t done, const BenchmarkRow&)>& finished);

} // namespace kerf
