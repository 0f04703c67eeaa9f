// The Princeton benchmark's segmentation metrics (Chen et al. 2009): cut discrepancy, Hamming
// distance, Rand index and consistency errors between two per-face segmentations of one mesh.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// A segmentation made ready for comparisons: compact labels, its cut and the distance to it.
struct PreparedSegmentation
{
  std::vector<int> labels;         ///< per face, 0..segmentCount-1, or -1 for unlabelled
  std::vector<int> originalLabels; ///< the input label of each compact label
  int segmentCount = 0;
  std::vector<int> cutVertices;      ///< vertices on an edge between two differently labelled faces
  std::vector<double> distanceToCut; ///< per vertex, edge-graph distance to the cut (empty if none)
};

/// Every metric between a segmentation S1 (evaluated) and a reference S2 (ground truth).
/// Lower is better for all of them; 0 for identical segmentations.
struct SegmentationScores
{
  /// (DCD(S1 => S2) + DCD(S2 => S1)) / average radius, where DCD(A => B) is the mean edge-graph
  /// distance from A's cut vertices to B's cut. 0 when either segmentation has no cut (the
  /// benchmark's convention), which `cutsCompared` reports.
  double cutDiscrepancy = 0.0;
  double directionalCutDiscrepancy12 = 0.0; ///< DCD(S1 => S2) / average radius
  double directionalCutDiscrepancy21 = 0.0; ///< DCD(S2 => S1) / average radius
  bool cutsCompared = false;
  /// Area-weighted Hamming distance (Rm + Rf) / 2 with the missing rate Rm = D_H(S1 => S2) / A
  /// and the false-alarm rate Rf = D_H(S2 => S1) / A.
  double hammingDistance = 0.0;
  double missingRate = 0.0;
  double falseAlarmRate = 0.0;
  /// 1 - Rand index over unordered face pairs (face counts, as the benchmark computes it).
  double randIndexError = 0.0;
  /// Area-weighted global and local consistency errors.
  double globalConsistencyError = 0.0;
  double localConsistencyError = 0.0;
  int segments1 = 0;
  int segments2 = 0;
  int comparedFaces = 0; ///< faces labelled in both segmentations
};

/// Compares segmentations of one mesh. Construct once per mesh; prepare each segmentation once
/// (one Dijkstra from its cut); then each comparison costs O(F + k1 k2 + cut vertices).
///
/// Label -1 marks an unlabelled face: such faces are left out of the region metrics (areas and
/// face pairs count only faces labelled in both segmentations) and their edges are not cuts.
/// Labels need not be contiguous or in the same order in both segmentations.
class SegmentationEvaluator
{
public:
  explicit SegmentationEvaluator(const TriangleMesh& mesh);

  /// Throws kerf::Error if `labels` does not have one entry per face or uses a negative label
  /// other than -1.
  PreparedSegmentation prepare(const std::vector<int>& labels) const;

  SegmentationScores compare(const PreparedSegmentation& evaluated, const PreparedSegmentation& reference) const;

  /// Mean distance from the vertices used by triangles to their centroid.
  double averageRadius() const { return this->AverageRadius; }
  const std::vector<double>& faceAreas() const { return this->FaceAreas; }

private:
  const TriangleMesh& Mesh;
  std::vector<double> FaceAreas;
  double AverageRadius = 0.0;
};

/// Renumbers `labels` so that each segment takes the label of the reference segment it overlaps
/// most (by face count), largest segments first and each reference label at most once; the
/// others get labels above the reference's largest. Comparisons do not need this (the metrics
/// ignore label values); pictures do, so that matching segments get the same colour.
std::vector<int> matchLabels(const std::vector<int>& labels, const std::vector<int>& reference);

/// One comparison, for convenience.
SegmentationScores compareSegmentations(
  const TriangleMesh& mesh, const std::vector<int>& evaluated, const std::vector<int>& reference);

} // namespace kerf
