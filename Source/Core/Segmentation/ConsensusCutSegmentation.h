// Consensus cuts: automatic segmentation from the isolines of many concavity-aware harmonic fields between feature
// points.
#pragma once

#include "Numerics/LaplacianWeights.h"
#include "Segmentation/FaceGraph.h"

#include <vector>

namespace kerf
{

class Surface;

struct ConsensusCutOptions
{
  /// The Laplacian the fields are harmonic for. Default ConcavityAware (Au et al. 2011): a field
  /// drops fastest across concave creases, so its isolines gather there.
  LaplacianWeighting weighting = LaplacianWeighting::ConcavityAware;
  /// Feature points: k + this many, found by farthest-point sampling along the edges (the first
  /// ones are the shape's extremities). Default 8.
  int extraFeaturePoints = 8;
  /// Never more feature points than this (every pair gives a field, so fields grow as its
  /// square). Default 16: on psb-dev it binds on models with k above 8, and against 20 it leaves
  /// the mean 1 - Rand index as it was (0.1755 against 0.1759) with 120 fields instead of 190.
  int maximumFeaturePoints = 16;
  /// Isovalues sampled in each field (ROI Scissor's score for each). Default 48.
  int isovaluesPerField = 48;
  /// Score peaks taken from each field, the strongest first. Default 4.
  int peaksPerField = 4;
  /// Each field is clipped to these quantiles of its vertex values, below and above, so that
  /// the logarithmic peaks at its two feature points do not take the isovalues. Default 0.02.
  double clipQuantile = 0.02;
  /// Candidate cuts are the same cut when their smaller sides differ by less than this fraction
  /// of the smaller of the two areas. Default 0.3.
  double sameCutTolerance = 0.3;
  /// A cut is refused when it would leave a segment smaller than this fraction of the area.
  /// Default 0.01.
  double minimumSegmentArea = 0.01;
  /// A candidate's score is ROI Scissor's isoline score times (isoline length)^this. With unit
  /// current the score alone is the inverse of the cut's conductance, high on thin parts as well
  /// as on concave creases; times the length it is the mean resistance per unit length, which
  /// only concavity raises. Default 0.5, between the two.
  double lengthExponent = 0.5;
  /// ... and times (the area it splits off / the total area)^this, so that parts of the size
  /// people name come before small tips. Default 0.25.
  double areaExponent = 0.25;
  /// A consensus cut ranks by its best score times (fields that found it)^this. Default 0.5.
  double voteExponent = 0.5;
  /// Boundary refinement by random walks: each segment's spine through its faces at least this
  /// fraction as deep as its innermost one (kerf::segmentSpines) seeds random walks on the same
  /// Laplacian (kerf::randomWalkLabels), which move the cuts onto the concave creases near them.
  /// 0 turns it off. Default 0.3.
  double walkDepth = 0.3;
};

struct ConsensusCutResult
{
  std::vector<int> labels; ///< per face, numbered by first face
  int featurePoints = 0;
  int fields = 0;
  int candidates = 0;    ///< candidate cuts (isoline components at score peaks)
  int consensusCuts = 0; ///< distinct cuts after grouping the candidates
  int chosenCuts = 0;
  /// Faces whose label the random walks changed (before the final clean-up).
  int walkedFaces = 0;
};

/// Consensus cuts. (1) Feature points by farthest-point sampling. (2) One factorization of the
/// concavity-aware Laplacian, grounded at one vertex; the potential G_i of a unit source at each
/// feature point (one back-substitution each); every pair's field f_ij = G_i - G_j carries a unit
/// current from i to j, so its gradient along an isoline is large where the isoline is short and
/// crosses low-conductance (concave) edges: ROI Scissor's isoline score (section 4.2) is then
/// comparable across fields. (3) In each field the isovalues whose score is a local maximum give
/// candidate cuts, one per isoline component that splits the surface. (4) Candidates that split it
/// the same way are one consensus cut, ranked by its best score and the number of fields that
/// found it. (5) The best cuts are taken in turn, skipping those that would leave a segment below
/// the minimum area or make more than k segments, until k segments exist; then segments are made
/// connected and at most k (finalizeSegments). (6) With a walk depth above 0, each segment's spine
/// seeds multi-label random walks on the same weights (Lai et al. 2009), every face takes its most
/// probable segment, and the clean-up runs again. Each dual-graph component is segmented apart with
/// its share of k (segmentComponents). Deterministic. Throws kerf::Error for k < 1, k > faces,
/// a surface that is not edge-manifold and consistently oriented, or options out of range.
ConsensusCutResult segmentByConsensusCuts(const Surface& surface, int k, const ConsensusCutOptions& options);

} // namespace kerf
