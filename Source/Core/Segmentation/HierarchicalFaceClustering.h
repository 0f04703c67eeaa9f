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
  /// Meshes of at most this many faces are contracted in the greedy order of the paper from the
  /// first face on. On larger meshes the contractions start inside blocks of `blockSize` nearby
  /// faces, each block greedy on the pairs within it down to its share of this count (its faces
  /// times exactClusterCount / n, rounded up), the blocks' contractions interleaved by cost; the
  /// greedy order then holds over the whole mesh from the clusters left (about this many). A cut
  /// at k clusters with k at most that number comes from that part of the tree, on the blocks'
  /// clusters. Default 50,000 (every psb-dev model is smaller).
  int exactClusterCount = 50000;
  /// Faces per block where exactClusterCount applies, grown breadth-first over the dual graph.
  /// Default 2048 (about 1 MB of quadrics and pairs: the block's contractions run in cache).
  int blockSize = 2048;
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
/// cluster, O(degree log n). Above options.exactClusterCount faces the contractions start in
/// blocks (HierarchicalClusteringOptions; Documentation/filters/AutomaticSegmentation.md, *Blocks
/// above 50,000 triangles*). Deterministic (ties by cluster slot). Throws kerf::Error for negative
/// or NaN weights and for a block size or exact cluster count below 1.
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
