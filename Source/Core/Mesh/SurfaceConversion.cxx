// Polygon meshes to welded triangle meshes.
#include "Mesh/SurfaceConversion.h"

#include "Mesh/PointWelding.h"
#include "Mesh/Triangulation.h"

namespace kerf
{

ConvertedPolygons convertPolygons(PolygonMesh polygons)
{
  ConvertedPolygons converted;
  Triangulation triangulation = triangulatePolygons(polygons);
  converted.allTriangles = triangulation.allTriangles;
  converted.sourcePolygon = std::move(triangulation.sourcePolygon);
  TriangleMesh::checkIndices(triangulation.triangles, static_cast<int>(polygons.points.size()));
  converted.representatives = findCoincidentPoints(polygons.points);
  for (std::size_t i = 0; i < converted.representatives.size(); ++i)
  {
    converted.welded += converted.representatives[i] != static_cast<int>(i) ? 1 : 0;
  }
  weldTriangles(converted.representatives, triangulation.triangles);
  converted.mesh = TriangleMesh(std::move(polygons.points), std::move(triangulation.triangles));
  return converted;
}

} // namespace kerf
