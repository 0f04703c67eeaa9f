// Hierarchical face clustering by dual-edge contraction (Garland et al. 2001): the merge tree and its cuts.
#pragma once

#include "Segmentation/FaceGraph.h"

#include <array>
#include <string>
#include <vector>

namespace kerf
{

class Surface;

/// The weights of the contraction cost E = E_fit + a1 E_dir + a2 E_shape (Garland et al. 2001,
/// section 3; Kouhestani 2013, section 3.3).
struct HierarchicalClusteringOptions
{
  /// a1, the weight of the orientation error E_dir. Default 1 (the paper's).
  double directionWeight = 1.0;
  /// a2, the weight of the shape error E_shape. Default 0.1: with the paper's 1, merging two
  /// squares of one plane into a 2:1 rectangle (E_shape = 0.11) costs more than joining faces
  /// across a right-angled crease, and a cube's six sides do not come out whole.
  double shapeWeight = 0.1;
};

/// A key naming these options (faceClusterHierarchy caches by it).
std::string cacheKey(const HierarchicalClusteringOptions& options);

/// The merge tree: nodes 0..n-1 are the faces, merge i joins two nodes into node n + i (the
/// layout of a dendrogram). Merges run until no dual edge is left, so a mesh whose dual graph
/// has c components ends with c clusters (n - c merges).
struct FaceClusterHierarchy
{
  int faceCount = 0;
  std::vector<std::array<int, 2>> merges; ///< the two nodes joined by each merge, in order
  std::vector<double> costs;              ///< E of each merge
  long long costEvaluations = 0;          ///< contraction costs computed while building (the work; bounds not counted)
};

/// Builds the tree: each face a cluster with its fit quadric (its corners, positions divided by the
/// bounding-box diagonal so E_fit is scale-free) and direction quadric (its normal, weighted by its
/// area); the pair of adjacent clusters with the least contraction cost contracted, the quadrics
/// summed, until no pair is left. The best plane of a cluster is the eigenvector of A - b b^T / c
/// with the smallest eigenvalue. One heap entry per adjacent pair, keyed on a lower bound of its
/// cost until the bound reaches the top, where the cost is computed: the order is that of computing
/// every cost, with about one cost computed per face. A merge bounds again every pair of the kept
/// cluster, O(degree log n). Deterministic (ties by cluster slot). Throws kerf::Error for negative
/// or NaN weights.
FaceClusterHierarchy buildFaceClusterHierarchy(const FaceGraph& graph, const HierarchicalClusteringOptions& options);

/// The tree for a surface, built on first use and cached on it (Surface::derived).
const FaceClusterHierarchy& faceClusterHierarchy(const Surface& surface, const HierarchicalClusteringOptions& options);

/// Per-face cluster labels after the first n - k merges (all of them when the tree has fewer),
/// numbered by first face: k clusters, or the number of components if that is larger. Linear
/// time: sliding k never rebuilds the tree. Throws kerf::Error for k < 1 or k > n.
std::vector<int> cutHierarchyAtCount(const FaceClusterHierarchy& hierarchy, int k);

/// Labels after the merges that precede the first whose cost exceeds `maximumError`.
std::vector<int> cutHierarchyAtError(const FaceClusterHierarchy& hierarchy, double maximumError);

} // namespace kerf
