// Loading a benchmark model: its OFF mesh, checked, and its human segmentations.
#include "Evaluation/BenchmarkCase.h"

#include "Error.h"
#include "IO/MeshFormats.h"
#include "Mesh/MeshValidation.h"
#include "Mesh/SurfaceConversion.h"

#include <string>
#include <utility>

namespace kerf
{

BenchmarkCase loadBenchmarkCase(const BenchmarkModel& model)
{
  BenchmarkCase loaded;
  loaded.model = model;
  ConvertedPolygons converted = convertPolygons(readOFF(model.meshFile));
  if (!converted.allTriangles)
  {
    throw Error("the benchmark's meshes are triangle meshes, but " + model.meshFile + " has other polygons");
  }
  // The metrics need no manifold: benchmark meshes may have any defect but NaN coordinates.
  MeshRequirements requirements;
  requirements.manifold = false;
  requirements.consistentOrientation = false;
  const std::string problems = describeProblems(inspectMesh(converted.mesh), requirements);
  if (!problems.empty())
  {
    throw Error(model.meshFile + " is not accepted: " + problems);
  }
  loaded.surface = std::make_shared<const Surface>(std::move(converted.mesh));
  for (const std::string& file : model.humanSegmentations)
  {
    loaded.humans.push_back(readSegmentation(file));
  }
  if (loaded.humans.size() < 2)
  {
    throw Error(
      "it has " + std::to_string(loaded.humans.size()) + " human segmentations; the protocol needs at least 2");
  }
  return loaded;
}

} // namespace kerf
