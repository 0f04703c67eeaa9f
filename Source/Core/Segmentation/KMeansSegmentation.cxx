// K-means face clustering: Shlafman et al.'s distance, representative initialisation, assignment and re-election.
#include "Segmentation/KMeansSegmentation.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace kerf
{

std::vector<double> kMeansEdgeDistances(const FaceGraph& graph, double physicalWeight)
{
  double meanPath = 0.0;
  for (const DualEdge& e : graph.edges())
  {
    meanPath += e.centroidPath;
  }
  meanPath = graph.edgeCount() > 0 && meanPath > 0.0 ? meanPath / graph.edgeCount() : 1.0;
  std::vector<double> distance(graph.edgeCount());
  for (int e = 0; e < graph.edgeCount(); ++e)
  {
    const double c = graph.edge(e).normalCosine;
    // Shlafman et al. 2002, section 3: (1 - delta)(1 - cos^2 alpha) + delta Phys.
    distance[e] = (1.0 - physicalWeight) * (1.0 - c * c) + physicalWeight * graph.edge(e).centroidPath / meanPath;
  }
  return distance;
}

namespace
{
// Shlafman et al. 2002, section 3: the first representative is the face nearest the centroid, each
// next one the face farthest on average from those chosen. The first k of the `count` returned
// are the representatives for k.
std::vector<int> initialRepresentatives(const FaceGraph& graph, const std::vector<double>& lengths, int count)
{
  const int n = graph.faceCount();
  Vector3 centre = Vector3::Zero();
  for (int f = 0; f < n; ++f)
  {
    centre += graph.area(f) * graph.centroid(f);
  }
  centre /= std::max(graph.totalArea(), std::numeric_limits<double>::min());
  int first = 0;
  for (int f = 1; f < n; ++f)
  {
    if ((graph.centroid(f) - centre).squaredNorm() < (graph.centroid(first) - centre).squaredNorm())
    {
      first = f;
    }
  }
  std::vector<int> representatives = { first };
  // Sum of distances to the chosen representatives; the next is the face farthest on average.
  std::vector<double> sum(n, 0.0);
  std::vector<char> chosen(n, 0);
  chosen[first] = 1;
  while (static_cast<int>(representatives.size()) < count)
  {
    const DualDistances single = dualDijkstra(graph, lengths, { representatives.back() });
    int best = -1;
    for (int f = 0; f < n; ++f)
    {
      sum[f] += single.distance[f];
      if (!chosen[f] && (best < 0 || sum[f] > sum[best]))
      {
        best = f;
      }
    }
    chosen[best] = 1;
    representatives.push_back(best);
  }
  return representatives;
}

// The assignment and re-election rounds from the first k of `initial`.
KMeansSegmentationResult clusterFrom(const FaceGraph& graph, const std::vector<double>& lengths,
  const std::vector<int>& initial, int k, const KMeansSegmentationOptions& options)
{
  const int n = graph.faceCount();
  KMeansSegmentationResult result;
  result.representatives.assign(initial.begin(), initial.begin() + k);
  std::vector<int> labels;
  for (result.iterations = 1;; ++result.iterations)
  {
    labels = dualDijkstra(graph, lengths, result.representatives).nearest;
    std::vector<Vector3> centroid(k, Vector3::Zero());
    std::vector<double> area(k, 0.0);
    for (int f = 0; f < n; ++f)
    {
      centroid[labels[f]] += graph.area(f) * graph.centroid(f);
      area[labels[f]] += graph.area(f);
    }
    std::vector<int> elected(k, -1);
    std::vector<double> nearest(k, std::numeric_limits<double>::infinity());
    for (int f = 0; f < n; ++f)
    {
      const int p = labels[f];
      const Vector3 c = area[p] > 0.0 ? Vector3(centroid[p] / area[p]) : graph.centroid(result.representatives[p]);
      const double d = (graph.centroid(f) - c).squaredNorm();
      if (d < nearest[p])
      {
        nearest[p] = d;
        elected[p] = f;
      }
    }
    if (elected == result.representatives || result.iterations >= options.maximumIterations)
    {
      break;
    }
    result.representatives = elected;
  }
  result.labels = finalizeSegments(graph, labels, k);
  return result;
}

KMeansSegmentationResult clusterConnected(const FaceGraph& graph, int k, const KMeansSegmentationOptions& options)
{
  const std::vector<double> lengths = kMeansEdgeDistances(graph, options.physicalWeight);
  return clusterFrom(graph, lengths, initialRepresentatives(graph, lengths, k), k, options);
}

void checkKMeansOptions(const KMeansSegmentationOptions& options)
{
  if (!(options.physicalWeight >= 0.0 && options.physicalWeight <= 1.0))
  {
    throw Error("the physical-distance weight delta must lie in [0, 1]");
  }
  if (options.maximumIterations < 1)
  {
    throw Error("k-means needs at least one iteration");
  }
}
} // namespace

KMeansSegmentationResult segmentByKMeans(const FaceGraph& graph, int k, const KMeansSegmentationOptions& options)
{
  checkSegmentCount(k, graph.faceCount());
  checkKMeansOptions(options);
  if (graph.componentCount() == 1)
  {
    return clusterConnected(graph, k, options);
  }
  KMeansSegmentationResult result;
  result.labels = segmentComponents(graph, k, [&](const TriangleMesh& part, int partK) {
    const FaceGraph partGraph(part);
    const KMeansSegmentationResult partResult = clusterConnected(partGraph, partK, options);
    result.iterations = std::max(result.iterations, partResult.iterations);
    return partResult.labels;
  });
  return result;
}

std::vector<KMeansSegmentationResult> segmentByKMeansAtCounts(
  const FaceGraph& graph, int lowestCount, int highestCount, const KMeansSegmentationOptions& options)
{
  if (lowestCount < 1 || highestCount < lowestCount)
  {
    throw Error("k-means at counts needs 1 <= lowest <= highest, got " + std::to_string(lowestCount) + " and " +
      std::to_string(highestCount));
  }
  checkSegmentCount(highestCount, graph.faceCount());
  checkKMeansOptions(options);
  std::vector<KMeansSegmentationResult> results;
  if (graph.componentCount() != 1)
  {
    for (int k = lowestCount; k <= highestCount; ++k)
    {
      results.push_back(segmentByKMeans(graph, k, options));
    }
    return results;
  }
  const std::vector<double> lengths = kMeansEdgeDistances(graph, options.physicalWeight);
  const std::vector<int> initial = initialRepresentatives(graph, lengths, highestCount);
  for (int k = lowestCount; k <= highestCount; ++k)
  {
    results.push_back(clusterFrom(graph, lengths, initial, k, options));
  }
  return results;
}

} // namespace kerf
