// Connected regions of triangles: faces joined across the edges a caller lets them cross.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <functional>
#include <vector>

namespace kerf
{

/// Labels the triangles by connected regions: a face and its neighbour across side k (the
/// manifold edge from corner k to k+1) share a region when `crossable(face, k)` is true.
/// Regions are numbered 0, 1, ... in order of their lowest face; returns their number.
int labelFaceRegions(
  const TriangleMesh& mesh, const std::function<bool(int face, int side)>& crossable, std::vector<int>& labels);

} // namespace kerf
