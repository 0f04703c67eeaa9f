// Snakes on the mesh: shorter, smoother boundaries near the jagged ones, embedded, meeting points kept, override
// strokes and errors.
#include "Error.h"
#include "Mesh/MeshGenerators.h"
#include "Segmentation/RegionGrowing.h"
#include "Segmentation/SnakeRefinement.h"
#include "StrokeShapes.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>

using namespace kerf;
using kerf::test::DumbbellWithStrokes;

namespace
{
constexpr double Pi = 3.14159265358979323846;

// The faces whose closure holds a snake point: those of its edge, or all of its vertex's when it
// sits at an end, or its own for a meeting point.
std::set<int> facesHolding(const TriangleMesh& mesh, const SnakePoint& point)
{
  std::set<int> faces;
  if (point.edge < 0)
  {
    faces.insert(point.face);
    return faces;
  }
  const auto& ev = mesh.edgeVertices(point.edge);
  if (point.t == 0.0 || point.t == 1.0)
  {
    const IndexRange around = mesh.vertexFaces(ev[point.t == 0.0 ? 0 : 1]);
    faces.insert(around.begin(), around.end());
  }
  else
  {
    for (int f : mesh.edgeFaces(point.edge))
    {
      if (f >= 0)
      {
        faces.insert(f);
      }
    }
  }
  return faces;
}

// Every point on its edge (or inside its face), and consecutive points in a common triangle.
void expectEmbedded(const TriangleMesh& mesh, const std::vector<SnakeCurve>& curves)
{
  for (const SnakeCurve& curve : curves)
  {
    ASSERT_GE(curve.points.size(), 2u);
    for (const SnakePoint& p : curve.points)
    {
      if (p.edge >= 0)
      {
        const auto& ev = mesh.edgeVertices(p.edge);
        ASSERT_GE(p.t, 0.0);
        ASSERT_LE(p.t, 1.0);
        EXPECT_LT((p.position - ((1.0 - p.t) * mesh.point(ev[0]) + p.t * mesh.point(ev[1]))).norm(), 1e-12);
      }
      else
      {
        ASSERT_GE(p.face, 0);
        const Triangle& t = mesh.triangle(p.face);
        const Vector3 n = (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0]));
        EXPECT_LT(std::abs((p.position - mesh.point(t[0])).dot(n.normalized())), 1e-12);
      }
    }
    const std::size_t n = curve.points.size();
    for (std::size_t i = 0; i + 1 < n + (curve.closed ? 1 : 0); ++i)
    {
      const std::set<int> a = facesHolding(mesh, curve.points[i]), b = facesHolding(mesh, curve.points[(i + 1) % n]);
      std::vector<int> common;
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
      EXPECT_FALSE(common.empty()) << "segment " << i << " leaves the triangles";
    }
  }
}

// The normal of the surface at a point of an edge (or face), interpolated.
Vector3 normalAt(const Surface& surface, const SnakePoint& p)
{
  const std::vector<Vector3>& normals = surface.vertexNormals();
  if (p.edge < 0)
  {
    const Triangle& t = surface.mesh().triangle(p.face);
    return (normals[t[0]] + normals[t[1]] + normals[t[2]]).normalized();
  }
  const auto& ev = surface.mesh().edgeVertices(p.edge);
  return ((1.0 - p.t) * normals[ev[0]] + p.t * normals[ev[1]]).normalized();
}

// Length and total turning (pi minus the angle between the segments, projected onto the tangent
// plane, summed over the inner points) of a polyline.
struct Shape
{
  double length = 0.0;
  double turning = 0.0;
};

Shape measure(const std::vector<Vector3>& points, const std::vector<Vector3>& normals, bool closed)
{
  Shape shape;
  const std::size_t n = points.size();
  for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
  {
    shape.length += (points[(i + 1) % n] - points[i]).norm();
  }
  for (std::size_t i = closed ? 0 : 1; i < (closed ? n : n - 1); ++i)
  {
    const Vector3& normal = normals[i];
    Vector3 u = points[i] - points[(i + n - 1) % n], w = points[(i + 1) % n] - points[i];
    u -= u.dot(normal) * normal;
    w -= w.dot(normal) * normal;
    shape.turning += std::atan2(u.cross(w).norm(), u.dot(w));
  }
  return shape;
}

Shape measure(const Surface& surface, const std::vector<LabelBoundary>& boundaries)
{
  Shape total;
  for (const LabelBoundary& b : boundaries)
  {
    std::vector<Vector3> points, normals;
    for (int v : b.vertices)
    {
      points.push_back(surface.mesh().point(v));
      normals.push_back(surface.vertexNormals()[v]);
    }
    const Shape shape = measure(points, normals, b.closed);
    total.length += shape.length;
    total.turning += shape.turning;
  }
  return total;
}

Shape measure(const Surface& surface, const std::vector<SnakeCurve>& curves)
{
  Shape total;
  for (const SnakeCurve& c : curves)
  {
    std::vector<Vector3> points, normals;
    for (const SnakePoint& p : c.points)
    {
      points.push_back(p.position);
      normals.push_back(normalAt(surface, p));
    }
    const Shape shape = measure(points, normals, c.closed);
    total.length += shape.length;
    total.turning += shape.turning;
  }
  return total;
}

// Rings (edge hops) from the given vertices.
std::vector<int> ringsFrom(const TriangleMesh& mesh, const std::vector<LabelBoundary>& boundaries)
{
  std::vector<int> ring(static_cast<std::size_t>(mesh.vertexCount()), -1), queue;
  for (const LabelBoundary& b : boundaries)
  {
    for (int v : b.vertices)
    {
      if (ring[v] < 0)
      {
        ring[v] = 0;
        queue.push_back(v);
      }
    }
  }
  for (std::size_t i = 0; i < queue.size(); ++i)
  {
    for (int w : mesh.vertexNeighbors(queue[i]))
    {
      if (ring[w] < 0)
      {
        ring[w] = ring[queue[i]] + 1;
        queue.push_back(w);
      }
    }
  }
  return ring;
}

// The farthest ring of the corners around any snake point.
int farthestRing(const TriangleMesh& mesh, const std::vector<SnakeCurve>& curves, const std::vector<int>& ring)
{
  int farthest = 0;
  for (const SnakeCurve& c : curves)
  {
    for (const SnakePoint& p : c.points)
    {
      for (int f : facesHolding(mesh, p))
      {
        int nearest = 1000000;
        for (int v : mesh.triangle(f))
        {
          nearest = std::min(nearest, ring[v]);
        }
        farthest = std::max(farthest, nearest);
      }
    }
  }
  return farthest;
}
} // namespace

TEST(SnakeRefinement, NeckBoundaryBecomesShorterSmootherAndStaysNear)
{
  const DumbbellWithStrokes shape(5);
  const auto surface = std::make_shared<const Surface>(shape.mesh);
  const RegionGrowingResult grown = growRegions(*surface, shape.strokes, {});
  const std::vector<LabelBoundary> jagged = labelBoundaries(shape.mesh, grown.faceLabels);
  BoundarySnake snake(surface, grown.faceLabels);
  const SnakeStatistics statistics = snake.refine({});
  EXPECT_TRUE(statistics.converged);
  EXPECT_GT(statistics.slides, 0);
  EXPECT_GT(statistics.splits, 0);
  EXPECT_GE(statistics.removals, statistics.splits);
  const std::vector<SnakeCurve> curves = snake.curves();
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_TRUE(curves[0].closed);
  EXPECT_EQ(curves[0].leftLabel, 1);
  EXPECT_EQ(curves[0].rightLabel, 2);
  expectEmbedded(shape.mesh, curves);

  // The jagged loop zig-zags along the neck's long thin triangles (length 15.6, turning 749 rad);
  // the snake goes round the neck nearly as a circle would (length 2.25, 13% longer than the circle
  // at its highest point, as it winds up and down by 0.05).
  const Shape before = measure(*surface, jagged), after = measure(*surface, curves);
  EXPECT_LT(after.length, 0.2 * before.length);
  double highest = 0.0, lowest = 1e300;
  for (const SnakePoint& p : curves[0].points)
  {
    highest = std::max(highest, p.position.z());
    lowest = std::min(lowest, p.position.z());
  }
  EXPECT_LT(after.length,
    1.2 * 2.0 * Pi *
      dumbbellRadius(highest, DumbbellWithStrokes::HalfLength, DumbbellWithStrokes::Radii,
        DumbbellWithStrokes::NeckHeight, DumbbellWithStrokes::Depth));
  EXPECT_LT(after.turning, 0.1 * before.turning);
  // Within two rings of the jagged boundary, and still in the neck.
  EXPECT_LE(farthestRing(shape.mesh, curves, ringsFrom(shape.mesh, jagged)), 2);
  EXPECT_LT(highest - shape.neckZ, 0.1 * DumbbellWithStrokes::Radii[1]);
  EXPECT_LT(shape.neckZ - lowest, 0.1 * DumbbellWithStrokes::Radii[1]);

  // Face labels agree with the snake: uncrossed faces keep their corners' label, and the faces'
  // boundary runs through faces the snake crosses or touches.
  const std::vector<int> faces = snake.faceLabels();
  const std::vector<int>& vertices = snake.vertexLabels();
  std::set<int> snakeFaces;
  for (const SnakePoint& p : curves[0].points)
  {
    const std::set<int> holding = facesHolding(shape.mesh, p);
    snakeFaces.insert(holding.begin(), holding.end());
  }
  for (int f = 0; f < shape.mesh.faceCount(); ++f)
  {
    const Triangle& t = shape.mesh.triangle(f);
    ASSERT_TRUE(faces[f] == 1 || faces[f] == 2);
    if (vertices[t[0]] == vertices[t[1]] && vertices[t[1]] == vertices[t[2]])
    {
      EXPECT_EQ(faces[f], vertices[t[0]]);
    }
  }
  for (const LabelBoundary& b : labelBoundaries(shape.mesh, faces))
  {
    for (int v : b.vertices)
    {
      const IndexRange around = shape.mesh.vertexFaces(v);
      EXPECT_TRUE(std::any_of(around.begin(), around.end(), [&](int f) { return snakeFaces.count(f) > 0; }));
    }
  }
}

TEST(SnakeRefinement, StaircaseOnAPlaneBecomesItsLine)
{
  // Faces right of the line x = 0.4 + 0.3 y: a staircase along the grid's edges. On a plane only
  // E_int counts: the snake straightens onto the line, its ends held on the border.
  const TriangleMesh grid = makeGrid(1.0, 1.0, 30, 30);
  std::vector<int> labels(static_cast<std::size_t>(grid.faceCount()));
  for (int f = 0; f < grid.faceCount(); ++f)
  {
    const Triangle& t = grid.triangle(f);
    const Vector3 c = (grid.point(t[0]) + grid.point(t[1]) + grid.point(t[2])) / 3.0;
    labels[f] = c.x() > 0.4 + 0.3 * c.y() ? 7 : 3;
  }
  const auto surface = std::make_shared<const Surface>(grid);
  const std::vector<LabelBoundary> jagged = labelBoundaries(grid, labels);
  BoundarySnake snake(surface, labels);
  const SnakeStatistics statistics = snake.refine({});
  EXPECT_TRUE(statistics.converged);
  const std::vector<SnakeCurve> curves = snake.curves();
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_FALSE(curves[0].closed);
  EXPECT_EQ(curves[0].leftLabel, 3);
  expectEmbedded(grid, curves);
  const Shape before = measure(*surface, jagged), after = measure(*surface, curves);
  const double line = std::hypot(1.0, 0.3);
  EXPECT_GT(before.length, 1.2 * line);
  EXPECT_LT(after.length, 1.02 * line);
  EXPECT_LT(after.turning, 0.25 * before.turning);
  // Every point within half a grid step of the line.
  for (const SnakePoint& p : curves[0].points)
  {
    EXPECT_LT(std::abs(p.position.x() - 0.4 - 0.3 * p.position.y()) / std::hypot(1.0, 0.3), 0.5 / 30)
      << p.position.transpose();
  }
  EXPECT_LE(farthestRing(grid, curves, ringsFrom(grid, jagged)), 2);

  // A face the snake crosses takes the label holding the larger part of its area: measured here
  // from the curve's points, the lone corner's triangle cut off by the chord between them.
  const std::vector<int> faces = snake.faceLabels();
  const std::vector<int>& vertices = snake.vertexLabels();
  int checked = 0;
  for (std::size_t i = 0; i + 1 < curves[0].points.size(); ++i)
  {
    const SnakePoint& p = curves[0].points[i];
    const SnakePoint& q = curves[0].points[i + 1];
    if (p.edge < 0 || q.edge < 0 || p.t < 1e-6 || p.t > 1.0 - 1e-6 || q.t < 1e-6 || q.t > 1.0 - 1e-6)
    {
      continue; // a vertex snaxel: its faces are not split by one chord
    }
    for (int f : grid.edgeFaces(p.edge))
    {
      if (f < 0 || (grid.faceEdge(f, 0) != q.edge && grid.faceEdge(f, 1) != q.edge && grid.faceEdge(f, 2) != q.edge))
      {
        continue;
      }
      const Triangle& t = grid.triangle(f);
      int lone = -1;
      for (int k = 0; k < 3; ++k)
      {
        lone = vertices[t[k]] != vertices[t[(k + 1) % 3]] && vertices[t[k]] != vertices[t[(k + 2) % 3]] ? k : lone;
      }
      ASSERT_GE(lone, 0);
      const Vector3& corner = grid.point(t[lone]);
      const double part = (p.position - corner).cross(q.position - corner).norm() /
        (grid.point(t[1]) - grid.point(t[0])).cross(grid.point(t[2]) - grid.point(t[0])).norm();
      if (std::abs(part - 0.5) < 1e-9)
      {
        continue;
      }
      EXPECT_EQ(faces[f], part > 0.5 ? vertices[t[lone]] : vertices[t[(lone + 1) % 3]])
        << "face " << f << ", part " << part;
      ++checked;
    }
  }
  EXPECT_GE(checked, 30);
}

TEST(SnakeRefinement, ThreeLabelsKeepTheirMeetingPoints)
{
  // A sphere in three sectors: three curves from one pole's meeting point to the other's.
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  std::vector<int> labels(static_cast<std::size_t>(sphere.faceCount()));
  for (int f = 0; f < sphere.faceCount(); ++f)
  {
    const Triangle& t = sphere.triangle(f);
    const Vector3 c = (sphere.point(t[0]) + sphere.point(t[1]) + sphere.point(t[2])) / 3.0;
    labels[f] = std::min(2, static_cast<int>((std::atan2(c.y(), c.x()) + Pi) / (2.0 * Pi / 3.0)));
  }
  const auto surface = std::make_shared<const Surface>(sphere);
  const std::vector<LabelBoundary> jagged = labelBoundaries(sphere, labels);
  BoundarySnake snake(surface, labels);
  snake.refine({});
  const std::vector<SnakeCurve> curves = snake.curves();
  ASSERT_EQ(curves.size(), 3u);
  expectEmbedded(sphere, curves);
  std::set<std::pair<int, int>> pairs;
  for (const SnakeCurve& c : curves)
  {
    EXPECT_FALSE(c.closed);
    pairs.emplace(c.leftLabel, c.rightLabel);
    for (const SnakePoint* end : { &c.points.front(), &c.points.back() })
    {
      EXPECT_EQ(end->edge, -1);
      EXPECT_GT(std::abs(end->position.z()), 0.95);
    }
  }
  EXPECT_EQ(pairs, (std::set<std::pair<int, int>>{ { 0, 1 }, { 0, 2 }, { 1, 2 } }));
  const std::vector<int> faces = snake.faceLabels();
  EXPECT_EQ(std::set<int>(faces.begin(), faces.end()), (std::set<int>{ 0, 1, 2 }));
  const Shape before = measure(*surface, jagged), after = measure(*surface, curves);
  EXPECT_LT(after.length, before.length);
  EXPECT_LT(after.turning, 0.5 * before.turning);
  EXPECT_LE(farthestRing(sphere, curves, ringsFrom(sphere, jagged)), 2);
}

TEST(SnakeRefinement, AVertexHoldingNoFaceOfItsOwnIsNoRegion)
{
  // A cap of label 1 on a sphere, and label 1 on the faces around one vertex far from it: that
  // vertex takes label 1, its neighbours (on faces of label 0 too) label 0, so the fan holds no
  // face of its own. The snake has the cap's loop only, and the fan's faces keep label 0.
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  int lone = 0;
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    lone = sphere.point(v).z() < sphere.point(lone).z() ? v : lone;
  }
  std::vector<int> labels(static_cast<std::size_t>(sphere.faceCount()), 0);
  for (int f = 0; f < sphere.faceCount(); ++f)
  {
    const Triangle& t = sphere.triangle(f);
    labels[f] = (sphere.point(t[0]) + sphere.point(t[1]) + sphere.point(t[2])).z() > 1.5 ? 1 : 0;
  }
  for (int f : sphere.vertexFaces(lone))
  {
    labels[f] = 1;
  }
  const auto surface = std::make_shared<const Surface>(sphere);
  BoundarySnake snake(surface, labels);
  ASSERT_EQ(snake.curves().size(), 1u);
  EXPECT_TRUE(snake.curves()[0].closed);
  snake.refine({});
  const std::vector<SnakeCurve> curves = snake.curves();
  ASSERT_EQ(curves.size(), 1u);
  expectEmbedded(sphere, curves);
  for (const SnakePoint& p : curves[0].points)
  {
    EXPECT_GT(p.position.z(), 0.3);
  }
  const std::vector<int> faces = snake.faceLabels();
  for (int f : sphere.vertexFaces(lone))
  {
    EXPECT_EQ(faces[f], 0);
  }
}

TEST(SnakeRefinement, OverrideStrokeReplacesTheNearbyBoundary)
{
  const DumbbellWithStrokes shape(5);
  const auto surface = std::make_shared<const Surface>(shape.mesh);
  const RegionGrowingResult grown = growRegions(*surface, shape.strokes, {});
  BoundarySnake snake(surface, grown.faceLabels);
  snake.refine({});
  const std::vector<SnakeCurve> refined = snake.curves();
  // Half a loop 0.1 above the neck, on the side y > 0.
  const double strokeZ = shape.neckZ + 0.1;
  const double r = dumbbellRadius(strokeZ, DumbbellWithStrokes::HalfLength, DumbbellWithStrokes::Radii,
    DumbbellWithStrokes::NeckHeight, DumbbellWithStrokes::Depth);
  std::vector<Vector3> stroke;
  for (double angle = 0.0; angle <= Pi + 1e-9; angle += Pi / 16)
  {
    stroke.emplace_back(r * std::cos(angle), r * std::sin(angle), strokeZ);
  }
  snake.overrideWithStroke(stroke, 0.15, 0.0);
  const std::vector<SnakeCurve> edited = snake.curves();
  ASSERT_EQ(edited.size(), 1u);
  expectEmbedded(shape.mesh, edited);
  int beside = 0, away = 0;
  for (const SnakePoint& p : edited[0].points)
  {
    const double angle = std::atan2(p.position.y(), p.position.x());
    if (angle > 0.3 && angle < Pi - 0.3)
    {
      // Beside the stroke the boundary follows it (within a tenth of the 0.07-high neck triangles).
      EXPECT_NEAR(p.position.z(), strokeZ, 0.007);
      ++beside;
    }
    else if (angle < -0.3 && angle > -Pi + 0.3)
    {
      // On the other side the refined boundary is kept as it was.
      const bool kept = std::any_of(refined[0].points.begin(), refined[0].points.end(),
        [&p](const SnakePoint& q) { return (q.position - p.position).norm() < 1e-12; });
      EXPECT_TRUE(kept) << p.position.transpose();
      ++away;
    }
  }
  EXPECT_GT(beside, 20);
  EXPECT_GT(away, 20);
  // The faces between the old boundary and the stroke changed sides.
  const std::vector<int> faces = snake.faceLabels();
  for (int f = 0; f < shape.mesh.faceCount(); ++f)
  {
    const Triangle& t = shape.mesh.triangle(f);
    const Vector3 c = (shape.mesh.point(t[0]) + shape.mesh.point(t[1]) + shape.mesh.point(t[2])) / 3.0;
    const double angle = std::atan2(c.y(), c.x());
    if (angle > 0.3 && angle < Pi - 0.3 && std::abs(c.z() - strokeZ) > 0.05 && std::abs(c.z() - strokeZ) < 0.1)
    {
      EXPECT_EQ(faces[f], c.z() < strokeZ ? 1 : 2);
    }
  }
}

TEST(SnakeRefinement, RefusesBadInput)
{
  const DumbbellWithStrokes shape(3);
  const auto surface = std::make_shared<const Surface>(shape.mesh);
  const RegionGrowingResult grown = growRegions(*surface, shape.strokes, {});
  const auto message = [](const std::function<void()>& run) {
    try
    {
      run();
    }
    catch (const Error& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] {
    BoundarySnake(surface, { 1, 2, 3 });
  }).find("there are 3 face labels for"),
    std::string::npos);
  const auto nonManifold = std::make_shared<const Surface>(TriangleMesh(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 } }, { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } }));
  EXPECT_NE(message([&] {
    BoundarySnake(nonManifold, { 0, 1, 2 });
  }).find("snakes need a manifold surface"),
    std::string::npos);
  BoundarySnake snake(surface, grown.faceLabels);
  SnakeOptions options;
  options.slideSamples = 0;
  EXPECT_NE(message([&] { snake.refine(options); }).find("slide samples"), std::string::npos);
  options = SnakeOptions();
  options.convergence = std::nan("");
  EXPECT_NE(message([&] { snake.refine(options); }).find("convergence"), std::string::npos);
  // Override strokes: too short, NaN, away from any boundary, off the surface, bad radius.
  EXPECT_NE(message([&] { snake.overrideWithStroke({ Vector3(0, 0, 2) }, 0.1, 0.0); }).find("at least two points"),
    std::string::npos);
  EXPECT_NE(message([&] {
    snake.overrideWithStroke({ Vector3(0, 0, 2), Vector3(0, std::nan(""), 0) }, 0.1, 0.0);
  }).find("NaN"),
    std::string::npos);
  const double z = -1.5,
               r = dumbbellRadius(z, DumbbellWithStrokes::HalfLength, DumbbellWithStrokes::Radii,
                 DumbbellWithStrokes::NeckHeight, DumbbellWithStrokes::Depth);
  const std::vector<Vector3> onLobe = { Vector3(r, 0, z), Vector3(0, r, z) };
  EXPECT_NE(
    message([&] { snake.overrideWithStroke(onLobe, 0.1, 0.0); }).find("not near a boundary"), std::string::npos);
  EXPECT_NE(message([&] {
    snake.overrideWithStroke({ Vector3(r + 1, 0, z), Vector3(0, r, z) }, 0.1, 0.5);
  }).find("farther than the allowed 0.5"),
    std::string::npos);
  EXPECT_NE(message([&] { snake.overrideWithStroke(onLobe, 0.0, 0.0); }).find("positive length"), std::string::npos);
  // Nothing changed by the refused edits.
  BoundarySnake fresh(surface, grown.faceLabels);
  EXPECT_EQ(snake.vertexLabels(), fresh.vertexLabels());
}

TEST(SnakeRefinement, IsDeterministic)
{
  const DumbbellWithStrokes shape(4);
  const auto surface = std::make_shared<const Surface>(shape.mesh);
  const RegionGrowingResult grown = growRegions(*surface, shape.strokes, {});
  BoundarySnake first(surface, grown.faceLabels), second(std::make_shared<const Surface>(shape.mesh), grown.faceLabels);
  first.refine({});
  second.refine({});
  const std::vector<SnakeCurve> a = first.curves(), b = second.curves();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t c = 0; c < a.size(); ++c)
  {
    ASSERT_EQ(a[c].points.size(), b[c].points.size());
    for (std::size_t i = 0; i < a[c].points.size(); ++i)
    {
      EXPECT_EQ(a[c].points[i].position, b[c].points[i].position);
    }
  }
  EXPECT_EQ(first.faceLabels(), second.faceLabels());
}
