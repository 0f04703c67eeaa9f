// The Princeton Segmentation Benchmark's folder layout: models, categories, human segmentations.
#pragma once

#include <string>
#include <vector>

namespace kerf
{

/// One model of a benchmark folder.
struct BenchmarkModel
{
  int id = 0;
  std::string category;
  std::string meshFile;                        ///< off/<id>.off
  std::vector<std::string> humanSegmentations; ///< seg/<id>/<id>_<j>.seg, in order of j
  int requestedSegments = 0;                   ///< line <id> of nSeg-ByModel.txt (0 if absent)
};

/// The benchmark's category of a model id (1-20 Human, 21-40 Cup, ..., 381-400 Fourleg), or
/// "Unknown" outside the benchmark's ranges.
std::string princetonCategory(int modelId);

/// Lists the models of a folder in the benchmark's layout (off/N.off, seg/N/N_j.seg,
/// nSeg-ByModel.txt), sorted by id. Models without an OFF file are skipped; throws kerf::Error
/// if the folder has no off/ subfolder or nSeg-ByModel.txt is malformed.
std::vector<BenchmarkModel> scanBenchmark(const std::string& directory);

} // namespace kerf
