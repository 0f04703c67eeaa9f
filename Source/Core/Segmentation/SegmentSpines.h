// Segment spines: the longest path through each segment's innermost faces, where a user strokes along a part.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// A path of faces inside one segment.
struct SegmentSpine
{
  int label = -1;
  std::vector<int> faces; ///< neighbours in turn
};

/// One spine per segment of a per-face segmentation, made of its innermost faces: distances
/// inside the segment are measured from its faces that border another label (along the
/// segment's faces, centroid to centroid); the spine is the longest path (two sweeps of Dijkstra,
/// centroid to centroid) through the faces at least `depth` (a fraction in (0, 1]) times as far
/// inside as the innermost face, among those the innermost face reaches through them. A segment
/// without a border (a whole component) gets its lowest-numbered face. Spines come in label
/// order; unlabelled faces (-1) get none. Throws kerf::Error for a labelling of the wrong size or
/// a depth outside (0, 1].
std::vector<SegmentSpine> segmentSpines(const TriangleMesh& mesh, const std::vector<int>& labels, double depth);

} // namespace kerf
