// Ear-clipping triangulation: counts, areas and orientation of convex and concave polygons.
#include "Mesh/Triangulation.h"

#include <gtest/gtest.h>

using namespace kerf;

namespace
{
PolygonMesh polygon(const std::vector<Vector3>& points)
{
  PolygonMesh mesh;
  mesh.points = points;
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
  {
    mesh.polygonIndices.push_back(i);
  }
  mesh.polygonOffsets.push_back(static_cast<int>(points.size()));
  return mesh;
}

Vector3 areaVector(const PolygonMesh& mesh, const Triangle& t)
{
  return 0.5 * (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]);
}
} // namespace

TEST(Triangulation, TrianglesAreKept)
{
  const PolygonMesh mesh = polygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } });
  const Triangulation t = triangulatePolygons(mesh);
  EXPECT_TRUE(t.allTriangles);
  ASSERT_EQ(t.triangles.size(), 1u);
  EXPECT_EQ(t.triangles[0], (Triangle{ 0, 1, 2 }));
}

TEST(Triangulation, ConcavePolygonKeepsAreaAndOrientation)
{
  // An L-shaped hexagon of area 3, tilted out of the xy plane.
  std::vector<Vector3> points = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 1, 1, 0 }, { 1, 2, 0 }, { 0, 2, 0 } };
  for (Vector3& p : points)
  {
    p = Vector3(p.x(), p.y() * 0.6, p.y() * 0.8);
  }
  const PolygonMesh mesh = polygon(points);
  const Triangulation t = triangulatePolygons(mesh);
  EXPECT_FALSE(t.allTriangles);
  ASSERT_EQ(t.triangles.size(), 4u);
  Vector3 total = Vector3::Zero();
  const Vector3 normal = Vector3(0, -0.8, 0.6);
  for (const Triangle& tri : t.triangles)
  {
    const Vector3 a = areaVector(mesh, tri);
    EXPECT_GT(a.dot(normal), 0.0) << "a triangle is flipped";
    total += a;
  }
  EXPECT_NEAR(total.norm(), 3.0, 1e-12);
  for (int source : t.sourcePolygon)
  {
    EXPECT_EQ(source, 0);
  }
}

TEST(Triangulation, MixedPolygonsMapToTheirSource)
{
  PolygonMesh mesh;
  mesh.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 2, 0, 0 } };
  mesh.polygonIndices = { 0, 1, 2, 3, 1, 4, 2 };
  mesh.polygonOffsets = { 0, 4, 7 };
  const Triangulation t = triangulatePolygons(mesh);
  ASSERT_EQ(t.triangles.size(), 3u);
  EXPECT_EQ(t.sourcePolygon, (std::vector<int>{ 0, 0, 1 }));
}

TEST(Triangulation, DegeneratePolygonFallsBackToAFan)
{
  // All corners on a line: no ear exists; the fan still gives n - 2 triangles.
  const PolygonMesh mesh = polygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 } });
  const Triangulation t = triangulatePolygons(mesh);
  EXPECT_EQ(t.triangles.size(), 2u);
}
