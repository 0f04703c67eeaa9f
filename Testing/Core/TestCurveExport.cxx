// Curve export operators: scissor keeps curves and area exactly, snap and inverse snap keep connectivity.
#include "Error.h"
#include "Export/CurveExport.h"
#include "Geodesic/SurfaceLocation.h"
#include "Harmonic/Isolines.h"
#include "Mesh/MeshGenerators.h"
#include "Mesh/MeshValidation.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace kerf
{
namespace
{

std::vector<SurfaceCurve> heightIsolines(const TriangleMesh& mesh, const std::vector<double>& heights)
{
  std::vector<double> z;
  for (const Vector3& p : mesh.points())
  {
    z.push_back(p.z());
  }
  std::vector<SurfaceCurve> curves;
  for (double h : heights)
  {
    for (const Isoline& isoline : extractIsolines(mesh, z, h))
    {
      curves.push_back(SurfaceCurve{ isoline.points, isoline.faces, isoline.closed });
    }
  }
  return curves;
}

double area(const TriangleMesh& mesh)
{
  double total = 0.0;
  for (const Triangle& t : mesh.triangles())
  {
    total += 0.5 * (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).norm();
  }
  return total;
}

double longestEdge(const TriangleMesh& mesh)
{
  double longest = 0.0;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    longest = std::max(longest, (mesh.point(mesh.edgeVertices(e)[0]) - mesh.point(mesh.edgeVertices(e)[1])).norm());
  }
  return longest;
}

bool joined(const TriangleMesh& mesh, int a, int b)
{
  for (int n : mesh.vertexNeighbors(a))
  {
    if (n == b)
    {
      return true;
    }
  }
  return false;
}

// The scissor invariants: the curves' points are vertices, the mesh is a valid manifold with the
// input's area and Euler characteristic, cut edges separate different charts only where cut.
void expectValidScissor(
  const TriangleMesh& input, const std::vector<SurfaceCurve>& curves, const CurveExportResult& result)
{
  const MeshReport before = inspectMesh(input);
  const MeshReport report = inspectMesh(result.mesh);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.nonManifoldVertices, 0);
  EXPECT_EQ(report.inconsistentEdges, 0);
  EXPECT_EQ(report.zeroAreaFaces, 0);
  EXPECT_EQ(report.duplicateFaces, 0);
  EXPECT_EQ(report.boundaryLoops, before.boundaryLoops);
  EXPECT_EQ(report.eulerCharacteristic, before.eulerCharacteristic);
  EXPECT_NEAR(area(result.mesh), area(input), 1e-12 * area(input));
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    const auto& vertices = result.curveVertices[c];
    for (std::size_t i = 0; i < curves[c].points.size(); ++i)
    {
      double nearest = std::numeric_limits<double>::infinity();
      for (int v : vertices)
      {
        nearest = std::min(nearest, (result.mesh.point(v) - curves[c].points[i]).norm());
      }
      EXPECT_LE(nearest, 1e-12) << "curve " << c << " point " << i;
    }
    // Consecutive points are joined by an edge, or by two through a crossing with another curve.
    for (std::size_t i = 0; i + 1 < vertices.size(); ++i)
    {
      bool throughCrossing = false;
      for (int w : result.mesh.vertexNeighbors(vertices[i]))
      {
        throughCrossing = throughCrossing ||
          (result.originalPointIds[static_cast<std::size_t>(w)] < 0 && joined(result.mesh, w, vertices[i + 1]));
      }
      EXPECT_TRUE(joined(result.mesh, vertices[i], vertices[i + 1]) || throughCrossing);
    }
  }
  // The split mesh's adjacency (updated from the input's around the split triangles) is the one
  // its triangles give when built from scratch.
  const TriangleMesh scratch(result.mesh.points(), result.mesh.triangles());
  ASSERT_EQ(scratch.edgeCount(), result.mesh.edgeCount());
  for (int e = 0; e < scratch.edgeCount(); ++e)
  {
    EXPECT_EQ(scratch.edgeVertices(e), result.mesh.edgeVertices(e));
    EXPECT_EQ(scratch.edgeFaces(e), result.mesh.edgeFaces(e));
    EXPECT_EQ(scratch.edgeFaceCount(e), result.mesh.edgeFaceCount(e));
  }
  for (int f = 0; f < scratch.faceCount(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(scratch.faceEdge(f, k), result.mesh.faceEdge(f, k));
      EXPECT_EQ(scratch.faceNeighbor(f, k), result.mesh.faceNeighbor(f, k));
    }
    EXPECT_EQ(scratch.faceComponent(f), result.mesh.faceComponent(f));
  }
  for (int v = 0; v < scratch.vertexCount(); ++v)
  {
    EXPECT_TRUE(std::equal(scratch.vertexEdges(v).begin(), scratch.vertexEdges(v).end(),
      result.mesh.vertexEdges(v).begin(), result.mesh.vertexEdges(v).end()));
    EXPECT_TRUE(std::equal(scratch.vertexFaces(v).begin(), scratch.vertexFaces(v).end(),
      result.mesh.vertexFaces(v).begin(), result.mesh.vertexFaces(v).end()));
    EXPECT_EQ(scratch.vertexComponent(v), result.mesh.vertexComponent(v));
  }
  EXPECT_EQ(scratch.boundaryLoops(), result.mesh.boundaryLoops());
  ASSERT_EQ(result.originalPointIds.size(), static_cast<std::size_t>(result.mesh.vertexCount()));
  for (int v = 0; v < input.vertexCount(); ++v)
  {
    EXPECT_EQ(result.originalPointIds[static_cast<std::size_t>(v)], v);
  }
  for (std::size_t v = static_cast<std::size_t>(input.vertexCount()); v < result.originalPointIds.size(); ++v)
  {
    EXPECT_EQ(result.originalPointIds[v], -1);
    const Vector3 origin = surfacePosition(input, result.pointOrigins[v]);
    EXPECT_LE((origin - result.mesh.point(static_cast<int>(v))).norm(), 1e-12);
  }
  for (int e = 0; e < result.mesh.edgeCount(); ++e)
  {
    const auto& faces = result.mesh.edgeFaces(e);
    if (faces[1] >= 0 && !result.cutEdges[static_cast<std::size_t>(e)])
    {
      EXPECT_EQ(result.charts[static_cast<std::size_t>(faces[0])], result.charts[static_cast<std::size_t>(faces[1])]);
    }
  }
}

TEST(CurveExport, ScissorSplitsASphereAlongAClosedIsolineIntoTwoCharts)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  const std::vector<SurfaceCurve> curves = heightIsolines(sphere, { 0.1234 });
  ASSERT_EQ(curves.size(), 1u);
  ASSERT_TRUE(curves[0].closed);
  const CurveExportResult result = exportCurves(sphere, curves, CurveExportOptions());
  expectValidScissor(sphere, curves, result);
  EXPECT_EQ(result.chartCount, 2);
  EXPECT_EQ(result.mesh.vertexCount(), sphere.vertexCount() + static_cast<int>(curves[0].points.size()));
  int cut = 0;
  for (char flag : result.cutEdges)
  {
    cut += flag;
  }
  EXPECT_EQ(cut, static_cast<int>(curves[0].points.size()));
  // Faces above the isoline form one chart, those below the other.
  std::set<std::pair<bool, int>> sides;
  for (int f = 0; f < result.mesh.faceCount(); ++f)
  {
    const Triangle& t = result.mesh.triangle(f);
    const double z = (result.mesh.point(t[0]).z() + result.mesh.point(t[1]).z() + result.mesh.point(t[2]).z()) / 3.0;
    sides.insert({ z > 0.1234, result.charts[static_cast<std::size_t>(f)] });
  }
  EXPECT_EQ(sides.size(), 2u);
}

TEST(CurveExport, ScissorCutsACylinderIntoRingsByTenIsolines)
{
  const TriangleMesh cylinder = makeCylinder(1.0, 2.0, 32, 20);
  std::vector<double> heights;
  for (int i = 0; i < 10; ++i)
  {
    heights.push_back(0.1 + 0.18 * i + 0.0123);
  }
  const std::vector<SurfaceCurve> curves = heightIsolines(cylinder, heights);
  ASSERT_EQ(curves.size(), 10u);
  const CurveExportResult result = exportCurves(cylinder, curves, CurveExportOptions());
  expectValidScissor(cylinder, curves, result);
  EXPECT_EQ(result.chartCount, 11);
}

// A stroke across a grid through a vertex, with a point inside a triangle, and a second stroke
// crossing it: the crossing becomes a vertex and the square falls into four charts.
TEST(CurveExport, ScissorHandlesVerticesInteriorPointsAndCrossings)
{
  const auto surface = std::make_shared<Surface>(makeGrid(4.0, 4.0, 4, 4));
  const TriangleMesh& grid = surface->mesh();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<SurfaceCurve> curves;
  curves.push_back(placeCurveOnSurface(*surface,
    { Vector3(0.0, 1.3, 0.0), Vector3(2.0, 2.0, 0.0), Vector3(3.3, 2.6, 0.0), Vector3(4.0, 3.2, 0.0) }, false, inf,
    "stroke"));
  curves.push_back(placeCurveOnSurface(
    *surface, { Vector3(1.1, 0.0, 0.0), Vector3(2.7, 2.75, 0.0), Vector3(3.1, 4.0, 0.0) }, false, inf, "stroke"));
  const CurveExportResult result = exportCurves(grid, curves, CurveExportOptions());
  expectValidScissor(grid, curves, result);
  EXPECT_EQ(result.chartCount, 4);
  int throughVertex = 0; // the stroke's point (2, 2) is the grid's vertex 12
  for (int v : result.curveVertices[0])
  {
    throughVertex += result.originalPointIds[static_cast<std::size_t>(v)] == 2 * 5 + 2 ? 1 : 0;
  }
  EXPECT_EQ(throughVertex, 1);
  EXPECT_EQ(result.mesh.vertexCount(),
    grid.vertexCount() + static_cast<int>(curves[0].points.size()) + static_cast<int>(curves[1].points.size()) - 1 +
      1); // all points but the vertex, plus the crossing
}

TEST(CurveExport, ScissorAcceptsACurveCrossingItself)
{
  const auto surface = std::make_shared<Surface>(makeGrid(4.0, 4.0, 4, 4));
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<SurfaceCurve> curves{ placeCurveOnSurface(*surface,
    { Vector3(0.0, 0.5, 0.0), Vector3(3.5, 3.4, 0.0), Vector3(3.6, 0.4, 0.0), Vector3(0.4, 3.6, 0.0),
      Vector3(0.0, 3.9, 0.0) },
    false, inf, "loop") };
  const CurveExportResult result = exportCurves(surface->mesh(), curves, CurveExportOptions());
  expectValidScissor(surface->mesh(), curves, result);
  // From the crossing the curve runs round a loop and back: the loop, the wedge between the
  // curve and the left side, and the rest.
  EXPECT_EQ(result.chartCount, 3);
}

TEST(CurveExport, ScissorRefusesAZeroAreaTriangleOnTheCurve)
{
  const TriangleMesh mesh({ Vector3(0, 0, 0), Vector3(2, 0, 0), Vector3(1, 0, 0), Vector3(1, 1, 0) },
    { Triangle{ 0, 2, 3 }, Triangle{ 2, 1, 3 }, Triangle{ 0, 1, 2 } });
  const std::vector<SurfaceCurve> curves{ SurfaceCurve{ { Vector3(0.5, 0, 0), Vector3(1.5, 0, 0) }, { 2 }, false } };
  try
  {
    exportCurves(mesh, curves, CurveExportOptions());
    FAIL() << "no error";
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find("zero area"), std::string::npos) << error.what();
  }
}

TEST(CurveExport, ErrorsNameTheCurveAndPoint)
{
  const TriangleMesh grid = makeGrid(4.0, 4.0, 4, 4);
  const std::vector<SurfaceCurve> outside{ SurfaceCurve{
    { Vector3(0.5, 0.2, 0), Vector3(0.6, 0.2, 0) }, { 99 }, false } };
  EXPECT_THROW(exportCurves(grid, outside, CurveExportOptions()), Error);
  // Segments in triangles 0 and 31 (opposite corners of the grid) do not touch.
  const std::vector<SurfaceCurve> apart{ SurfaceCurve{
    { Vector3(0.5, 0.2, 0), Vector3(0.6, 0.2, 0), Vector3(3.6, 3.8, 0) }, { 0, 31 }, false } };
  try
  {
    exportCurves(grid, apart, CurveExportOptions());
    FAIL() << "no error";
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find("point 1 of curve 0"), std::string::npos) << error.what();
  }
  EXPECT_THROW(exportCurves(TriangleMesh(), {}, CurveExportOptions()), Error);
  // No curve: the mesh comes back whole, one chart.
  const CurveExportResult none = exportCurves(grid, {}, CurveExportOptions());
  EXPECT_EQ(none.mesh.faceCount(), grid.faceCount());
  EXPECT_EQ(none.chartCount, 1);
}

TEST(CurveExport, SnapKeepsTheMeshAndFollowsEdgesNearTheCurve)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  const std::vector<SurfaceCurve> curves = heightIsolines(sphere, { -0.3, 0.45 });
  ASSERT_EQ(curves.size(), 2u);
  CurveExportOptions options;
  options.mode = CurveExportMode::Snap;
  const CurveExportResult result = exportCurves(sphere, curves, options);
  EXPECT_TRUE(result.mesh.empty()); // the output is the input mesh
  EXPECT_EQ(&exportedMesh(result, sphere), &sphere);
  EXPECT_EQ(result.cutEdges.size(), static_cast<std::size_t>(sphere.edgeCount()));
  EXPECT_EQ(result.chartCount, 3);
  const double edge = longestEdge(sphere);
  int chainEdges = 0;
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    const auto& chain = result.curveVertices[c];
    ASSERT_GE(chain.size(), 3u);
    for (std::size_t i = 0; i < chain.size(); ++i)
    {
      EXPECT_TRUE(joined(sphere, chain[i], chain[(i + 1) % chain.size()]));
      double nearest = std::numeric_limits<double>::infinity();
      for (const Vector3& p : curves[c].points)
      {
        nearest = std::min(nearest, (sphere.point(chain[i]) - p).norm());
      }
      EXPECT_LE(nearest, edge);
    }
    chainEdges += static_cast<int>(chain.size());
  }
  int cut = 0;
  for (char flag : result.cutEdges)
  {
    cut += flag;
  }
  EXPECT_EQ(cut, chainEdges);
}

TEST(CurveExport, InverseSnapMovesVerticesExactlyOntoTheCurveWithoutFlips)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  const std::vector<SurfaceCurve> curves = heightIsolines(sphere, { 0.2 });
  CurveExportOptions options;
  options.mode = CurveExportMode::InverseSnap;
  const CurveExportResult result = exportCurves(sphere, curves, options);
  EXPECT_EQ(result.mesh.triangles(), sphere.triangles());
  EXPECT_GT(result.movedVertices, 0);
  EXPECT_EQ(result.chartCount, 2);
  std::set<int> moved;
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    if (result.mesh.point(v) != sphere.point(v))
    {
      moved.insert(v);
      bool onCurve = false;
      for (const Vector3& p : curves[0].points)
      {
        onCurve = onCurve || result.mesh.point(v) == p;
      }
      EXPECT_TRUE(onCurve) << v;
    }
  }
  EXPECT_EQ(static_cast<int>(moved.size()), result.movedVertices);
  EXPECT_EQ(
    result.movedVertices + result.refusedFlips + result.droppedPoints, static_cast<int>(curves[0].points.size()));
  for (int f = 0; f < sphere.faceCount(); ++f)
  {
    const Triangle& t = sphere.triangle(f);
    const Vector3 before = (sphere.point(t[1]) - sphere.point(t[0])).cross(sphere.point(t[2]) - sphere.point(t[0]));
    const Vector3 after =
      (result.mesh.point(t[1]) - result.mesh.point(t[0])).cross(result.mesh.point(t[2]) - result.mesh.point(t[0]));
    EXPECT_GT(before.dot(after), 0.0) << f;
  }
}

// A densely sampled stroke on a coarse grid: many points share a nearest vertex; the nearest
// wins, the others are counted as dropped.
TEST(CurveExport, InverseSnapDropsPointsSharingAVertex)
{
  const auto surface = std::make_shared<Surface>(makeGrid(4.0, 4.0, 4, 4));
  std::vector<Vector3> stroke;
  for (int i = 0; i <= 40; ++i)
  {
    stroke.emplace_back(0.1 * i, 1.2 + 0.02 * i, 0.0);
  }
  const std::vector<SurfaceCurve> curves{ placeCurveOnSurface(
    *surface, stroke, false, std::numeric_limits<double>::infinity(), "stroke") };
  CurveExportOptions options;
  options.mode = CurveExportMode::InverseSnap;
  const CurveExportResult result = exportCurves(surface->mesh(), curves, options);
  std::set<int> nearest;
  for (const Vector3& p : curves[0].points)
  {
    int best = 0;
    for (int v = 1; v < surface->mesh().vertexCount(); ++v)
    {
      if ((surface->mesh().point(v) - p).norm() < (surface->mesh().point(best) - p).norm())
      {
        best = v;
      }
    }
    nearest.insert(best);
  }
  EXPECT_EQ(result.droppedPoints, static_cast<int>(curves[0].points.size() - nearest.size()));
  EXPECT_GT(result.droppedPoints, 0);
  int alreadyThere = 0; // the stroke's last point (4, 2) is a grid vertex: nothing to move
  for (int v : nearest)
  {
    for (const Vector3& p : curves[0].points)
    {
      alreadyThere += surface->mesh().point(v) == p ? 1 : 0;
    }
  }
  EXPECT_EQ(alreadyThere, 1);
  EXPECT_EQ(result.movedVertices + result.refusedFlips + alreadyThere, static_cast<int>(nearest.size()));
  EXPECT_EQ(result.chartCount, 2);
  // Repeated runs give the same mesh bit for bit.
  const CurveExportResult again = exportCurves(surface->mesh(), curves, options);
  EXPECT_EQ(again.mesh.points(), result.mesh.points());
  EXPECT_EQ(again.charts, result.charts);
}

TEST(CurveExport, ScissorIsDeterministic)
{
  const TriangleMesh cylinder = makeCylinder(1.0, 2.0, 24, 12);
  const std::vector<SurfaceCurve> curves = heightIsolines(cylinder, { 0.77, 1.31 });
  const CurveExportResult a = exportCurves(cylinder, curves, CurveExportOptions());
  const CurveExportResult b = exportCurves(cylinder, curves, CurveExportOptions());
  EXPECT_EQ(a.mesh.points(), b.mesh.points());
  EXPECT_EQ(a.mesh.triangles(), b.mesh.triangles());
  EXPECT_EQ(a.charts, b.charts);
  EXPECT_EQ(a.chartCount, 3);
}

} // namespace
} // namespace kerf
