// Ensemble segmentation: the partition into k parts that several automatic segmentations agree on most.
#pragma once

#include "Segmentation/BoundaryRefinement.h"
#include "Segmentation/ConsensusCutSegmentation.h"
#include "Segmentation/ConvexFlooding.h"
#include "Segmentation/CoreExtraction.h"
#include "Segmentation/FaceGraph.h"
#include "Segmentation/HierarchicalFaceClustering.h"
#include "Segmentation/KMeansSegmentation.h"
#include "Segmentation/SpectralSegmentation.h"
#include "Segmentation/WatershedSegmentation.h"

#include <array>
#include <vector>

namespace kerf
{

class Surface;

/// One segmentation of a mesh's faces (a label per face, any non-negative numbers) and its vote.
struct WeightedPartition
{
  std::vector<int> labels;
  double weight = 1.0;
};

struct PartitionConsensus
{
  std::vector<int> labels; ///< per face, numbered by first face
  int atoms = 0;           ///< connected groups of faces that every partition keeps together
  int merges = 0;          ///< atom groups joined by the average linkage
};

/// The consensus of several partitions of a surface's faces, in at most k connected segments (never
/// fewer segments than the dual graph has components, which cannot merge). Evidence accumulation
/// (Fred and Jain 2005, section 3): the co-association of two faces is the weighted fraction of
/// partitions that put them in one segment. Faces that every partition keeps together form atoms
/// (each one edge-connected set); atoms are merged by average linkage (the mean co-association over
/// all pairs of faces of two groups; Fred and Jain 2005, section 4), only across dual edges so that
/// every segment stays connected, the most agreed pair first, until k groups remain. A face counts
/// once in each mean (the Princeton benchmark's Rand index counts faces), or by its area (in units
/// of the mean face area) with `areaWeighted`. Among pairs with equal means the one whose smaller
/// group is smallest joins first, then the pair of smaller group numbers, so the result is
/// deterministic. The groups are then made at most k and numbered by first face (finalizeSegments).
/// Throws kerf::Error for k out of range, no partition, a partition of the wrong size or with a
/// negative label, or weights that are negative, not finite or all zero.
PartitionConsensus combinePartitions(
  const FaceGraph& graph, const std::vector<WeightedPartition>& partitions, int k, bool areaWeighted = false);

/// The merge tree behind combinePartitions: the atoms and every average-linkage merge, in order, so
/// that the consensus at any count is a cut of one tree (cutConsensusHierarchy).
struct ConsensusHierarchy
{
  std::vector<int> atomOfFace;            ///< per face, its atom, numbered by first face
  int atoms = 0;                          ///< connected groups of faces that every partition keeps together
  std::vector<std::array<int, 2>> merges; ///< per merge (a, b), a < b: the group of atom b joins that of atom a
  std::vector<double> linkages;           ///< the mean co-association of each merge's two groups
};

/// combinePartitions' atoms and linkage, merging until `lowestCount` groups remain or no two
/// groups share an edge (one group per dual-graph component): a group is named by its least atom.
/// Throws as combinePartitions does, with lowestCount for k.
ConsensusHierarchy consensusHierarchy(
  const FaceGraph& graph, const std::vector<WeightedPartition>& partitions, bool areaWeighted, int lowestCount = 1);

/// The consensus in at most k segments from a hierarchy: its first atoms - k merges (all of them
/// when it has fewer), made at most k and numbered by first face as combinePartitions does; equal
/// to combinePartitions at k whenever the hierarchy was merged down to k or below (above k, the
/// groups left are merged as finalizeSegments merges; never fewer segments than the dual graph
/// has components). More segments than atoms cannot be cut: k above the atoms gives the atoms.
/// Linear in the faces. Throws kerf::Error for k out of range, a hierarchy of another number of
/// faces, or one whose atoms or merges are out of range.
PartitionConsensus cutConsensusHierarchy(const FaceGraph& graph, const ConsensusHierarchy& hierarchy, int k);

struct EnsembleSegmentationOptions
{
  /// The members' votes (0 leaves a member out). Defaults: 1 each for consensus cuts, spectral
  /// clustering, convex flooding, k-means and the watershed; 0 for face clustering, which lowered
  /// the ensemble's accuracy on the Princeton benchmark (AutomaticSegmentation.md).
  double consensusCutsWeight = 1.0;
  double spectralWeight = 1.0;
  double convexFloodingWeight = 1.0;
  double kMeansWeight = 1.0;
  double watershedWeight = 1.0;
  double faceClusteringWeight = 0.0;
  /// Core extraction votes with its own number of parts (not k). Default 0: see
  /// AutomaticSegmentation.md for what it did to the ensemble on the Princeton benchmark.
  double coreExtractionWeight = 0.0;
  /// segmentByEnsembleChoosingCount only: a component whose vertices all lie within this fraction
  /// of its bounding box's diagonal from its convex hull (largestHullDepthFraction) has no parts to
  /// find and stays one segment: a sphere, a planar patch, a box. Default 0.01, a third of the
  /// least of the Princeton benchmark's psb-dev models (0.032); 0 gives every component a count in
  /// the range.
  double convexTolerance = 0.01;
  /// Faces weigh by their area in the linkage instead of once each. Default false.
  bool areaWeighted = false;
  /// The consensus's boundaries re-cut within a band (refineSegmentBoundaries, its defaults);
  /// bandWidth 0 leaves them as the linkage drew them.
  BoundaryRefinementOptions refinement;
  /// Each member's own options (their defaults; the segment count is the ensemble's k).
  ConsensusCutOptions consensusCuts;
  SpectralSegmentationOptions spectral;
  ConvexFloodingOptions convexFlooding;
  KMeansSegmentationOptions kMeans;
  WatershedOptions watershed;
  HierarchicalClusteringOptions faceClustering;
  CoreExtractionOptions coreExtraction;
};

struct EnsembleSegmentationResult
{
  std::vector<int> labels; ///< per face, numbered by first face
  int members = 0;         ///< segmentations that voted
  int atoms = 0;           ///< over all components
  int segmentCount = 0;    ///< segments in labels
  /// segmentByEnsembleChoosingCount on a connected surface: per count from the lowest scored (the
  /// minimum, or the faces if fewer) up, the mean 1 - Rand index of the ensemble at that count
  /// against every member at every count (the smallest was chosen); empty otherwise.
  std::vector<double> countScores;
  double countScore = 0.0; ///< the chosen count's entry of countScores (0 when countScores is empty)
};

/// Ensemble segmentation: each member with a positive weight segments the surface into k parts
/// with its own options, combinePartitions joins their votes, and refineSegmentBoundaries moves the
/// joined segments' boundaries onto nearby short, concave ways (unless options.refinement's band
/// is 0). Each dual-graph component is segmented apart with its share of k (segmentComponents). Deterministic. Throws
/// kerf::Error for k < 1, k > faces, a surface that is not edge-manifold and consistently oriented, weights out of
/// range, or whatever a member refuses.
EnsembleSegmentationResult segmentByEnsemble(const Surface& surface, int k, const EnsembleSegmentationOptions& options);

/// segmentByEnsembleChoosingCount chooses among at most this many counts.
constexpr int MaximumCountsToChoose = 40;

/// Ensemble segmentation that chooses the number of segments itself, among minimumCount to
/// maximumCount: the ensemble is run at each count, and the count whose partition has the least
/// mean 1 - Rand index against the members' partitions at all the counts wins (a median partition
/// of every member at every count; the smaller count on a tie). The range is clipped to each
/// component's faces (a component of 3 faces with the range 5 to 11 is scored at 3 only).
/// Each component of a surface with several chooses its own count in the range (a component of a
/// single face stays one segment), so the surface can have up to components x maximumCount
/// segments. A component within options.convexTolerance of its convex hull is one segment and
/// costs only that test. Defaults 5 and 11: on the Princeton benchmark's psb-dev models the choice scored best
/// there and worse with 4 or 10 (Documentation/filters/AutomaticSegmentation.md). Costs the
/// ensemble's time once per count. Deterministic. Throws kerf::Error for a surface without faces,
/// minimumCount < 2, maximumCount < minimumCount, maximumCount above the surface's faces, more
/// than MaximumCountsToChoose counts, a convexTolerance outside [0, 1), and what segmentByEnsemble
/// refuses.
EnsembleSegmentationResult segmentByEnsembleChoosingCount(
  const Surface& surface, int minimumCount, int maximumCount, const EnsembleSegmentationOptions& options);

/// One ensemble for every count: each member segments the surface at every count from minimumCount
/// to maximumCount (each dual-graph component with its share of the count, as segmentByEnsemble
/// shares k), and all those segmentations vote in one co-association, whose average-linkage merge
/// tree (consensusHierarchy, merged down to one group per component) is cut at any count by
/// cutEnsembleHierarchy. Fred and Jain 2005 (section 3) pool partitions of several counts in the same
/// way. Costs the members' time once per count; a new count then costs a cut and the boundary
/// refinement. Deterministic.
struct EnsembleHierarchy
{
  ConsensusHierarchy consensus;
  int members = 0;      ///< the segmentations that voted (the members at all the counts)
  int minimumCount = 0; ///< the counts the members ran at
  int maximumCount = 0;
  /// Per count from minimumCount up, the mean 1 - Rand index of the cut at that count (with the
  /// options' refinement) against every member at every count; empty for a connected surface
  /// within options.convexTolerance of its convex hull.
  std::vector<double> countScores;
  /// The count of least score (the smaller on a tie), or 1 where countScores is empty: the count
  /// the hierarchy chooses itself, as segmentByEnsembleChoosingCount does among its ensembles.
  int chosenCount = 1;
  /// The refined cuts that were scored, per count from minimumCount up (empty with countScores),
  /// and the refinement they were made with: cutEnsembleHierarchy hands them out again.
  std::vector<std::vector<int>> refinedCuts;
  BoundaryRefinementOptions refinedWith;
};

/// Builds the hierarchy and scores its cuts at the counts it ran at (countScores). Throws
/// kerf::Error for a surface without faces, minimumCount < 2, maximumCount < minimumCount,
/// maximumCount above the surface's faces, more than MaximumCountsToChoose counts, a
/// convexTolerance outside [0, 1), and what segmentByEnsemble refuses.
EnsembleHierarchy ensembleHierarchy(
  const Surface& surface, int minimumCount, int maximumCount, const EnsembleSegmentationOptions& options);

/// The hierarchy cut into k segments (cutConsensusHierarchy; k above the atoms gives the atoms, so
/// segmentCount says how many there are) and the boundaries refined (refineSegmentBoundaries with
/// `refinement`; a count the hierarchy scored, with the refinement it was scored with, is its
/// kept cut, the same labels without the work; a band of 0 keeps the tree's boundaries, which are
/// then nested: each count's segments are unions of the next count's). The hierarchy must be one
/// built on this surface: only one of another number of faces, or whose atoms or merges are out
/// of range, can be told apart. Throws kerf::Error for k out of range, refinement options
/// refineSegmentBoundaries refuses, or such a hierarchy.
EnsembleSegmentationResult cutEnsembleHierarchy(
  const Surface& surface, const EnsembleHierarchy& hierarchy, int k, const BoundaryRefinementOptions& refinement);

} // namespace kerf
