// Scanning a folder in the Princeton Segmentation Benchmark's layout.
#include "Evaluation/PrincetonBenchmark.h"

#include "Error.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace kerf
{

std::string princetonCategory(int modelId)
{
  static const char* const categories[] = { "Human", "Cup", "Glasses", "Airplane", "Ant", "Chair", "Octopus", "Table",
    "Teddy", "Hand", "Plier", "Fish", "Bird", "Spring", "Armadillo", "Bust", "Mech", "Bearing", "Vase", "Fourleg" };
  if (modelId < 1 || modelId > 400)
  {
    return "Unknown";
  }
  return categories[(modelId - 1) / 20];
}

std::vector<BenchmarkModel> scanBenchmark(const std::string& directory)
{
  namespace fs = std::filesystem;
  const fs::path root(directory);
  if (!fs::is_directory(root / "off"))
  {
    throw Error(directory + " is not a benchmark folder: it has no off/ subfolder");
  }
  std::vector<int> requested;
  std::ifstream counts(root / "nSeg-ByModel.txt");
  if (counts)
  {
    int value;
    while (counts >> value)
    {
      requested.push_back(value);
    }
    if (!counts.eof())
    {
      throw Error((root / "nSeg-ByModel.txt").string() + " holds something other than integers");
    }
  }
  std::vector<BenchmarkModel> models;
  for (const fs::directory_entry& entry : fs::directory_iterator(root / "off"))
  {
    const fs::path& path = entry.path();
    const std::string stem = path.stem().string();
    if (path.extension() != ".off" || stem.empty() ||
      !std::all_of(stem.begin(), stem.end(), [](char c) { return c >= '0' && c <= '9'; }) || stem.size() > 6)
    {
      continue;
    }
    BenchmarkModel model;
    model.id = std::stoi(stem);
    model.category = princetonCategory(model.id);
    model.meshFile = path.string();
    if (model.id >= 1 && model.id <= static_cast<int>(requested.size()))
    {
      model.requestedSegments = requested[model.id - 1];
    }
    for (int j = 0;; ++j)
    {
      const fs::path seg = root / "seg" / stem / (stem + "_" + std::to_string(j) + ".seg");
      if (!fs::exists(seg))
      {
        break;
      }
      model.humanSegmentations.push_back(seg.string());
    }
    models.push_back(std::move(model));
  }
  std::sort(models.begin(), models.end(), [](const BenchmarkModel& a, const BenchmarkModel& b) { return a.id < b.id; });
  return models;
}

} // namespace kerf
