// Polylines placed on a surface: isolines kept as they are, sparse strokes followed across triangles, bad input.
#include "Error.h"
#include "Geodesic/SurfaceLocation.h"
#include "Harmonic/Isolines.h"
#include "Mesh/MeshGenerators.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

using namespace kerf;

namespace
{
constexpr double Pi = 3.14159265358979323846;
const double NoLimit = std::numeric_limits<double>::infinity();

// Every segment lies in the triangle holding it: both ends within `tolerance` of its plane and
// inside it (barycentric coordinates >= -tolerance).
void expectSegmentsInTheirFaces(const TriangleMesh& mesh, const SurfaceCurve& curve, double tolerance)
{
  const int segments = segmentCount(curve);
  ASSERT_EQ(static_cast<int>(curve.faces.size()), segments);
  for (int i = 0; i < segments; ++i)
  {
    for (const Vector3& p : { curve.points[i], curve.points[(i + 1) % curve.points.size()] })
    {
      SurfacePoint inFace;
      inFace.face = curve.faces[i];
      inFace.barycentric = barycentricInFace(mesh, inFace.face, p);
      EXPECT_GE(inFace.barycentric.minCoeff(), -tolerance) << "segment " << i;
      EXPECT_LE((surfacePosition(mesh, inFace) - p).norm(), tolerance) << "segment " << i;
    }
  }
}
} // namespace

TEST(SurfaceLocation, IsolinePointsKeepTheirTriangles)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 4));
  const TriangleMesh& mesh = surface->mesh();
  std::vector<double> height(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    height[v] = mesh.point(v).z() + 0.3 * mesh.point(v).x();
  }
  const Isoline isoline = extractIsolines(mesh, height, 0.2).at(0);
  const SurfaceCurve curve = placeCurveOnSurface(*surface, isoline.points, true, 1e-9, "the isoline");
  // Consecutive points of an isoline share a triangle: no point is added.
  ASSERT_EQ(curve.points.size(), isoline.points.size());
  for (std::size_t i = 0; i < curve.points.size(); ++i)
  {
    EXPECT_LE((curve.points[i] - isoline.points[i]).norm(), 1e-12);
  }
  // The triangle found for each segment holds both its ends (an isoline segment's own triangle,
  // or the neighbour across the edge when the segment runs along it).
  expectSegmentsInTheirFaces(mesh, curve, 1e-9);
  GeodesicSource source;
  source.curves = { curve };
  EXPECT_NO_THROW(checkGeodesicSource(mesh, source));
}

TEST(SurfaceLocation, SparseStrokeIsFollowedAcrossTriangles)
{
  // Six points on the unit sphere's equator, a closed stroke: the curve crosses every triangle
  // between them, its points stay on the triangles, and it stays near the equator.
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 4));
  const TriangleMesh& mesh = surface->mesh();
  std::vector<Vector3> stroke;
  for (int k = 0; k < 6; ++k)
  {
    stroke.emplace_back(std::cos(k * Pi / 3.0), std::sin(k * Pi / 3.0), 0.0);
  }
  const SurfaceCurve curve = placeCurveOnSurface(*surface, stroke, true, 0.05, "the stroke");
  EXPECT_TRUE(curve.closed);
  EXPECT_GT(curve.points.size(), 60u);
  expectSegmentsInTheirFaces(mesh, curve, 1e-9);
  double length = 0.0;
  for (std::size_t i = 0; i < curve.points.size(); ++i)
  {
    EXPECT_LE(std::abs(curve.points[i].z()), 0.01);
    length += (curve.points[(i + 1) % curve.points.size()] - curve.points[i]).norm();
  }
  // The polyhedral equator is a little shorter than the circle.
  EXPECT_NEAR(length, 2.0 * Pi, 0.01 * 2.0 * Pi);
  GeodesicSource source;
  source.curves = { curve };
  EXPECT_NO_THROW(checkGeodesicSource(mesh, source));
}

TEST(SurfaceLocation, ProjectionAndCoincidentVertices)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 2));
  const TriangleMesh& mesh = surface->mesh();
  const SurfacePoint atVertex = projectOntoSurface(*surface, mesh.point(17), 1e-9, "the point");
  EXPECT_EQ(coincidentVertex(mesh, atVertex), 17);
  EXPECT_GE(facesHolding(mesh, atVertex).size(), 5u);
  const SurfacePoint inside =
    projectOntoSurface(*surface, surfacePosition(mesh, { 3, Vector3(0.2, 0.3, 0.5) }), 1e-9, "the point");
  EXPECT_EQ(coincidentVertex(mesh, inside), -1);
  EXPECT_EQ(facesHolding(mesh, inside), std::vector<int>{ 3 });
  try
  {
    projectOntoSurface(*surface, Vector3(0, 0, 2), 0.1, "click 2");
    ADD_FAILURE() << "a point off the surface is refused";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("click 2 lies off the surface"), std::string::npos) << e.what();
  }
  EXPECT_THROW(projectOntoSurface(*surface, Vector3(std::nan(""), 0, 0), NoLimit, "p"), Error);
}

TEST(SurfaceLocation, RefusesBadPolylines)
{
  // Two spheres: a segment from one to the other joins two components.
  const TriangleMesh one = makeIcosphere(1.0, 2);
  std::vector<Vector3> points = one.points();
  std::vector<Triangle> triangles = one.triangles();
  for (const Vector3& p : one.points())
  {
    points.push_back(p + Vector3(3, 0, 0));
  }
  for (const Triangle& t : one.triangles())
  {
    const int n = one.vertexCount();
    triangles.push_back({ t[0] + n, t[1] + n, t[2] + n });
  }
  const auto surface = std::make_shared<Surface>(TriangleMesh(points, triangles));
  EXPECT_THROW(placeCurveOnSurface(*surface, { Vector3(1, 0, 0), Vector3(2, 0, 0) }, false, NoLimit, "l"), Error);
  EXPECT_THROW(placeCurveOnSurface(*surface, { Vector3(1, 0, 0), Vector3(1, 0, 0) }, false, NoLimit, "l"), Error);
  EXPECT_THROW(placeCurveOnSurface(*surface, { Vector3(1, 0, 0), Vector3(0, 1, 0) }, true, NoLimit, "l"), Error);
  EXPECT_THROW(placeCurveOnSurface(*surface, { Vector3(1, 0, 0), Vector3(0, 0, 5) }, false, 0.1, "l"), Error);
  // A segment that meets the boundary of an open surface before its end.
  const auto grid = std::make_shared<Surface>(makeGrid(4, 4, 8, 8));
  std::vector<Triangle> holed;
  for (int f = 0; f < grid->mesh().faceCount(); ++f)
  {
    const Triangle& t = grid->mesh().triangle(f);
    const Vector3 centre = (grid->mesh().point(t[0]) + grid->mesh().point(t[1]) + grid->mesh().point(t[2])) / 3.0;
    if ((centre - Vector3(2, 2, 0)).norm() > 1.0)
    {
      holed.push_back(t);
    }
  }
  const auto withHole = std::make_shared<Surface>(TriangleMesh(grid->mesh().points(), holed));
  EXPECT_THROW(placeCurveOnSurface(*withHole, { Vector3(0.5, 2, 0), Vector3(3.5, 2, 0) }, false, NoLimit, "l"), Error);
  EXPECT_NO_THROW(placeCurveOnSurface(*withHole, { Vector3(0.5, 0.2, 0), Vector3(3.5, 0.3, 0) }, false, NoLimit, "l"));
}
