// One benchmark model loaded for the methods: its surface and its human segmentations.
#pragma once

#include "Evaluation/PrincetonBenchmark.h"
#include "Surface/Surface.h"

#include <memory>
#include <vector>

namespace kerf
{

/// One model ready for a method: its surface and its human segmentations.
struct BenchmarkCase
{
  BenchmarkModel model;
  std::shared_ptr<const Surface> surface;
  std::vector<std::vector<int>> humans; ///< per face, in the order of model.humanSegmentations
};

/// Reads a model's mesh (OFF, triangles only; coincident points welded as every Kerf filter does)
/// and its human segmentations; throws kerf::Error naming the file and the problem.
BenchmarkCase loadBenchmarkCase(const BenchmarkModel& model);

} // namespace kerf
