// Simulated user input made from a segmentation, for benchmarking interactive methods.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// A stroke drawn along the boundary between two segments.
struct BoundaryStroke
{
  int label1 = -1; ///< the smaller of the two labels
  int label2 = -1;
  std::vector<Vector3> points;
};

/// One stroke along each boundary between two segments of a per-face segmentation: for every
/// pair of labels whose faces share edges, each chain of those edges (a handle attached at two
/// places has two) at least a quarter of `spacing` long (a user strokes a thin leg too), walked
/// from an end (or around, if it is a loop) and resampled by arc length to points about
/// `spacing` apart (at least 4, at most 64). Where a jagged boundary branches (a vertex with more than two of the
/// pair's edges) the walk goes on one way and the edges it leaves become strokes of their own, so every boundary edge
/// is stroked. Unlabelled faces (-1) have no boundary. Strokes are ordered by label pair and then by their first edge,
/// so the result is deterministic.
std::vector<BoundaryStroke> boundaryStrokes(const TriangleMesh& mesh, const std::vector<int>& labels, double spacing);

/// A stroke drawn inside one segment.
struct SegmentStroke
{
  int label = -1;
  std::vector<Vector3> points;
};

/// One stroke per segment of a per-face segmentation, as a user strokes along a part: its points
/// are the centroids of the segment's spine (kerf::segmentSpines, the longest path through the
/// faces at least `depth` times as far inside as its innermost face). Strokes come in label order;
/// unlabelled faces (-1) get none. Throws kerf::Error for a labelling of the wrong size or a depth
/// outside (0, 1].
std::vector<SegmentStroke> innermostStrokes(const TriangleMesh& mesh, const std::vector<int>& labels, double depth);

} // namespace kerf
