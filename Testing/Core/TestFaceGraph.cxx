// The dual graph: the signed bend of an edge between unequal faces, and its cache on a surface.
#include "Mesh/MeshGenerators.h"
#include "Segmentation/ConvexFlooding.h"
#include "Segmentation/FaceGraph.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
// A large triangle in z = 0 and a small one hinged on the x axis, lifted by `angle` towards the
// normal (+z) side: a valley (concave) for angle > 0, a ridge (convex) for angle < 0.
kerf::TriangleMesh Hinge(double angle)
{
  std::vector<kerf::Vector3> points{ { 0.0, 0.0, 0.0 }, { 1.0, 0.0, 0.0 }, { 0.3, -2.0, 0.0 },
    { 0.6, 0.2 * std::cos(angle), 0.2 * std::sin(angle) } };
  return kerf::TriangleMesh(std::move(points), { { 1, 0, 2 }, { 0, 1, 3 } });
}
} // namespace

TEST(FaceGraph, BendIsSignedByConvexityForUnequalFaces)
{
  for (double angle : { -1.2, -0.5, -0.05, 0.05, 0.5, 1.2 })
  {
    const kerf::TriangleMesh mesh = Hinge(angle);
    const kerf::FaceGraph graph(mesh);
    ASSERT_EQ(graph.edgeCount(), 1);
    // The normals turn by |angle|; the bend is positive on a ridge, negative in a valley.
    EXPECT_NEAR(graph.edge(0).bend, -angle, 1e-12) << "angle " << angle;
    EXPECT_NEAR(graph.edge(0).normalCosine, std::cos(angle), 1e-12);
  }
}

TEST(FaceGraph, CachedOnTheSurface)
{
  const kerf::Surface surface(kerf::makeIcosphere(1.0, 2));
  const int before = surface.computations();
  const kerf::FaceGraph& graph = kerf::faceGraph(surface);
  EXPECT_EQ(&graph, &kerf::faceGraph(surface));
  EXPECT_EQ(surface.computations(), before + 1);
  EXPECT_EQ(graph.faceCount(), 320);
  EXPECT_EQ(graph.edgeCount(), 480);
  // A closed convex surface: every edge is convex, and flooding keeps it one patch.
  for (const kerf::DualEdge& edge : graph.edges())
  {
    EXPECT_GT(edge.bend, 0.0);
  }
  EXPECT_EQ(kerf::segmentByConvexFlooding(graph, {}).segmentCount, 1);
}
