// Splits polygons into triangles (ear clipping in each polygon's best-fit plane).
#pragma once

#include "Mesh/PolygonMesh.h"

#include <vector>

namespace kerf
{

/// Triangles of a polygon mesh and, for each, the polygon it came from.
struct Triangulation
{
  std::vector<Triangle> triangles;
  std::vector<int> sourcePolygon;
  bool allTriangles = true; ///< true when every polygon already was a triangle
};

/// Triangulates every polygon: triangles are kept as they are; larger polygons are projected
/// onto their Newell plane and split by ear clipping, which is exact for simple polygons and
/// keeps the polygon's orientation. Polygons that are not simple fall back to a fan. Throws
/// kerf::Error if a polygon uses an index outside the points.
Triangulation triangulatePolygons(const PolygonMesh& mesh);

} // namespace kerf
