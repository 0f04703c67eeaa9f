// Convex flooding of the dual graph and the merging of small patches.
#include "Segmentation/ConvexFlooding.h"

#include "Error.h"

#include <cmath>

namespace kerf
{

ConvexFloodingResult segmentByConvexFlooding(const FaceGraph& graph, const ConvexFloodingOptions& options)
{
  if (!(options.angleTolerance >= 0.0) || !std::isfinite(options.angleTolerance))
  {
    throw Error("the convexity tolerance must be a finite angle >= 0");
  }
  if (!(options.minimumAreaFraction >= 0.0 && options.minimumAreaFraction <= 1.0))
  {
    throw Error("the minimum area fraction must lie in [0, 1]");
  }
  if (options.segmentCount < 0)
  {
    throw Error("the segment count must be 0 (no limit) or positive");
  }
  const int n = graph.faceCount();
  std::vector<int> patch(n, -1);
  std::vector<int> rejectedBy(n, -1); // the patch that refused a face (final: a patch only grows)
  std::vector<int> queue;
  int patches = 0;
  for (int seed = 0; seed < n; ++seed)
  {
    if (patch[seed] >= 0)
    {
      continue;
    }
    const int current = patches++;
    patch[seed] = current;
    queue.assign(1, seed);
    for (std::size_t i = 0; i < queue.size(); ++i)
    {
      for (int e : graph.faceEdges(queue[i]))
      {
        if (e < 0)
        {
          continue;
        }
        const int g = graph.opposite(e, queue[i]);
        if (patch[g] >= 0 || rejectedBy[g] == current)
        {
          continue;
        }
        // Local convexity at every edge g shares with the patch: interior angle <= pi + epsilon.
        bool convex = true;
        for (int ge : graph.faceEdges(g))
        {
          if (ge >= 0 && patch[graph.opposite(ge, g)] == current && graph.edge(ge).bend < -options.angleTolerance)
          {
            convex = false;
          }
        }
        if (convex)
        {
          patch[g] = current;
          queue.push_back(g);
        }
        else
        {
          rejectedBy[g] = current;
        }
      }
    }
  }
  ConvexFloodingResult result;
  result.floodedPatches = patches;
  RegionAdjacency regions(graph, patch);
  const auto largest = [](const RegionAdjacency& r, int region) { return r.largestNeighbour(region); };
  mergeSmallRegions(regions, options.minimumAreaFraction * graph.totalArea(), largest);
  if (options.segmentCount > 0)
  {
    mergeSmallestUntil(regions, options.segmentCount, largest);
  }
  result.labels = regions.labels();
  result.segmentCount = regions.liveCount();
  return result;
}

} // namespace kerf
