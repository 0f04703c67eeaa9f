// Short-Term Vector Dijkstra, streamline paths and geodesic loops: lengths, exact ends, crossings, anisotropy.
#include "Error.h"
#include "Geodesic/GeodesicPaths.h"
#include "Geodesic/GraphDistance.h"
#include "Geodesic/SurfaceLocation.h"
#include "Geodesic/VectorDijkstra.h"
#include "Geometry/ClosestPoint.h"
#include "Mesh/MeshGenerators.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

using namespace kerf;

namespace
{
double greatCircle(const Vector3& a, const Vector3& b)
{
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

// Mean relative error of a distance field against great-circle distances from vertex s, beyond
// its one-ring.
double sphereMeanError(const TriangleMesh& sphere, const std::vector<double>& distance, int s)
{
  double sum = 0.0;
  int count = 0;
  const IndexRange ring = sphere.vertexNeighbors(s);
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    if (v == s || std::find(ring.begin(), ring.end(), v) != ring.end())
    {
      continue;
    }
    const double exact = greatCircle(sphere.point(v), sphere.point(s));
    sum += std::abs(distance[v] - exact) / exact;
    ++count;
  }
  return sum / count;
}

SurfacePoint pointNear(const TriangleMesh& mesh, const Vector3& p)
{
  const ClosestPointLocator locator(mesh);
  const ClosestPointLocator::Hit hit = locator.closest(p);
  SurfacePoint point;
  point.face = hit.face;
  point.barycentric = hit.barycentric;
  return point;
}

// Every point of a path lies on the triangle that holds its segments.
void expectOnSurface(const TriangleMesh& mesh, const SurfaceCurve& curve)
{
  const int segments = segmentCount(curve);
  ASSERT_EQ(static_cast<int>(curve.faces.size()), segments);
  for (int i = 0; i < segments; ++i)
  {
    const Triangle& t = mesh.triangle(curve.faces[i]);
    for (const Vector3& p : { curve.points[i], curve.points[(i + 1) % curve.points.size()] })
    {
      Vector3 barycentric;
      const Vector3 q = closestPointOnTriangle(p, mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), barycentric);
      EXPECT_LE((q - p).norm(), 1e-9);
    }
  }
}
} // namespace

TEST(VectorDijkstra, IsotropicSphereDistanceWithinOnePercent)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 5);
  const AnisotropicMetric euclidean = computeAnisotropicMetric(sphere, computeSurfaceDescriptors(sphere), {});
  GeodesicSource source;
  source.vertices = { 11 };
  const double vectorError = sphereMeanError(sphere, shortTermVectorDijkstra(sphere, euclidean, source).distance, 11);
  const double edgeError = sphereMeanError(sphere, edgeGraphDistances(sphere, { 11 }), 11);
  const double heatError = sphereMeanError(sphere, HeatGeodesics(sphere).compute(source).distance, 11);
  RecordProperty("VectorDijkstraMeanError", std::to_string(vectorError));
  RecordProperty("EdgeDijkstraMeanError", std::to_string(edgeError));
  EXPECT_LE(vectorError, 0.01);
  EXPECT_LE(heatError, 0.01);
  // Depth 3 removes most of plain Dijkstra's zig-zag.
  EXPECT_LE(vectorError, 0.5 * edgeError);
  VectorDijkstraOptions plain;
  plain.depth = 1;
  const std::vector<double> one = shortTermVectorDijkstra(sphere, euclidean, source, plain).distance;
  const std::vector<double> edges = edgeGraphDistances(sphere, { 11 });
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    EXPECT_NEAR(one[v], edges[v], 1e-12);
  }
}

TEST(VectorDijkstra, StopsSoonAfterItsTargets)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  const AnisotropicMetric euclidean = computeAnisotropicMetric(sphere, computeSurfaceDescriptors(sphere), {});
  GeodesicSource source;
  source.vertices = { 0 };
  const VectorDijkstraResult full = shortTermVectorDijkstra(sphere, euclidean, source);
  VectorDijkstraOptions options;
  options.targets = { 100 };
  const VectorDijkstraResult partial = shortTermVectorDijkstra(sphere, euclidean, source, options);
  int settled = 0;
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    if (std::isfinite(partial.distance[v]))
    {
      ++settled;
      EXPECT_EQ(partial.distance[v], full.distance[v]);
    }
  }
  EXPECT_TRUE(std::isfinite(partial.distance[100]));
  EXPECT_LT(settled, sphere.vertexCount());
}

TEST(GeodesicPaths, PathLengthMatchesDistanceAndEndsExactly)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 5));
  const TriangleMesh& sphere = surface->mesh();
  const SurfacePoint from = pointNear(sphere, Vector3(0.3, 0.2, 1.0).normalized());
  const SurfacePoint to = pointNear(sphere, Vector3(-0.5, 0.8, -0.4).normalized());
  const Vector3 a = surfacePosition(sphere, from), b = surfacePosition(sphere, to);
  for (int anisotropic = 0; anisotropic < 2; ++anisotropic)
  {
    GeodesicPathOptions options;
    GeodesicSource source;
    source.points = { from };
    double distanceAtEnd = 0.0;
    if (anisotropic)
    {
      // gamma = 0 through Short-Term Vector Dijkstra: the path's length against its field.
      options.vectorDijkstra = true;
      const AnisotropicMetric& metric = anisotropicMetric(*surface, options.metric);
      const VectorDijkstraResult field = shortTermVectorDijkstra(sphere, metric, source);
      const Triangle& t = sphere.triangle(to.face);
      distanceAtEnd = to.barycentric[0] * field.distance[t[0]] + to.barycentric[1] * field.distance[t[1]] +
        to.barycentric[2] * field.distance[t[2]];
    }
    else
    {
      const GeodesicDistance field = HeatGeodesics::of(*surface).compute(source);
      const Triangle& t = sphere.triangle(to.face);
      distanceAtEnd = to.barycentric[0] * field.distance[t[0]] + to.barycentric[1] * field.distance[t[1]] +
        to.barycentric[2] * field.distance[t[2]];
    }
    const SurfacePath path = shortestPath(*surface, from, to, options);
    EXPECT_EQ(path.curve.points.front(), a);
    EXPECT_EQ(path.curve.points.back(), b);
    expectOnSurface(sphere, path.curve);
    RecordProperty("PathLengthRatio" + std::to_string(anisotropic), std::to_string(path.length / distanceAtEnd));
    EXPECT_NEAR(path.length, distanceAtEnd, 0.01 * distanceAtEnd) << "anisotropic " << anisotropic;
    EXPECT_NEAR(path.length, greatCircle(a, b), 0.01 * greatCircle(a, b));
  }
}

TEST(GeodesicPaths, LoopIsClosedAndSimple)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 5));
  const TriangleMesh& sphere = surface->mesh();
  // Four points around the z axis at latitude 30 degrees, in order, then in a crossing order.
  std::vector<SurfacePoint> points;
  for (int i = 0; i < 4; ++i)
  {
    const double angle = 2.0 * 3.14159265358979323846 * (i + 0.1) / 4.0;
    points.push_back(pointNear(sphere, Vector3(std::cos(angle), std::sin(angle), 1.1547)));
  }
  const GeodesicLoop loop = geodesicLoop(*surface, points, GeodesicPathOptions());
  EXPECT_TRUE(loop.path.curve.closed);
  EXPECT_EQ(loop.path.curve.points.size(), loop.path.curve.faces.size());
  EXPECT_EQ(loop.selfCrossings, 0);
  expectOnSurface(sphere, loop.path.curve);
  // The loop passes exactly through every point.
  for (const SurfacePoint& p : points)
  {
    const Vector3 x = surfacePosition(sphere, p);
    EXPECT_NE(std::find(loop.path.curve.points.begin(), loop.path.curve.points.end(), x), loop.path.curve.points.end());
  }
  // Its length is the sum of four great-circle arcs.
  double expected = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    expected += greatCircle(surfacePosition(sphere, points[i]), surfacePosition(sphere, points[(i + 1) % 4]));
  }
  EXPECT_NEAR(loop.path.length, expected, 0.01 * expected);
  const GeodesicLoop bowTie =
    geodesicLoop(*surface, { points[0], points[2], points[1], points[3] }, GeodesicPathOptions());
  EXPECT_GE(bowTie.selfCrossings, 1);
}

TEST(GeodesicPaths, AnisotropicPathsFollowTheRidge)
{
  // A cylindrical ridge over [-3, 3] x [0, 6], z = 0.4 (1 + cos(pi x)) for |x| < 1 and flat
  // beyond: its minimum curvature direction is the axis y, its curvature strongest on the crest.
  const TriangleMesh grid = makeGrid(6.0, 6.0, 90, 90);
  std::vector<Vector3> points = grid.points();
  for (Vector3& p : points)
  {
    p.x() -= 3.0;
    p.z() = std::abs(p.x()) < 1.0 ? 0.4 * (1.0 + std::cos(3.14159265358979323846 * p.x())) : 0.0;
  }
  const auto surface = std::make_shared<Surface>(TriangleMesh(points, grid.triangles()));
  const TriangleMesh& ridge = surface->mesh();
  // Length-weighted mean |cos| between the path and the axis on the crest (|x| < 0.5).
  const auto axialAlignment = [&](const SurfacePath& path) {
    double aligned = 0.0, total = 0.0;
    const std::vector<Vector3>& p = path.curve.points;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
    {
      const Vector3 d = p[i + 1] - p[i];
      if (std::abs(0.5 * (p[i].x() + p[i + 1].x())) < 0.5 && d.norm() > 0.0)
      {
        aligned += std::abs(d.y());
        total += d.norm();
      }
    }
    return aligned / total;
  };
  double isotropicSum = 0.0, anisotropicSum = 0.0;
  const double starts[3][4] = { { -2.0, 1.0, 2.0, 5.0 }, { -2.5, 0.8, 1.5, 4.0 }, { 2.2, 1.2, -1.8, 5.2 } };
  for (const auto& s : starts)
  {
    const SurfacePoint from = pointNear(ridge, Vector3(s[0], s[1], 0.0));
    const SurfacePoint to = pointNear(ridge, Vector3(s[2], s[3], 0.0));
    GeodesicPathOptions isotropic;
    GeodesicPathOptions anisotropic;
    anisotropic.metric.gamma = 4.0;
    const double a = axialAlignment(shortestPath(*surface, from, to, isotropic));
    const double b = axialAlignment(shortestPath(*surface, from, to, anisotropic));
    RecordProperty(
      "Alignment" + std::to_string(static_cast<int>(s[0] * 10)), std::to_string(a) + " " + std::to_string(b));
    EXPECT_GT(b, a);
    isotropicSum += a;
    anisotropicSum += b;
  }
  // Measured: 0.64 isotropic, 0.78 with gamma = 4.
  EXPECT_GT(anisotropicSum / 3.0, isotropicSum / 3.0 + 0.08);
}

TEST(GeodesicPaths, RefusesBadInput)
{
  // Two spheres: points on different components have no path.
  TriangleMesh one = makeIcosphere(1.0, 2);
  std::vector<Vector3> points = one.points();
  std::vector<Triangle> triangles = one.triangles();
  const int offset = static_cast<int>(points.size());
  for (const Vector3& p : one.points())
  {
    points.push_back(p + Vector3(5.0, 0.0, 0.0));
  }
  for (const Triangle& t : one.triangles())
  {
    triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  const auto surface = std::make_shared<Surface>(TriangleMesh(points, triangles));
  const SurfacePoint a = vertexSurfacePoint(surface->mesh(), 0);
  const SurfacePoint b = vertexSurfacePoint(surface->mesh(), offset);
  EXPECT_THROW(shortestPath(*surface, a, b, GeodesicPathOptions()), Error);
  SurfacePoint off = a;
  off.barycentric = Vector3(2.0, -0.5, -0.5);
  EXPECT_THROW(shortestPath(*surface, off, a, GeodesicPathOptions()), Error);
  off.face = surface->mesh().faceCount();
  EXPECT_THROW(shortestPath(*surface, a, off, GeodesicPathOptions()), Error);
  EXPECT_THROW(geodesicLoop(*surface, { a, a }, GeodesicPathOptions()), Error);
  GeodesicSource empty;
  EXPECT_THROW(HeatGeodesics(surface->mesh()).compute(empty), Error);
  GeodesicSource outside;
  outside.vertices = { -1 };
  EXPECT_THROW(HeatGeodesics(surface->mesh()).compute(outside), Error);
}

TEST(GeodesicPaths, DistanceFollowsTheChosenMetric)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 3));
  GeodesicSource source;
  source.vertices = { 5 };
  GeodesicPathOptions options;
  // gamma = 0: the heat method, its set-up cached on the surface.
  const GeodesicDistance heat = geodesicDistance(*surface, source, options);
  EXPECT_EQ(heat.distance, HeatGeodesics::of(*surface).compute(source).distance);
  EXPECT_EQ(heat.faceGradients.size(), static_cast<std::size_t>(surface->mesh().faceCount()));
  // Otherwise Short-Term Vector Dijkstra under the metric.
  options.metric.gamma = 2.0;
  const GeodesicDistance anisotropic = geodesicDistance(*surface, source, options);
  VectorDijkstraOptions dijkstra;
  EXPECT_EQ(anisotropic.distance,
    shortTermVectorDijkstra(surface->mesh(), anisotropicMetric(*surface, options.metric), source, dijkstra).distance);
  options.metric.gamma = 0.0;
  options.vectorDijkstra = true;
  EXPECT_EQ(geodesicDistance(*surface, source, options).distance,
    shortTermVectorDijkstra(surface->mesh(), anisotropicMetric(*surface, options.metric), source, dijkstra).distance);
  for (double gamma : { -1.0, std::nan(""), std::numeric_limits<double>::infinity() })
  {
    options.metric.gamma = gamma;
    EXPECT_THROW(geodesicDistance(*surface, source, options), Error);
  }
}

TEST(GeodesicPaths, PathToAVertexEndsWithoutDetour)
{
  // From the vertex at the north pole to the one on the x axis: the quarter meridian in the
  // plane y = 0. A source point at a vertex lies in each of its triangles, so the path ends as
  // soon as it enters one (it used to circle the vertex one edge away: 4.4% too long).
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 5));
  const TriangleMesh& sphere = surface->mesh();
  const SurfacePoint from = pointNear(sphere, Vector3(0.0, 0.0, 5.0));
  const SurfacePoint to = pointNear(sphere, Vector3(5.0, 0.0, 0.0));
  ASSERT_GE(coincidentVertex(sphere, from), 0);
  ASSERT_GE(coincidentVertex(sphere, to), 0);
  const double quarter = 0.5 * 3.14159265358979323846;
  for (bool vectorDijkstra : { false, true })
  {
    GeodesicPathOptions options;
    options.vectorDijkstra = vectorDijkstra;
    const SurfacePath path = shortestPath(*surface, from, to, options);
    double offPlane = 0.0;
    for (const Vector3& p : path.curve.points)
    {
      offPlane = std::max(offPlane, std::abs(p.y()));
    }
    RecordProperty(
      std::string("QuarterLength") + (vectorDijkstra ? "VectorDijkstra" : "Heat"), std::to_string(path.length));
    EXPECT_NEAR(path.length, quarter, 0.005 * quarter);
    EXPECT_LE(offPlane, 0.005);
    expectOnSurface(sphere, path.curve);
  }
}

TEST(GeodesicPaths, PolylineJoinsTheLegsThroughEveryPoint)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 4));
  const TriangleMesh& sphere = surface->mesh();
  const std::vector<SurfacePoint> points = { pointNear(sphere, Vector3(1.0, 0.2, 0.3)),
    pointNear(sphere, Vector3(0.1, 1.0, 0.4)), pointNear(sphere, Vector3(-0.6, 0.5, -0.7)) };
  for (bool closed : { false, true })
  {
    const GeodesicPolyline line = geodesicPolyline(*surface, points, closed, GeodesicPathOptions());
    const SurfaceCurve& curve = line.path.curve;
    EXPECT_EQ(curve.closed, closed);
    EXPECT_EQ(curve.faces.size(), static_cast<std::size_t>(segmentCount(curve)));
    expectOnSurface(sphere, curve);
    // Each given point is a point of the curve, exactly, at the arc length of the legs before it.
    ASSERT_EQ(line.waypoints.size(), points.size());
    ASSERT_EQ(line.arcLength.size(), curve.points.size());
    double before = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      EXPECT_EQ(curve.points[line.waypoints[i]], surfacePosition(sphere, points[i]));
      EXPECT_NEAR(line.arcLength[line.waypoints[i]], before, 1e-12);
      if (closed || i + 1 < points.size())
      {
        before += shortestPath(*surface, points[i], points[(i + 1) % points.size()], GeodesicPathOptions()).length;
      }
    }
    EXPECT_NEAR(line.path.length, before, 1e-12);
    EXPECT_TRUE(std::is_sorted(line.arcLength.begin(), line.arcLength.end()));
    EXPECT_EQ(line.selfCrossings, 0);
  }
  EXPECT_THROW(geodesicPolyline(*surface, { points[0] }, false, GeodesicPathOptions()), Error);
  EXPECT_THROW(geodesicPolyline(*surface, { points[0], points[1] }, true, GeodesicPathOptions()), Error);
  EXPECT_THROW(geodesicPolyline(*surface, { points[0], points[0], points[1] }, false, GeodesicPathOptions()), Error);
  // A loop's last point may not repeat its first.
  EXPECT_THROW(
    geodesicPolyline(*surface, { points[0], points[1], points[2], points[0] }, true, GeodesicPathOptions()), Error);
}

TEST(GeodesicPaths, LegCacheRetracesOnlyTheLegsOfAMovedPoint)
{
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 4));
  const TriangleMesh& sphere = surface->mesh();
  std::vector<SurfacePoint> points = { pointNear(sphere, Vector3(1.0, 0.2, 0.3)),
    pointNear(sphere, Vector3(0.6, 0.8, 0.1)), pointNear(sphere, Vector3(0.1, 1.0, 0.4)),
    pointNear(sphere, Vector3(-0.5, 0.6, 0.6)), pointNear(sphere, Vector3(-0.6, 0.5, -0.7)) };
  for (bool closed : { false, true })
  {
    const int legs = closed ? 5 : 4;
    GeodesicLegCache cache;
    const auto same = [](const GeodesicPolyline& a, const GeodesicPolyline& b) {
      return a.path.curve.points == b.path.curve.points && a.path.curve.faces == b.path.curve.faces &&
        a.arcLength == b.arcLength && a.waypoints == b.waypoints && a.path.length == b.path.length;
    };
    std::vector<SurfacePoint> moved = points;
    EXPECT_TRUE(same(geodesicPolyline(*surface, moved, closed, GeodesicPathOptions(), &cache),
      geodesicPolyline(*surface, moved, closed, GeodesicPathOptions())));
    EXPECT_EQ(cache.computed(), legs);
    EXPECT_EQ(cache.reused(), 0);
    // Moving point 2 retraces its two legs only, and gives what a fresh call gives, bit for bit.
    moved[2] = pointNear(sphere, Vector3(0.0, 1.0, 0.2));
    EXPECT_TRUE(same(geodesicPolyline(*surface, moved, closed, GeodesicPathOptions(), &cache),
      geodesicPolyline(*surface, moved, closed, GeodesicPathOptions())));
    EXPECT_EQ(cache.computed(), 2);
    EXPECT_EQ(cache.reused(), legs - 2);
    // Another metric retraces everything; the same call again retraces nothing.
    GeodesicPathOptions anisotropic;
    anisotropic.metric.gamma = 2.0;
    anisotropic.vectorDijkstra = true;
    geodesicPolyline(*surface, moved, closed, anisotropic, &cache);
    EXPECT_EQ(cache.computed(), legs);
    geodesicPolyline(*surface, moved, closed, anisotropic, &cache);
    EXPECT_EQ(cache.computed(), 0);
    EXPECT_EQ(cache.reused(), legs);
    // Another surface starts afresh.
    const auto other = std::make_shared<Surface>(makeIcosphere(1.0, 4));
    geodesicPolyline(*other, moved, closed, anisotropic, &cache);
    EXPECT_EQ(cache.computed(), legs);
  }
}

TEST(GeodesicPaths, PathsToPointsNearAVertexEndThroughIt)
{
  // Points given in single precision lie about 1e-8 from a vertex, inside one of its triangles:
  // there the distance is a cone whose apex is the vertex, and 4 of 108 paths used to circle it
  // without ending ("did not reach the source").
  const auto surface = std::make_shared<Surface>(makeIcosphere(1.0, 4));
  const TriangleMesh& sphere = surface->mesh();
  int paths = 0, offVertex = 0;
  for (int v = 12; v < sphere.vertexCount(); v += 97)
  {
    const SurfacePoint near = pointNear(sphere, sphere.point(v).cast<float>().cast<double>());
    offVertex += coincidentVertex(sphere, near) < 0 ? 1 : 0;
    const SurfacePoint far = pointNear(sphere, -sphere.point(v) + Vector3(0.3, 0.2, 0.1));
    const double exact = greatCircle(surfacePosition(sphere, near), surfacePosition(sphere, far));
    for (bool vectorDijkstra : { false, true })
    {
      GeodesicPathOptions options;
      options.vectorDijkstra = vectorDijkstra;
      for (const SurfacePath& path :
        { shortestPath(*surface, near, far, options), shortestPath(*surface, far, near, options) })
      {
        EXPECT_NEAR(path.length, exact, 0.01 * exact) << "vertex " << v;
        expectOnSurface(sphere, path.curve);
        ++paths;
      }
    }
  }
  EXPECT_EQ(paths, 108);
  RecordProperty("OffVertex", offVertex);
  EXPECT_GE(offVertex, 13); // half the points are not at their vertex
}
