// Curvature, concavity and normal-cone accuracy of kerf::computeSurfaceDescriptors on analytic surfaces.
#include "Geometry/SurfaceDescriptors.h"
#include "Mesh/MeshGenerators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

using namespace kerf;

namespace
{
constexpr double Pi = 3.14159265358979323846;

double mean(const std::vector<double>& values)
{
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double angleBetweenLines(const Vector3& a, const Vector3& b)
{
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized()))));
}
} // namespace

TEST(SurfaceDescriptors, SphereCurvatureWithinTwoPercent)
{
  const double radius = 2.5;
  const TriangleMesh sphere = makeIcosphere(radius, 5);
  ASSERT_GE(sphere.vertexCount(), 10000);
  const SurfaceDescriptors d = computeSurfaceDescriptors(sphere);
  std::vector<double> e1, e2, eh;
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    e1.push_back(std::abs(d.maximumCurvature[v] - 1.0 / radius) * radius);
    e2.push_back(std::abs(d.minimumCurvature[v] - 1.0 / radius) * radius);
    eh.push_back(std::abs(d.meanCurvature[v] - 1.0 / radius) * radius);
    EXPECT_GE(d.maximumCurvature[v], d.minimumCurvature[v]);
    EXPECT_NEAR(d.normals[v].dot(sphere.point(v).normalized()), 1.0, 1e-6);
    EXPECT_NEAR(d.gaussianCurvature[v], d.maximumCurvature[v] * d.minimumCurvature[v], 1e-15);
  }
  EXPECT_LE(mean(e1), 0.02);
  EXPECT_LE(mean(e2), 0.02);
  EXPECT_LE(mean(eh), 0.02);
  RecordProperty("MeanRelativeErrorK1", std::to_string(mean(e1)));
  RecordProperty("MeanRelativeErrorMean", std::to_string(mean(eh)));
}

TEST(SurfaceDescriptors, CylinderAwayFromRims)
{
  const double radius = 1.5, height = 6.0;
  const int around = 128;
  // Rings spaced like the vertices around, so that triangles are close to isosceles right ones.
  const int rings = static_cast<int>(height / (2.0 * Pi * radius / around)) + 1;
  const TriangleMesh cylinder = makeCylinder(radius, height, around, rings);
  const SurfaceDescriptors d = computeSurfaceDescriptors(cylinder);
  double axisAngleSum = 0.0;
  int inner = 0;
  for (int v = 0; v < cylinder.vertexCount(); ++v)
  {
    const double z = cylinder.point(v).z();
    if (z < 1.0 || z > height - 1.0)
    {
      continue;
    }
    ++inner;
    EXPECT_NEAR(d.maximumCurvature[v], 1.0 / radius, 0.03 / radius) << "vertex " << v;
    EXPECT_NEAR(d.minimumCurvature[v], 0.0, 0.03 / radius) << "vertex " << v;
    axisAngleSum += angleBetweenLines(d.minimumDirections[v], Vector3::UnitZ());
    EXPECT_NEAR(d.maximumDirections[v].dot(d.minimumDirections[v]), 0.0, 1e-12);
    EXPECT_NEAR(d.maximumDirections[v].norm(), 1.0, 1e-12);
  }
  ASSERT_GT(inner, 1000);
  EXPECT_LE(axisAngleSum / inner, 5.0 * Pi / 180.0);
}

TEST(SurfaceDescriptors, TorusMatchesClosedForm)
{
  const double R = 3.0, r = 1.0;
  const int around = 360, tube = 120;
  const TriangleMesh torus = makeTorus(R, r, around, tube);
  const SurfaceDescriptors d = computeSurfaceDescriptors(torus);
  int checked = 0;
  for (int i = 0; i < around; ++i)
  {
    for (int j = 0; j < tube; ++j)
    {
      const int v = i * tube + j;
      const double phi = 2.0 * Pi * j / tube;
      const double kTube = 1.0 / r;
      const double kAround = std::cos(phi) / (R + r * std::cos(phi));
      const double k1 = std::max(kTube, kAround), k2 = std::min(kTube, kAround);
      EXPECT_NEAR(d.maximumCurvature[v], k1, 0.03 * std::abs(k1)) << "vertex " << v;
      // Away from the parabolic circles (k2 = 0) a relative bound is meaningful.
      if (std::abs(k2) >= 0.1 * kTube)
      {
        EXPECT_NEAR(d.minimumCurvature[v], k2, 0.03 * std::abs(k2)) << "vertex " << v;
        ++checked;
      }
      else
      {
        EXPECT_NEAR(d.minimumCurvature[v], k2, 0.003 * kTube) << "vertex " << v;
      }
    }
  }
  EXPECT_GT(checked, around * tube / 4);
}

TEST(SurfaceDescriptors, IndependentOfVertexAndFaceOrder)
{
  const TriangleMesh torus = makeTorus(2.0, 0.8, 60, 24);
  const int n = torus.vertexCount();
  std::vector<int> permutation(n);
  std::iota(permutation.begin(), permutation.end(), 0);
  std::mt19937 random(12345);
  std::shuffle(permutation.begin(), permutation.end(), random);
  std::vector<Vector3> points(n);
  for (int v = 0; v < n; ++v)
  {
    points[permutation[v]] = torus.point(v);
  }
  std::vector<Triangle> triangles;
  for (const Triangle& t : torus.triangles())
  {
    // Rotate the corners and renumber.
    triangles.push_back({ permutation[t[1]], permutation[t[2]], permutation[t[0]] });
  }
  std::reverse(triangles.begin(), triangles.end());
  const TriangleMesh shuffled(points, triangles);
  const SurfaceDescriptors a = computeSurfaceDescriptors(torus);
  const SurfaceDescriptors b = computeSurfaceDescriptors(shuffled);
  for (int v = 0; v < n; ++v)
  {
    const int w = permutation[v];
    EXPECT_NEAR(a.maximumCurvature[v], b.maximumCurvature[w], 1e-9);
    EXPECT_NEAR(a.minimumCurvature[v], b.minimumCurvature[w], 1e-9);
    EXPECT_NEAR(a.meanCurvature[v], b.meanCurvature[w], 1e-9);
    EXPECT_NEAR((a.normals[v] - b.normals[w]).norm(), 0.0, 1e-12);
    EXPECT_LE(angleBetweenLines(a.maximumDirections[v], b.maximumDirections[w]), 1e-5);
    EXPECT_EQ(a.concave[v], b.concave[w]);
    EXPECT_NEAR(a.normalConeAngle[v], b.normalConeAngle[w], 1e-12);
  }
}

TEST(SurfaceDescriptors, CurvatureScalesAsOneOverLength)
{
  const TriangleMesh torus = makeTorus(2.0, 0.8, 60, 24);
  const double scale = 7.25;
  std::vector<Vector3> points = torus.points();
  for (Vector3& p : points)
  {
    p *= scale;
  }
  const TriangleMesh scaled(points, torus.triangles());
  const SurfaceDescriptors a = computeSurfaceDescriptors(torus);
  const SurfaceDescriptors b = computeSurfaceDescriptors(scaled);
  for (int v = 0; v < torus.vertexCount(); ++v)
  {
    EXPECT_NEAR(b.maximumCurvature[v] * scale, a.maximumCurvature[v], 1e-10);
    EXPECT_NEAR(b.minimumCurvature[v] * scale, a.minimumCurvature[v], 1e-10);
    EXPECT_NEAR(b.gaussianCurvature[v] * scale * scale, a.gaussianCurvature[v], 1e-10);
    EXPECT_NEAR(b.normalConeAngle[v], a.normalConeAngle[v], 1e-12);
    EXPECT_EQ(b.concave[v], a.concave[v]);
  }
}

TEST(SurfaceDescriptors, ConcavityFollowsTheNormalSide)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  std::vector<Triangle> inward;
  for (const Triangle& t : sphere.triangles())
  {
    inward.push_back({ t[0], t[2], t[1] });
  }
  const SurfaceDescriptors outside = computeSurfaceDescriptors(sphere);
  const SurfaceDescriptors inside = computeSurfaceDescriptors(TriangleMesh(sphere.points(), inward));
  EXPECT_EQ(std::count(outside.concave.begin(), outside.concave.end(), 1), 0);
  EXPECT_EQ(std::count(inside.concave.begin(), inside.concave.end(), 1), sphere.vertexCount());
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    EXPECT_LT(inside.meanCurvature[v], 0.0);
  }

  // A paraboloid cup z = a (x^2 + y^2) with upward normals bends towards its normal: concave,
  // with k1 = k2 = -2a at the apex.
  const double a = 0.5;
  const int cells = 40;
  TriangleMesh grid = makeGrid(2.0, 2.0, cells, cells);
  std::vector<Vector3> points = grid.points();
  for (Vector3& p : points)
  {
    p.x() -= 1.0;
    p.y() -= 1.0;
    p.z() = a * (p.x() * p.x() + p.y() * p.y());
  }
  const TriangleMesh cup(points, grid.triangles());
  const SurfaceDescriptors d = computeSurfaceDescriptors(cup);
  for (int v = 0; v < cup.vertexCount(); ++v)
  {
    if (!cup.isBoundaryVertex(v))
    {
      EXPECT_EQ(d.concave[v], 1) << "vertex " << v;
    }
  }
  const int apex = (cells / 2) * (cells + 1) + cells / 2;
  EXPECT_NEAR(d.maximumCurvature[apex], -2.0 * a, 0.02 * 2.0 * a);
  EXPECT_NEAR(d.minimumCurvature[apex], -2.0 * a, 0.02 * 2.0 * a);
}

TEST(SurfaceDescriptors, NormalConeAngleOfAFold)
{
  // A grid folded along x = 1: the two halves' normals differ by twice the slope angle.
  const double slope = 0.3;
  const int cells = 10;
  TriangleMesh grid = makeGrid(2.0, 1.0, cells, cells);
  std::vector<Vector3> points = grid.points();
  for (Vector3& p : points)
  {
    p.z() = slope * std::abs(p.x() - 1.0);
  }
  const TriangleMesh fold(points, grid.triangles());
  const SurfaceDescriptors d = computeSurfaceDescriptors(fold);
  const double expected = 2.0 * std::atan(slope);
  for (int v = 0; v < fold.vertexCount(); ++v)
  {
    const double x = fold.point(v).x();
    if (std::abs(x - 1.0) < 1e-12)
    {
      EXPECT_NEAR(d.normalConeAngle[v], expected, 1e-12) << "crease vertex " << v;
    }
    else if (std::abs(x - 1.0) > 0.2 + 1e-9)
    {
      EXPECT_NEAR(d.normalConeAngle[v], 0.0, 1e-7) << "flat vertex " << v;
    }
  }
}

TEST(SurfaceDescriptors, DegenerateAndUnusedVerticesGiveFiniteZeros)
{
  // A flat square with a zero-area sliver and an unused point.
  const TriangleMesh mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 2, 0, 0 }, { 7, 7, 7 } },
    { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 4, 1 } });
  const SurfaceDescriptors d = computeSurfaceDescriptors(mesh);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    EXPECT_TRUE(std::isfinite(d.maximumCurvature[v]));
    EXPECT_TRUE(std::isfinite(d.minimumCurvature[v]));
    EXPECT_TRUE(d.normals[v].allFinite());
    EXPECT_TRUE(std::isfinite(d.normalConeAngle[v]));
  }
  EXPECT_EQ(d.normals[5], Vector3::Zero());
  EXPECT_EQ(d.maximumCurvature[5], 0.0);
  EXPECT_NEAR(d.normals[0].z(), 1.0, 1e-12);
  EXPECT_NEAR(d.maximumCurvature[2], 0.0, 1e-12);
}

TEST(SurfaceDescriptors, RightAngleBesideAHugeEdgeGivesFiniteCurvature)
{
  // A right angle at point 1 next to an edge 10^8 long: rounding the squared edge lengths makes
  // the corner at point 0 look obtuse, and the obtuse-corner area formula then divides by the
  // right angle's zero cosine (a triangle a fuzzed file produced).
  const TriangleMesh mesh(
    { { 0.30901700258255005, -0.42797544598579407, 5.2411874220866593e-17 },
      { -0.30901700258255005, -0.42797544598579407, 5.2411874220866593e-17 },
      { -0.30901700258255005, -0.21398772299289703, 99492272 }, { 0.30901700258255005, -0.21398772299289703, 0.5 } },
    { { 0, 1, 2 }, { 0, 2, 3 } });
  const SurfaceDescriptors d = computeSurfaceDescriptors(mesh);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    EXPECT_TRUE(std::isfinite(d.maximumCurvature[v])) << "point " << v;
    EXPECT_TRUE(std::isfinite(d.minimumCurvature[v])) << "point " << v;
    EXPECT_TRUE(d.maximumDirections[v].allFinite()) << "point " << v;
  }
}
