// A polygon mesh made into the triangle mesh Kerf computes on: triangulated, coincident points welded.
#pragma once

#include "Mesh/PolygonMesh.h"
#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// The triangle mesh made from a polygon mesh, and the maps back to it.
struct ConvertedPolygons
{
  TriangleMesh mesh;
  std::vector<int> sourcePolygon;   ///< the polygon each triangle came from
  std::vector<int> representatives; ///< per point, the point it was welded onto (itself if unique)
  int welded = 0;                   ///< points welded onto an earlier point
  bool allTriangles = true;         ///< every polygon already was a triangle
};

/// Triangulates the polygons (triangulatePolygons) and welds points with identical coordinates
/// (findCoincidentPoints): readers split OBJ files at texture seams and STL files at every
/// facet, and welding restores the surface's connectivity. Every input point stays a vertex of
/// the mesh (welded and unreferenced ones are used by no triangle). Throws kerf::Error for an
/// index outside the points.
ConvertedPolygons convertPolygons(PolygonMesh polygons);

} // namespace kerf
