// The convex hull in 3D against analytic answers: a cube's corners and faces, interior points' depths, a sphere's
// vertices, flat and bad input.
#include "Error.h"
#include "Geometry/ConvexHull.h"
#include "Mesh/MeshGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace kerf
{
namespace
{

TEST(ConvexHull, CubeCornersAndInteriorPoints)
{
  std::vector<Vector3> points;
  for (int i = 0; i < 8; ++i)
  {
    points.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  }
  points.emplace_back(0.0, 0.0, 0.0);   // depth 1
  points.emplace_back(0.5, 0.25, -0.1); // depth 0.5 (to x = 1)
  points.emplace_back(1.0, 0.3, 0.2);   // on a face: depth 0
  const ConvexHull hull = convexHull(points, 1e-12);
  ASSERT_FALSE(hull.flat);
  EXPECT_EQ(hull.faces.size(), 12u); // two triangles per side
  std::set<int> corners;
  for (const Triangle& t : hull.faces)
  {
    corners.insert(t.begin(), t.end());
  }
  EXPECT_EQ(corners.size(), 8u);
  EXPECT_EQ(*corners.rbegin(), 7);
  const std::vector<double> depths = hullDepths(hull, points);
  for (int i = 0; i < 8; ++i)
  {
    EXPECT_NEAR(depths[i], 0.0, 1e-14);
  }
  EXPECT_NEAR(depths[8], 1.0, 1e-14);
  EXPECT_NEAR(depths[9], 0.5, 1e-14);
  EXPECT_NEAR(depths[10], 0.0, 1e-14);
  // Every face is outward: the interior point lies behind all of them.
  for (std::size_t f = 0; f < hull.faces.size(); ++f)
  {
    EXPECT_LT(hull.normals[f].dot(points[8]), hull.offsets[f]);
  }
}

TEST(ConvexHull, SpherePointsAreAllOnIt)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  const ConvexHull hull = convexHull(sphere.points(), 1e-12);
  // A convex polyhedron with every point a vertex: Euler's 2V - 4 triangles.
  EXPECT_EQ(static_cast<int>(hull.faces.size()), 2 * sphere.vertexCount() - 4);
  for (double depth : hullDepths(hull, sphere.points()))
  {
    EXPECT_LT(depth, 1e-12);
  }
}

TEST(ConvexHull, FlatAndBadInput)
{
  std::vector<Vector3> plane;
  for (int i = 0; i < 20; ++i)
  {
    plane.emplace_back(std::cos(i), std::sin(2.0 * i), 0.0);
  }
  EXPECT_TRUE(convexHull(plane, 1e-9).flat);
  EXPECT_TRUE(convexHull({ Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, 1, 0) }, 0.0).flat);
  EXPECT_TRUE(convexHull({}, 0.0).flat);
  plane[3].z() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(convexHull(plane, 0.0), Error);
  EXPECT_THROW(convexHull({ Vector3(0, 0, 0) }, -1.0), Error);
}

TEST(ConvexHull, LargestDepthAsAFractionOfTheDiagonal)
{
  // A unit cube's corners and its centre: the centre is 0.5 below every face, the diagonal sqrt(3).
  std::vector<Vector3> cube;
  for (int i = 0; i < 8; ++i)
  {
    cube.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  }
  cube.emplace_back(0.5, 0.5, 0.5);
  EXPECT_NEAR(largestHullDepthFraction(cube, 100), 0.5 / std::sqrt(3.0), 1e-12);
  // A sphere's vertices are all on the hull; with 40 samples of its 642, still none inside.
  const TriangleMesh sphere = makeIcosphere(2.0, 3);
  EXPECT_LT(largestHullDepthFraction(sphere.points(), 100000), 1e-12);
  EXPECT_LT(largestHullDepthFraction(sphere.points(), 40), 1e-12);
  // Every s-th point stands for the set, the first included: the sphere's centre first, then its
  // 642 vertices, at most 40 samples (s = 17): the centre and 38 vertices, whose hull lies inside
  // the sphere (the centre at most the radius 2 deep) and holds most of it.
  std::vector<Vector3> centred{ Vector3(0, 0, 0) };
  centred.insert(centred.end(), sphere.points().begin(), sphere.points().end());
  Vector3 lowest = centred[0], highest = centred[0];
  for (const Vector3& p : centred)
  {
    lowest = lowest.cwiseMin(p);
    highest = highest.cwiseMax(p);
  }
  const double diagonal = (highest - lowest).norm();
  // All samples: the centre lies the hull's inradius deep (the flat faces' planes a little inside the sphere).
  EXPECT_LE(largestHullDepthFraction(centred, 100000), 2.0 / diagonal);
  EXPECT_GE(largestHullDepthFraction(centred, 100000), 0.98 * 2.0 / diagonal);
  EXPECT_LE(largestHullDepthFraction(centred, 40), 2.0 / diagonal);
  EXPECT_GE(largestHullDepthFraction(centred, 40), 0.7 * 2.0 / diagonal);
  // A torus of radii 1 and 0.3: its inner equator (radius 0.7, z = 0) lies 0.3 below the hull's
  // planes z = +-0.3, and the bounding box is 2.6 x 2.6 x 0.6.
  const TriangleMesh torus = makeTorus(1.0, 0.3, 64, 32);
  EXPECT_NEAR(largestHullDepthFraction(torus.points(), 100000), 0.3 / std::sqrt(2.6 * 2.6 * 2 + 0.6 * 0.6), 2e-3);
  // A flat set, one point, none: 0.
  std::vector<Vector3> plane;
  for (int i = 0; i < 20; ++i)
  {
    plane.emplace_back(std::cos(i), std::sin(2.0 * i), 0.0);
  }
  EXPECT_EQ(largestHullDepthFraction(plane, 100), 0.0);
  EXPECT_EQ(largestHullDepthFraction({ Vector3(1, 2, 3), Vector3(1, 2, 3) }, 100), 0.0);
  EXPECT_EQ(largestHullDepthFraction({}, 100), 0.0);
  EXPECT_THROW(largestHullDepthFraction(cube, 3), Error);
  cube[2].y() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(largestHullDepthFraction(cube, 100), Error);
}

} // namespace
} // namespace kerf
