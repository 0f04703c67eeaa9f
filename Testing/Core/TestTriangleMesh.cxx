// Adjacency, topology invariants and validation of kerf::TriangleMesh on known meshes.
#include "Error.h"
#include "Mesh/MeshGenerators.h"
#include "Mesh/MeshValidation.h"
#include "Mesh/OpenMeshAdapter.h"
#include "Mesh/PointWelding.h"
#include "Mesh/TriangleMesh.h"
#include "Mesh/UnionFind.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <string>

using namespace kerf;

namespace
{
TriangleMesh tetrahedron()
{
  return TriangleMesh(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 } });
}

void expectConsistentAdjacency(const TriangleMesh& mesh)
{
  int incidences = 0;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int e = mesh.faceEdge(f, k);
      ASSERT_GE(e, 0);
      const std::array<int, 2>& ev = mesh.edgeVertices(e);
      const int a = mesh.triangle(f)[k];
      const int b = mesh.triangle(f)[(k + 1) % 3];
      EXPECT_EQ(std::min(a, b), ev[0]);
      EXPECT_EQ(std::max(a, b), ev[1]);
      const int g = mesh.faceNeighbor(f, k);
      if (g >= 0)
      {
        bool back = false;
        for (int j = 0; j < 3; ++j)
        {
          back = back || mesh.faceNeighbor(g, j) == f;
        }
        EXPECT_TRUE(back) << "neighbour relation is not symmetric at face " << f;
      }
      ++incidences;
    }
  }
  int counted = 0;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    counted += mesh.edgeFaceCount(e);
  }
  EXPECT_EQ(incidences, counted);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const IndexRange neighbors = mesh.vertexNeighbors(v);
    const IndexRange edges = mesh.vertexEdges(v);
    ASSERT_EQ(neighbors.size(), edges.size());
    for (std::size_t i = 0; i < neighbors.size(); ++i)
    {
      const std::array<int, 2>& ev = mesh.edgeVertices(edges[i]);
      EXPECT_TRUE((ev[0] == v && ev[1] == neighbors[i]) || (ev[1] == v && ev[0] == neighbors[i]));
    }
    for (int f : mesh.vertexFaces(v))
    {
      const Triangle& t = mesh.triangle(f);
      EXPECT_TRUE(t[0] == v || t[1] == v || t[2] == v);
    }
  }
}

// Every number and list of two meshes, compared.
void expectSameMesh(const TriangleMesh& a, const TriangleMesh& b)
{
  ASSERT_EQ(a.points(), b.points());
  ASSERT_EQ(a.triangles(), b.triangles());
  ASSERT_EQ(a.edgeCount(), b.edgeCount());
  for (int v = 0; v < a.vertexCount(); ++v)
  {
    const auto row = [](IndexRange r) { return std::vector<int>(r.begin(), r.end()); };
    EXPECT_EQ(row(a.vertexFaces(v)), row(b.vertexFaces(v))) << "vertex " << v;
    EXPECT_EQ(row(a.vertexNeighbors(v)), row(b.vertexNeighbors(v))) << "vertex " << v;
    EXPECT_EQ(row(a.vertexEdges(v)), row(b.vertexEdges(v))) << "vertex " << v;
    EXPECT_EQ(a.isBoundaryVertex(v), b.isBoundaryVertex(v)) << "vertex " << v;
    EXPECT_EQ(a.vertexComponent(v), b.vertexComponent(v)) << "vertex " << v;
  }
  for (int e = 0; e < a.edgeCount(); ++e)
  {
    EXPECT_EQ(a.edgeVertices(e), b.edgeVertices(e)) << "edge " << e;
    EXPECT_EQ(a.edgeFaces(e), b.edgeFaces(e)) << "edge " << e;
    EXPECT_EQ(a.edgeFaceCount(e), b.edgeFaceCount(e)) << "edge " << e;
  }
  for (int f = 0; f < a.faceCount(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(a.faceEdge(f, k), b.faceEdge(f, k)) << "face " << f;
      EXPECT_EQ(a.faceNeighbor(f, k), b.faceNeighbor(f, k)) << "face " << f;
    }
    EXPECT_EQ(a.faceComponent(f), b.faceComponent(f)) << "face " << f;
  }
  EXPECT_EQ(a.boundaryLoops(), b.boundaryLoops());
  EXPECT_EQ(a.componentCount(), b.componentCount());
}

// A random refinement of `mesh`: some edges get a midpoint (shared by the triangles beside them),
// and every triangle with a midpoint, or picked at random, is replaced by a fan around a new
// centre through its corners and midpoints. `odd` mixes in what a refinement may also hold: a
// triangle dropped, kept with its corners turned, or replaced by a piece reaching a vertex that
// is not its own, a repeated corner, and a point no triangle uses.
struct Refinement
{
  std::vector<Vector3> points;
  std::vector<Triangle> triangles;
  std::vector<int> originalFaces;
};

Refinement refine(const TriangleMesh& mesh, unsigned seed, bool odd)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Refinement r;
  r.points = mesh.points();
  std::vector<int> midpoint(static_cast<std::size_t>(mesh.edgeCount()), -1);
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    if (unit(random) < 0.1)
    {
      const auto& ev = mesh.edgeVertices(e);
      midpoint[static_cast<std::size_t>(e)] = static_cast<int>(r.points.size());
      r.points.push_back(0.5 * (mesh.point(ev[0]) + mesh.point(ev[1])));
    }
  }
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    std::vector<int> ring;
    for (int k = 0; k < 3; ++k)
    {
      ring.push_back(t[k]);
      const int e = mesh.faceEdge(f, k);
      if (e >= 0 && midpoint[static_cast<std::size_t>(e)] >= 0)
      {
        ring.push_back(midpoint[static_cast<std::size_t>(e)]);
      }
    }
    const double roll = unit(random);
    if (odd && roll < 0.03)
    {
      continue; // dropped
    }
    if (odd && roll < 0.06)
    {
      r.triangles.push_back(Triangle{ t[1], t[2], t[0] });
      r.originalFaces.push_back(f);
      continue;
    }
    if (ring.size() == 3 && roll > 0.2)
    {
      r.triangles.push_back(t);
      r.originalFaces.push_back(f);
      continue;
    }
    const int centre = static_cast<int>(r.points.size());
    r.points.push_back((mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0);
    for (std::size_t i = 0; i < ring.size(); ++i)
    {
      r.triangles.push_back(Triangle{ ring[i], ring[(i + 1) % ring.size()], centre });
      r.originalFaces.push_back(f);
    }
    if (odd && roll > 0.97)
    {
      r.triangles.push_back(Triangle{ centre, t[0], (t[0] + 1) % mesh.vertexCount() }); // another vertex
      r.originalFaces.push_back(f);
    }
    else if (odd && roll > 0.94)
    {
      r.triangles.push_back(Triangle{ centre, t[0], t[0] }); // a repeated corner
      r.originalFaces.push_back(f);
    }
  }
  if (odd)
  {
    r.points.push_back(Vector3(9.0, 9.0, 9.0)); // used by no triangle
  }
  return r;
}
} // namespace

TEST(TriangleMesh, TetrahedronCounts)
{
  const TriangleMesh mesh = tetrahedron();
  EXPECT_EQ(mesh.vertexCount(), 4);
  EXPECT_EQ(mesh.faceCount(), 4);
  EXPECT_EQ(mesh.edgeCount(), 6);
  EXPECT_EQ(mesh.componentCount(), 1);
  EXPECT_TRUE(mesh.boundaryLoops().empty());
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    EXPECT_EQ(mesh.edgeFaceCount(e), 2);
  }
  for (int v = 0; v < 4; ++v)
  {
    EXPECT_EQ(mesh.vertexNeighbors(v).size(), 3u);
    EXPECT_EQ(mesh.vertexFaces(v).size(), 3u);
  }
  expectConsistentAdjacency(mesh);
  const MeshReport report = inspectMesh(mesh);
  EXPECT_EQ(report.eulerCharacteristic, 2);
  EXPECT_EQ(report.inconsistentEdges, 0);
  EXPECT_EQ(describeProblems(report, MeshRequirements{}), "");
}

TEST(TriangleMesh, GeneratedSurfacesHaveTheirEulerCharacteristic)
{
  struct Case
  {
    TriangleMesh mesh;
    int euler;
    int loops;
  };
  const Case cases[] = { { makeIcosphere(1.0, 3), 2, 0 }, { makeTorus(3.0, 1.0, 40, 16), 0, 0 },
    { makeCylinder(1.0, 2.0, 24, 7), 0, 2 }, { makeGrid(2.0, 1.0, 8, 5), 1, 1 } };
  for (const Case& c : cases)
  {
    const MeshReport report = inspectMesh(c.mesh);
    EXPECT_EQ(report.eulerCharacteristic, c.euler);
    EXPECT_EQ(report.boundaryLoops, c.loops);
    EXPECT_EQ(report.components, 1);
    EXPECT_EQ(report.nonManifoldEdges + report.nonManifoldVertices + report.inconsistentEdges + report.duplicateFaces +
        report.zeroAreaFaces + report.unreferencedVertices,
      0);
    expectConsistentAdjacency(c.mesh);
  }
}

TEST(TriangleMesh, GridBoundaryLoopFollowsTheTriangles)
{
  const int columns = 6, rows = 4;
  const TriangleMesh grid = makeGrid(3.0, 2.0, columns, rows);
  ASSERT_EQ(grid.boundaryLoops().size(), 1u);
  const std::vector<int>& loop = grid.boundaryLoops()[0];
  EXPECT_EQ(loop.size(), static_cast<std::size_t>(2 * (columns + rows)));
  // Triangles are counter-clockwise seen from +z, so the loop has positive signed area.
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i)
  {
    const Vector3& a = grid.point(loop[i]);
    const Vector3& b = grid.point(loop[(i + 1) % loop.size()]);
    twiceArea += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_NEAR(twiceArea, 2.0 * 3.0 * 2.0, 1e-12);
  for (int v : loop)
  {
    EXPECT_TRUE(grid.isBoundaryVertex(v));
  }
  EXPECT_FALSE(grid.isBoundaryVertex((columns + 1) + 1));
}

TEST(TriangleMesh, ComponentsAndUnreferencedPoints)
{
  const TriangleMesh mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 5, 0, 0 }, { 6, 0, 0 }, { 5, 1, 0 }, { 9, 9, 9 } },
    { { 0, 1, 2 }, { 3, 4, 5 } });
  EXPECT_EQ(mesh.componentCount(), 2);
  EXPECT_EQ(mesh.faceComponent(0), 0);
  EXPECT_EQ(mesh.faceComponent(1), 1);
  EXPECT_EQ(mesh.vertexComponent(6), -1);
  const MeshReport report = inspectMesh(mesh);
  EXPECT_EQ(report.unreferencedVertices, 1);
  EXPECT_EQ(report.components, 2);
  MeshRequirements single;
  single.allowSeveralComponents = false;
  EXPECT_NE(describeProblems(report, single).find("2 connected components"), std::string::npos);
  EXPECT_EQ(describeProblems(report, MeshRequirements{}), "");
}

TEST(TriangleMesh, RejectsIndicesOutOfRange)
{
  EXPECT_THROW(TriangleMesh({ { 0, 0, 0 }, { 1, 0, 0 } }, { { 0, 1, 2 } }), Error);
  EXPECT_THROW(TriangleMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, -1, 2 } }), Error);
}

TEST(TriangleMesh, EmptyMeshIsReported)
{
  const TriangleMesh empty;
  EXPECT_TRUE(empty.empty());
  const MeshReport report = inspectMesh(empty);
  EXPECT_EQ(describeProblems(report, MeshRequirements{}), "the mesh has no triangles");
}

TEST(TriangleMesh, NumberingIsDeterministic)
{
  const TriangleMesh a = makeTorus(2.0, 0.5, 30, 12);
  const TriangleMesh b = makeTorus(2.0, 0.5, 30, 12);
  ASSERT_EQ(a.edgeCount(), b.edgeCount());
  for (int e = 0; e < a.edgeCount(); ++e)
  {
    EXPECT_EQ(a.edgeVertices(e), b.edgeVertices(e));
    EXPECT_EQ(a.edgeFaces(e), b.edgeFaces(e));
  }
}

// refined() updates the adjacency around the split triangles only; the result must be the mesh
// built from scratch, number for number, on closed and open surfaces, several components,
// non-manifold edges, triangles repeating a vertex and unreferenced points.
TEST(TriangleMesh, RefinedEqualsTheMeshBuiltFromScratch)
{
  std::vector<TriangleMesh> meshes;
  meshes.push_back(makeIcosphere(1.0, 2));
  meshes.push_back(makeGrid(3.0, 2.0, 6, 4));
  meshes.push_back(makeTorus(2.0, 0.5, 12, 6));
  // Two components, an unreferenced point, the non-manifold edge (0, 1) and a repeated vertex.
  meshes.push_back(TriangleMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 5, 0, 0 }, { 6, 0, 0 }, { 5, 1, 0 },
                                  { 9, 9, 9 }, { 0, -1, 0 }, { 0, 0, 1 } },
    { { 0, 1, 2 }, { 3, 4, 5 }, { 1, 0, 7 }, { 0, 1, 8 }, { 2, 2, 1 } }));
  for (std::size_t m = 0; m < meshes.size(); ++m)
  {
    for (unsigned seed = 1; seed <= 6; ++seed)
    {
      for (bool odd : { false, true })
      {
        SCOPED_TRACE("mesh " + std::to_string(m) + ", seed " + std::to_string(seed) + (odd ? ", odd" : ""));
        const Refinement r = refine(meshes[m], seed, odd);
        const TriangleMesh scratch(r.points, r.triangles);
        expectSameMesh(meshes[m].refined(r.points, r.triangles, r.originalFaces), scratch);
      }
    }
    // Nothing split, and everything split.
    const TriangleMesh& mesh = meshes[m];
    std::vector<int> identity(static_cast<std::size_t>(mesh.faceCount()));
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      identity[static_cast<std::size_t>(f)] = f;
    }
    expectSameMesh(mesh.refined(mesh.points(), mesh.triangles(), identity), mesh);
    std::vector<Triangle> turned;
    for (const Triangle& t : mesh.triangles())
    {
      turned.push_back(Triangle{ t[2], t[0], t[1] });
    }
    expectSameMesh(mesh.refined(mesh.points(), turned, identity), TriangleMesh(mesh.points(), turned));
  }
}

// componentMeshes() copies each component's adjacency instead of searching it again: each part
// must be the mesh built from scratch from the component's points and triangles, number for
// number (several components, unreferenced points, non-manifold edges, repeated vertices).
TEST(TriangleMesh, ComponentMeshesEqualTheMeshesBuiltFromScratch)
{
  std::vector<TriangleMesh> meshes;
  meshes.push_back(makeIcosphere(1.0, 2));
  meshes.push_back(TriangleMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 5, 0, 0 }, { 6, 0, 0 }, { 5, 1, 0 },
                                  { 9, 9, 9 }, { 0, -1, 0 }, { 0, 0, 1 } },
    { { 0, 1, 2 }, { 3, 4, 5 }, { 1, 0, 7 }, { 0, 1, 8 }, { 2, 2, 1 } }));
  {
    // A grid, a torus and a sphere interleaved: points and triangles of the three alternate.
    const TriangleMesh parts[] = { makeGrid(3.0, 2.0, 6, 4), makeTorus(2.0, 0.5, 12, 6), makeIcosphere(1.0, 1) };
    std::vector<Vector3> points;
    std::vector<Triangle> triangles;
    std::vector<int> offsets;
    for (const TriangleMesh& part : parts)
    {
      offsets.push_back(static_cast<int>(points.size()));
      points.insert(points.end(), part.points().begin(), part.points().end());
    }
    points.emplace_back(7, 7, 7); // unreferenced
    for (int f = 0; f < 60; ++f)
    {
      for (int p = 0; p < 3; ++p)
      {
        if (f < parts[p].faceCount())
        {
          const Triangle& t = parts[p].triangle(f);
          triangles.push_back({ t[0] + offsets[p], t[1] + offsets[p], t[2] + offsets[p] });
        }
      }
    }
    meshes.emplace_back(points, triangles);
  }
  for (std::size_t m = 0; m < meshes.size(); ++m)
  {
    SCOPED_TRACE("mesh " + std::to_string(m));
    const TriangleMesh& mesh = meshes[m];
    const std::vector<TriangleMesh> parts = mesh.componentMeshes();
    ASSERT_EQ(static_cast<int>(parts.size()), mesh.componentCount());
    for (int c = 0; c < mesh.componentCount(); ++c)
    {
      std::vector<int> local(static_cast<std::size_t>(mesh.vertexCount()), -1);
      std::vector<Vector3> points;
      for (int v = 0; v < mesh.vertexCount(); ++v)
      {
        if (mesh.vertexComponent(v) == c)
        {
          local[static_cast<std::size_t>(v)] = static_cast<int>(points.size());
          points.push_back(mesh.point(v));
        }
      }
      std::vector<Triangle> triangles;
      for (int f = 0; f < mesh.faceCount(); ++f)
      {
        if (mesh.faceComponent(f) == c)
        {
          const Triangle& t = mesh.triangle(f);
          triangles.push_back({ local[static_cast<std::size_t>(t[0])], local[static_cast<std::size_t>(t[1])],
            local[static_cast<std::size_t>(t[2])] });
        }
      }
      SCOPED_TRACE("component " + std::to_string(c));
      expectSameMesh(parts[static_cast<std::size_t>(c)], TriangleMesh(points, triangles));
    }
  }
  EXPECT_EQ(meshes[2].componentCount(), 3);
}

// Refinements that join or split components, where the components cannot be copied.
TEST(TriangleMesh, RefinedFindsComponentsThatChange)
{
  const TriangleMesh two({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 5, 0, 0 }, { 6, 0, 0 }, { 5, 1, 0 }, { 9, 9, 9 } },
    { { 0, 1, 2 }, { 3, 4, 5 } });
  std::vector<Vector3> points = two.points();
  points.emplace_back(3, 0, 0); // 7
  const std::vector<std::pair<std::vector<Triangle>, std::vector<int>>> cases = {
    // A piece of triangle 0 reaching vertex 3 of the other component.
    { { { 0, 1, 7 }, { 1, 2, 7 }, { 2, 0, 7 }, { 7, 3, 1 }, { 3, 4, 5 } }, { 0, 0, 0, 0, 1 } },
    // A new vertex in the pieces of both triangles.
    { { { 0, 1, 7 }, { 1, 2, 7 }, { 2, 0, 7 }, { 3, 4, 7 }, { 4, 5, 7 }, { 5, 3, 7 } }, { 0, 0, 0, 1, 1, 1 } },
    // Triangle 1 dropped, triangle 0 split.
    { { { 0, 1, 7 }, { 1, 2, 7 }, { 2, 0, 7 } }, { 0, 0, 0 } },
    // Triangle 0 split into pieces that leave corner 2 out.
    { { { 0, 1, 7 }, { 3, 4, 5 } }, { 0, 1 } },
  };
  for (std::size_t c = 0; c < cases.size(); ++c)
  {
    SCOPED_TRACE("case " + std::to_string(c));
    expectSameMesh(two.refined(points, cases[c].first, cases[c].second), TriangleMesh(points, cases[c].first));
  }
}

TEST(TriangleMesh, RefinedRefusesWhatDoesNotFit)
{
  const TriangleMesh grid = makeGrid(2.0, 2.0, 2, 2);
  std::vector<Triangle> triangles = grid.triangles();
  std::vector<int> originalFaces;
  for (int f = 0; f < grid.faceCount(); ++f)
  {
    originalFaces.push_back(f);
  }
  EXPECT_THROW(grid.refined(grid.points(), triangles, std::vector<int>(2, 0)), Error);
  EXPECT_THROW(grid.refined(std::vector<Vector3>(2), triangles, originalFaces), Error);
  std::vector<int> decreasing = originalFaces;
  std::swap(decreasing[1], decreasing[2]);
  EXPECT_THROW(grid.refined(grid.points(), triangles, decreasing), Error);
  std::vector<int> outside = originalFaces;
  outside.back() = grid.faceCount();
  EXPECT_THROW(grid.refined(grid.points(), triangles, outside), Error);
  // A piece naming a point that does not exist: the constructor's sentence.
  triangles[3] = Triangle{ 0, 1, 99 };
  std::string expected;
  try
  {
    TriangleMesh(grid.points(), triangles);
  }
  catch (const Error& error)
  {
    expected = error.what();
  }
  try
  {
    grid.refined(grid.points(), triangles, originalFaces);
    FAIL() << "no error";
  }
  catch (const Error& error)
  {
    EXPECT_EQ(std::string(error.what()), expected);
  }
}

TEST(MeshValidation, NonManifoldEdge)
{
  // Three triangles around the edge (0, 1).
  const TriangleMesh mesh(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 } }, { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } });
  const MeshReport report = inspectMesh(mesh);
  EXPECT_EQ(report.nonManifoldEdges, 1);
  const std::string problems = describeProblems(report, MeshRequirements{});
  EXPECT_NE(problems.find("1 edge is non-manifold"), std::string::npos) << problems;
  MeshRequirements lenient;
  lenient.manifold = false;
  lenient.consistentOrientation = false;
  EXPECT_EQ(describeProblems(report, lenient), "");
}

TEST(MeshValidation, BowtieVertex)
{
  const TriangleMesh mesh(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { -1, 0, 0 }, { -1, -1, 0 } }, { { 0, 1, 2 }, { 0, 3, 4 } });
  const MeshReport report = inspectMesh(mesh);
  EXPECT_EQ(report.nonManifoldVertices, 1);
  EXPECT_EQ(report.nonManifoldEdges, 0);
  EXPECT_EQ(report.components, 1);
}

// inspectMesh finds pinched vertices by walking each vertex's fan and duplicates through the
// edge they share, with a fuller search where those shortcuts cannot tell: both counts equal a
// search over all pairs of triangles on tangled triangle soups (pinches, closed fans meeting at
// a vertex, duplicates two and three deep, edges of three and more triangles, mixed orientation).
TEST(MeshValidation, PinchesAndDuplicatesEqualAnExhaustiveSearch)
{
  std::mt19937 random(20261126);
  int pinchedSeen = 0;
  int duplicatesSeen = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    const int n = 5 + trial % 9;
    std::vector<Vector3> points;
    for (int v = 0; v < n; ++v)
    {
      points.emplace_back(std::cos(v * 2.4), std::sin(v * 1.7), 0.1 * v);
    }
    // A fan or two around vertex 0 (closed or open), then random triangles and copies.
    std::vector<Triangle> triangles;
    const int ring = std::min(n - 1, 4 + trial % 4);
    for (int i = 0; i < ring; ++i)
    {
      if (i + 1 < ring || trial % 2 == 0)
      {
        triangles.push_back({ { 0, 1 + i, 1 + (i + 1) % ring } });
      }
    }
    std::uniform_int_distribution<int> vertex(0, n - 1);
    const int extra = 2 + trial % 7;
    for (int i = 0; i < extra; ++i)
    {
      Triangle t{ { vertex(random), vertex(random), vertex(random) } };
      if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0])
      {
        triangles.push_back(t);
      }
    }
    const int copies = trial % 3;
    for (int i = 0; i < copies && !triangles.empty(); ++i)
    {
      Triangle t = triangles[std::uniform_int_distribution<int>(0, static_cast<int>(triangles.size()) - 1)(random)];
      if (random() % 2)
      {
        std::swap(t[1], t[2]);
      }
      triangles.push_back(t);
    }
    const TriangleMesh mesh(points, triangles);
    const MeshReport report = inspectMesh(mesh);

    // Pinched vertices: the triangles at v joined across sides at v held by exactly two triangles.
    auto sideHolders = [&](int a, int b) {
      int count = 0;
      for (const Triangle& t : triangles)
      {
        count += std::count(t.begin(), t.end(), a) && std::count(t.begin(), t.end(), b) ? 1 : 0;
      }
      return count;
    };
    int pinched = 0;
    for (int v = 0; v < n; ++v)
    {
      std::vector<int> around;
      for (int f = 0; f < static_cast<int>(triangles.size()); ++f)
      {
        if (std::count(triangles[f].begin(), triangles[f].end(), v))
        {
          around.push_back(f);
        }
      }
      std::vector<int> fan(around.size());
      std::iota(fan.begin(), fan.end(), 0);
      for (bool changed = true; changed;)
      {
        changed = false;
        for (std::size_t i = 0; i < around.size(); ++i)
        {
          for (std::size_t j = 0; j < around.size(); ++j)
          {
            for (int w : triangles[around[i]])
            {
              if (w != v && std::count(triangles[around[j]].begin(), triangles[around[j]].end(), w) && i != j &&
                sideHolders(v, w) == 2 && fan[j] > fan[i])
              {
                fan[j] = fan[i];
                changed = true;
              }
            }
          }
        }
      }
      pinched += std::set<int>(fan.begin(), fan.end()).size() > 1 ? 1 : 0;
    }
    int duplicates = 0;
    for (std::size_t f = 0; f < triangles.size(); ++f)
    {
      Triangle sorted = triangles[f];
      std::sort(sorted.begin(), sorted.end());
      for (std::size_t g = 0; g < f; ++g)
      {
        Triangle other = triangles[g];
        std::sort(other.begin(), other.end());
        if (other == sorted)
        {
          ++duplicates;
          break;
        }
      }
    }
    ASSERT_EQ(report.nonManifoldVertices, pinched) << "trial " << trial;
    ASSERT_EQ(report.duplicateFaces, duplicates) << "trial " << trial;
    pinchedSeen += pinched > 0 ? 1 : 0;
    duplicatesSeen += duplicates > 1 ? 1 : 0;
  }
  // The soups do hold what the shortcuts must hand over to the fuller search.
  EXPECT_GT(pinchedSeen, 100);
  EXPECT_GT(duplicatesSeen, 10);
}

TEST(MeshValidation, FlippedTriangle)
{
  TriangleMesh grid = makeGrid(1.0, 1.0, 3, 3);
  std::vector<Triangle> triangles = grid.triangles();
  std::swap(triangles[8][1], triangles[8][2]); // an interior triangle
  const TriangleMesh flipped(grid.points(), triangles);
  const MeshReport report = inspectMesh(flipped);
  EXPECT_EQ(report.inconsistentEdges, 3);
  EXPECT_NE(describeProblems(report, MeshRequirements{}).find("inconsistently oriented"), std::string::npos);
}

TEST(MeshValidation, DegenerateDuplicateAndNonFinite)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const TriangleMesh mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 2, 0, 0 }, { nan, 0, 0 } },
    {
      { 0, 1, 2 }, // fine
      { 2, 1, 0 }, // duplicate of the first, opposite orientation
      { 0, 1, 3 }, // collinear: zero area
      { 0, 0, 2 }, // repeats a vertex
    });
  const MeshReport report = inspectMesh(mesh);
  EXPECT_EQ(report.duplicateFaces, 1);
  EXPECT_EQ(report.zeroAreaFaces, 1);
  EXPECT_EQ(report.repeatedVertexFaces, 1);
  EXPECT_EQ(report.nonFinitePoints, 1);
  EXPECT_EQ(report.unreferencedVertices, 1);
  const std::string problems = describeProblems(report, MeshRequirements{});
  EXPECT_NE(problems.find("NaN or infinite"), std::string::npos) << problems;
  EXPECT_NE(problems.find("same point twice"), std::string::npos) << problems;
  EXPECT_NE(problems.find("duplicates another"), std::string::npos) << problems;
  EXPECT_EQ(problems.find("zero area"), std::string::npos) << "zero area is allowed by default";
  MeshRequirements strict;
  strict.allowZeroAreaFaces = false;
  EXPECT_NE(describeProblems(report, strict).find("1 triangle has zero area"), std::string::npos);
  EXPECT_NE(report.summary().find("1 duplicate triangle"), std::string::npos) << report.summary();
}

TEST(MeshValidation, ClosedSurfaceRequirement)
{
  MeshRequirements closed;
  closed.allowBoundary = false;
  EXPECT_NE(
    describeProblems(inspectMesh(makeCylinder(1.0, 1.0, 8, 3)), closed).find("2 boundary loops"), std::string::npos);
  EXPECT_EQ(describeProblems(inspectMesh(makeIcosphere(1.0, 1)), closed), "");
}

TEST(OpenMeshAdapter, RoundTripKeepsNumbering)
{
  const TriangleMesh torus = makeTorus(2.0, 0.7, 24, 10);
  const EditableMesh editable = toEditableMesh(torus);
  EXPECT_EQ(static_cast<int>(editable.n_vertices()), torus.vertexCount());
  EXPECT_EQ(static_cast<int>(editable.n_edges()), torus.edgeCount());
  EXPECT_EQ(static_cast<int>(editable.n_faces()), torus.faceCount());
  const TriangleMesh back = fromEditableMesh(editable);
  ASSERT_EQ(back.faceCount(), torus.faceCount());
  for (int f = 0; f < torus.faceCount(); ++f)
  {
    // OpenMesh may start a face at another corner; the cyclic order is kept.
    const Triangle& a = torus.triangle(f);
    const Triangle& b = back.triangle(f);
    const bool same =
      (a == b) || (a[0] == b[1] && a[1] == b[2] && a[2] == b[0]) || (a[0] == b[2] && a[1] == b[0] && a[2] == b[1]);
    EXPECT_TRUE(same) << "face " << f;
  }
  for (int v = 0; v < torus.vertexCount(); ++v)
  {
    EXPECT_EQ(back.point(v), torus.point(v));
  }
}

TEST(OpenMeshAdapter, RefusesNonManifoldInput)
{
  const TriangleMesh mesh(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 } }, { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } });
  EXPECT_THROW(toEditableMesh(mesh), Error);
}

TEST(PointWelding, IdenticalCoordinatesShareTheFirstIndex)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Vector3> points = { { 0, 0, 0 }, { 1, 2, 3 }, { -0.0, 0, 0 }, { 1, 2, 3 }, { 1, 2, 3.0000000001 },
    { nan, 0, 0 }, { nan, 0, 0 } };
  EXPECT_EQ(findCoincidentPoints(points), (std::vector<int>{ 0, 1, 0, 1, 4, 5, 6 }));
  std::vector<Triangle> triangles = { { 3, 2, 4 } };
  weldTriangles(findCoincidentPoints(points), triangles);
  EXPECT_EQ(triangles[0], (Triangle{ 1, 0, 4 }));
  // Many points: a torus's own points are distinct; every duplicate finds its original.
  const TriangleMesh torus = makeTorus(2.0, 0.5, 200, 100);
  std::vector<Vector3> doubled = torus.points();
  doubled.insert(doubled.end(), torus.points().begin(), torus.points().end());
  const std::vector<int> rep = findCoincidentPoints(doubled);
  for (int v = 0; v < torus.vertexCount(); ++v)
  {
    ASSERT_EQ(rep[v], v);
    ASSERT_EQ(rep[v + torus.vertexCount()], v);
  }
}

TEST(TriangleMesh, ProblemsNameTheirFirstPlaces)
{
  // Three triangles on edge 0-1, a zero-area triangle, a duplicate (which makes edge 8-9 non-manifold).
  const TriangleMesh fan({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 2, 0, 0 }, { 3, 0, 0 },
                           { 5, 5, 0 }, { 6, 5, 0 }, { 5, 6, 0 }, { 6, 6, 0 } },
    { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 }, { 1, 5, 6 }, { 7, 8, 9 }, { 8, 10, 9 }, { 9, 10, 8 } });
  const MeshReport report = inspectMesh(fan);
  EXPECT_EQ(report.nonManifoldEdgeIds, (std::vector<std::array<int, 2>>{ { 0, 1 }, { 8, 9 } }));
  EXPECT_EQ(report.zeroAreaFaceIds, std::vector<int>{ 3 });
  EXPECT_EQ(report.duplicateFaceIds, std::vector<int>{ 6 });
  MeshRequirements strict;
  strict.allowZeroAreaFaces = false;
  const std::string named = describeProblems(report, strict);
  EXPECT_NE(
    named.find("2 edges are non-manifold (shared by three or more triangles: points 0-1, 8-9)"), std::string::npos)
    << named;
  EXPECT_NE(named.find("1 triangle has zero area (collinear or coincident corners: triangles 3)"), std::string::npos)
    << named;
  const std::vector<long long> cells = { 10, 11, 12, 13, 14, 15, 16 };
  EXPECT_NE(describeProblems(report, strict, &cells).find("same three points: cells 16"), std::string::npos);

  // More defects than examples: the first five, then an ellipsis.
  std::vector<Vector3> points;
  std::vector<Triangle> triangles;
  for (int i = 0; i < 8; ++i)
  {
    points.push_back({ 3.0 * i, 0, 0 });
    points.push_back({ 3.0 * i + 1, 0, 0 });
    points.push_back({ 3.0 * i + 2, 0, 0 });
    triangles.push_back({ 3 * i, 3 * i + 1, 3 * i + 2 });
  }
  const std::string many = describeProblems(inspectMesh(TriangleMesh(points, triangles)), strict);
  EXPECT_NE(many.find("8 triangles have zero area (collinear or coincident corners: triangles 0, 1, 2, 3, 4, ...)"),
    std::string::npos)
    << many;
}

TEST(UnionFind, TheSmallerRootWinsWhateverTheOrderOfTheJoins)
{
  // The same three trees joined in two orders give the same parents' roots: 0 for {0, 3, 5, 7},
  // 1 for {1, 4}, 2 for {2, 6}; a join within a tree reports false.
  const std::vector<std::array<int, 2>> joins{ { 7, 5 }, { 3, 7 }, { 4, 1 }, { 6, 2 }, { 5, 0 } };
  for (const bool reversed : { false, true })
  {
    UnionFind forest(8);
    for (std::size_t i = 0; i < joins.size(); ++i)
    {
      const auto& join = joins[reversed ? joins.size() - 1 - i : i];
      EXPECT_TRUE(reversed ? forest.join(join[1], join[0]) : forest.join(join[0], join[1]));
    }
    EXPECT_FALSE(forest.join(3, 5));
    const std::vector<int> expected{ 0, 1, 2, 0, 1, 0, 2, 0 };
    for (int v = 0; v < 8; ++v)
    {
      EXPECT_EQ(forest.find(v), expected[static_cast<std::size_t>(v)])
        << "vertex " << v << (reversed ? " reversed" : "");
    }
  }
  // findRoot on a raw array halves the path: after one call every node of the chain 4 -> 3 -> 2
  // -> 1 -> 0 points two steps closer to the root.
  int parent[5] = { 0, 0, 1, 2, 3 };
  EXPECT_EQ(findRoot(parent, 4), 0);
  EXPECT_EQ(parent[4], 2);
  EXPECT_EQ(parent[2], 0);
}
