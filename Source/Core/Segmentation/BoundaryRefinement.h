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
  int movedFaces = 0;      ///< faces whose segment changed (before the final clean-up)
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
/// whose band swallows one of its segments whole keeps its boundary. The result is cleaned up like
/// every method's (finalizeSegments): connected segments, at most k = the number of input labels.
/// `labels` must number segments 0..k-1, each face labelled. Deterministic. Throws kerf::Error for
/// labels of another size or negative, or a negative or non-finite band or weight.
BoundaryRefinementResult refineSegmentBoundaries(
  const FaceGraph& graph, const std::vector<int>& labels, const BoundaryRefinementOptions& options);

} // namespace kerf
