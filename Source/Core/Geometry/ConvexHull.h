// The convex hull of a point set in 3D (incremental construction), each point's depth below it and the deepest.
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

/// How far a point set reaches inside its convex hull: the largest hullDepths of the points,
/// divided by the diagonal of their bounding box (0 for a convex or flat set, about 0.03 to 0.2
/// for the Princeton benchmark's objects). Above `maximumSamples` points, every s-th point in index
/// order (s = ceil(n / maximumSamples)) stands for the set, so the cost stays that of a hull of
/// `maximumSamples` points. Deterministic. 0 for fewer than four points or a set of one point.
/// Throws kerf::Error for a non-finite point or maximumSamples < 4.
double largestHullDepthFraction(const std::vector<Vector3>& points, int maximumSamples);

} // namespace kerf
