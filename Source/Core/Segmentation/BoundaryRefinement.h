// Boundary refinement of a face segmentation: each boundary moved by a minimum cut within a band around it.
#pragma once

#include "Segmentation/FaceGraph.h"

#include <vector>

namespace kerf
{

struct BoundaryRefinementOptions
{
  /// Half-width of the band around each boundary, as a fraction of the square root of the smaller
  /// of its two segments' areas (a scale-free length). 0 leaves the labels as they are. Default
  /// 0.4, the best of 0.25 to 0.5 for the ensemble on the Princeton benchmark (AutomaticSegmentation.md).
  double bandWidth = 0.4;
  /// How much a convex edge's bend counts against a concave one's in the cut's capacity (Katz
  /// and Tal 2003's eta). Default 0.1 (0.2 measured alike).
  double convexWeight = 0.1;
};

struct BoundaryRefinementResult
{
  std::vector<int> labels; ///< per face, numbered by first face
  int boundaries = 0;      ///< pairs of neighbouring segments whose boundary was re-cut
  int movedFaces = 0;      ///< faces the cuts gave to the other side (the clean-up's merges not counted)
};

/// Throws kerf::Error unless the band and the convex weight are finite and non-negative.
void checkBoundaryRefinementOptions(const BoundaryRefinementOptions& options);

/// Moves the boundaries of a segmentation to the short and concave ways nearby (the fuzzy-region
/// cut of Katz and Tal 2003): for each pair of neighbouring segments, in label order,
/// the faces of the two within `bandWidth` sqrt(min area) of their shared boundary (dual-graph
/// distance over centroid paths) are freed; faces of the two just outside the band hold the cut to
/// their sides; a minimum cut (Boykov and Kolmogorov 2004) gives the freed faces to one side or the
/// other, each dual edge cut costing its mesh edge's length over the mean, divided by 1 + its
/// angular distance over the mean (1 - cos of the bend, times `convexWeight` where convex). A pair
/// whose band swallows one of its segments whole keeps its boundary (the check is per pair: a piece
/// of a segment in several pieces that lies inside the band goes to the pair's larger label). The
/// pairs are those of the input labels; a contact an earlier cut creates is not re-cut. Where cuts
/// cost the same, the one nearest the smaller label's side is taken. The result is cleaned up like every method's
/// (finalizeSegments): connected segments, numbered by first face, at most as many as the input
/// has distinct labels (any non-negative numbers); with `bandWidth` 0 the labels are returned as
/// given. Cost: per pair, passes over all faces and dual edges and a Dijkstra search within the
/// band, O(pairs (n + E)) plus the cuts. Deterministic. Throws kerf::Error for labels of another
/// size or negative, or a negative or non-finite band or weight.
BoundaryRefinementResult refineSegmentBoundaries(
  const FaceGraph& graph, const std::vector<int>& labels, const BoundaryRefinementOptions& options);

} // namespace kerf
