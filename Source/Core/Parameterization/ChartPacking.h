// Laying charts out in the unit square: convex hull, minimal-area bounding box, shelf packing of boxes, overlap count.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <Eigen/Core>

#include <vector>

namespace kerf
{

using Vector2 = Eigen::Vector2d;

/// Convex hull of points, counter-clockwise from the lowest-then-leftmost point, without
/// collinear points (Andrew's monotone chain).
std::vector<Vector2> convexHull(std::vector<Vector2> points);

/// Angle by which to turn `points` so that their axis-aligned bounding box has the least area
/// (rotating calipers over the convex hull's edges; Toussaint 1983) and is at least as wide as tall.
double minimalBoundingBoxRotation(const std::vector<Vector2>& points);

/// Axis-aligned boxes (width, height) placed on shelves in a square of side 1 with `margin`
/// between boxes and to the border: the tallest first, left to right, at the least square side
/// found by a search in steps of 1%, then scaled to side 1. Returns each box's lower-left corner
/// in the unit square and sets `scale` to the factor that maps the boxes' units to the unit
/// square. Throws kerf::Error for a margin outside [0, 0.25] or a box with a non-finite or
/// negative size.
std::vector<Vector2> packBoxes(const std::vector<Vector2>& sizes, double margin, double& scale);

/// Number of pairs of charts (faceChart: each triangle's chart) whose triangles cover a common
/// sample of a resolution x resolution grid over the unit square (a sample at each texel's
/// centre, strictly inside a triangle). Throws kerf::Error for a resolution outside [1, 65536].
int countChartOverlaps(const std::vector<Vector2>& uv, const std::vector<Triangle>& triangles,
  const std::vector<int>& faceChart, int resolution);

} // namespace kerf
