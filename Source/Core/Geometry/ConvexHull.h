// The convex hull of a point set in 3D (incremental construction) and each point's depth below it.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// A convex polytope as outward-oriented triangles over the input's point indices.
struct ConvexHull
{
  std::vector<Triangle> faces;  ///< counter-clockwise seen from outside
  std::vector<Vector3> normals; ///< unit outward normal per face
  std::vector<double> offsets;  ///< normal . x = offset on each face's plane
  /// True when the points span less than a volume (all within the tolerance of one plane, or
  /// fewer than four points): `faces` is then empty and every point counts as on the hull.
  bool flat = false;
};

/// The convex hull of `points` (Clarkson and Shor 1989's incremental construction, points taken in
/// index order after an initial tetrahedron of extreme points): a point within `tolerance` of the
/// current hull's planes is taken as inside, so nearly coplanar points do not make slivers.
/// Deterministic. Cost O(n h) for h hull faces, meant for hundreds to a few thousand points.
/// Throws kerf::Error for a non-finite point or a negative or non-finite tolerance.
ConvexHull convexHull(const std::vector<Vector3>& points, double tolerance);

/// Per point, how far it lies inside the hull: the smallest distance to a face's plane (0 for a
/// hull vertex, about 0 for a point on a face, larger inside; 0 everywhere for a flat hull).
std::vector<double> hullDepths(const ConvexHull& hull, const std::vector<Vector3>& points);

} // namespace kerf
