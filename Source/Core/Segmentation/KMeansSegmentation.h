// K-means face clustering with representatives on the dual graph (Shlafman et al. 2002; Kouhestani 2013, section 3.4).
#pragma once

#include "Segmentation/FaceGraph.h"

#include <vector>

namespace kerf
{

struct KMeansSegmentationOptions
{
  /// delta of Distance = (1 - delta)(1 - cos^2 alpha) + delta Phys (Shlafman et al. 2002), Phys
  /// divided by its mean over the dual edges so that delta does not depend on the mesh's scale.
  /// Default 0.2.
  double physicalWeight = 0.2;
  /// Assignment and re-election rounds at most (they stop earlier when no representative
  /// changes). Default 20.
  int maximumIterations = 20;
};

struct KMeansSegmentationResult
{
  std::vector<int> labels;          ///< per face, numbered by first face
  std::vector<int> representatives; ///< the faces of the last election
  int iterations = 0;
};

/// The dual-edge distance of Shlafman et al. 2002 for every dual edge.
std::vector<double> kMeansEdgeDistances(const FaceGraph& graph, double physicalWeight);

/// Shlafman et al. 2002: the first representative is the face whose centroid is nearest the mesh's
/// (area-weighted) centroid; each next one the face with the largest mean dual-graph distance to
/// those chosen. Each round assigns every face to its nearest representative by a multi-source
/// Dijkstra on the dual graph, then re-elects in each patch the face whose centroid is nearest the
/// patch's centroid (the survey's cheaper option), until nothing changes. Segments are connected
/// (finalizeSegments). Each dual-graph component is clustered apart with its share of k
/// (segmentComponents). Throws kerf::Error for k < 1, k > faces, delta outside [0, 1] or fewer
/// than one iteration.
KMeansSegmentationResult segmentByKMeans(const FaceGraph& graph, int k, const KMeansSegmentationOptions& options);

/// segmentByKMeans at every count from lowestCount to highestCount, in that order, each result
/// equal to segmentByKMeans at its count: on a connected graph the representatives' initialisation,
/// whose first k faces are the k-count's, is run once for the highest count (highestCount - 1
/// single-source searches instead of one run per count). Throws kerf::Error for lowestCount < 1,
/// highestCount < lowestCount, and what segmentByKMeans refuses at highestCount.
std::vector<KMeansSegmentationResult> segmentByKMeansAtCounts(
  const FaceGraph& graph, int lowestCount, int highestCount, const KMeansSegmentationOptions& options);

} // namespace kerf
