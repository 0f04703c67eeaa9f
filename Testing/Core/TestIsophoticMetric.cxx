// The improved isophotic metric: f(k), Euler's formula, lengths on a plane and a sphere, scale, caching and errors.
#include "Error.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Mesh/MeshGenerators.h"
#include "Segmentation/IsophoticMetric.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace kerf;

TEST(IsophoticMetric, AugmentationKeepsConvexAndAugmentsConcaveCurvature)
{
  for (CurvatureAugmentation g :
    { CurvatureAugmentation::Exponential, CurvatureAugmentation::Linear, CurvatureAugmentation::Square })
  {
    EXPECT_EQ(augmentedCurvature(2.5, g), 2.5);
    EXPECT_EQ(augmentedCurvature(0.0, g), 0.0);
  }
  EXPECT_DOUBLE_EQ(augmentedCurvature(-1.0, CurvatureAugmentation::Exponential), std::exp(1.0) - 1.0);
  EXPECT_DOUBLE_EQ(augmentedCurvature(-2.0, CurvatureAugmentation::Linear), 6.0);
  EXPECT_DOUBLE_EQ(augmentedCurvature(-2.0, CurvatureAugmentation::Square), 4.0);
  // Near zero, e^x - 1 is x: concave and convex weigh alike for gentle bends.
  EXPECT_NEAR(augmentedCurvature(-1e-8, CurvatureAugmentation::Exponential), 1e-8, 1e-16);
  // Capped: no overflow for absurd curvature.
  EXPECT_DOUBLE_EQ(augmentedCurvature(-1e6, CurvatureAugmentation::Exponential), std::expm1(AugmentationLimit));
  EXPECT_TRUE(std::isfinite(augmentedCurvature(-std::numeric_limits<double>::max(), CurvatureAugmentation::Square)));
  EXPECT_EQ(parseCurvatureAugmentation("square"), CurvatureAugmentation::Square);
  EXPECT_THROW(parseCurvatureAugmentation("cubic"), Error);
}

TEST(IsophoticMetric, EulerFormulaOnACylinder)
{
  // Radius 2: k = 1/2 around, 0 along the axis, and k1 cos^2 + k2 sin^2 in between.
  const double radius = 2.0;
  const TriangleMesh cylinder = makeCylinder(radius, 4.0, 128, 64);
  const SurfaceDescriptors descriptors = computeSurfaceDescriptors(cylinder);
  const int v = 32 * 128 + 5; // an interior ring
  const Vector3 p = cylinder.point(v);
  const Vector3 around = Vector3(-p.y(), p.x(), 0.0).normalized();
  const Vector3 axis(0.0, 0.0, 1.0);
  EXPECT_NEAR(normalCurvature(descriptors, v, around), 1.0 / radius, 0.01 / radius);
  EXPECT_NEAR(normalCurvature(descriptors, v, axis), 0.0, 0.01 / radius);
  for (double phi : { 0.3, 0.7848, 1.2 })
  {
    const Vector3 direction = std::cos(phi) * around + std::sin(phi) * axis;
    EXPECT_NEAR(
      normalCurvature(descriptors, v, 3.0 * direction), std::cos(phi) * std::cos(phi) / radius, 0.01 / radius);
  }
  // A component along the normal does not count; along the normal alone, the mean curvature.
  const Vector3 normal = descriptors.normals[v];
  EXPECT_NEAR(normalCurvature(descriptors, v, around + 5.0 * normal), normalCurvature(descriptors, v, around), 1e-12);
  EXPECT_DOUBLE_EQ(normalCurvature(descriptors, v, normal), descriptors.meanCurvature[v]);
}

TEST(IsophoticMetric, FlatSurfaceHasEuclideanLengths)
{
  const TriangleMesh grid = makeGrid(3.0, 2.0, 30, 20);
  const std::vector<double> lengths = isophoticEdgeLengths(grid, computeSurfaceDescriptors(grid), {});
  for (int e = 0; e < grid.edgeCount(); ++e)
  {
    const auto [a, b] = grid.edgeVertices(e);
    EXPECT_NEAR(lengths[e], (grid.point(a) - grid.point(b)).norm(), 1e-12);
  }
}

TEST(IsophoticMetric, SphereLengthsFollowTheFormula)
{
  // Radius R: normals n = p / R, so |n_p - n_q| = |p - q| / R, and k = 1/R in every direction. In
  // the unit box (side s ~ 2R) that is k s along a chord |p - q| / s, and the length in input units
  // is |p - q| + s w |p - q| / R + w* (s / R) |p - q|; per edge (the paper's printed formula) the
  // last term is s w* s / R.
  const double radius = 3.0;
  const TriangleMesh sphere = makeIcosphere(radius, 4);
  const double s = unitBoxScale(sphere);
  EXPECT_NEAR(s, 2.0 * radius, 0.01 * radius);
  IsophoticMetricOptions options;
  options.normalWeight = 2.0;
  options.curvatureWeight = 0.5;
  const SurfaceDescriptors descriptors = computeSurfaceDescriptors(sphere);
  const std::vector<double> lengths = isophoticEdgeLengths(sphere, descriptors, options);
  options.curvaturePerEdge = true;
  const std::vector<double> perEdge = isophoticEdgeLengths(sphere, descriptors, options);
  for (int e = 0; e < sphere.edgeCount(); ++e)
  {
    const auto [a, b] = sphere.edgeVertices(e);
    const double chord = (sphere.point(a) - sphere.point(b)).norm();
    const double curvatureTerm = 0.5 * (s / radius) * chord;
    EXPECT_NEAR(lengths[e], chord + s * 2.0 * chord / radius + curvatureTerm, 0.02 * curvatureTerm) << "edge " << e;
    const double perEdgeTerm = s * 0.5 * (s / radius);
    EXPECT_NEAR(perEdge[e], chord + s * 2.0 * chord / radius + perEdgeTerm, 0.02 * perEdgeTerm) << "edge " << e;
  }
}

TEST(IsophoticMetric, LengthsAreInTheInputUnits)
{
  // The metric is measured in the unit box: scaling the mesh scales every length by the same factor.
  const TriangleMesh shape = makeDumbbell(2.2, { { 1.0, 0.8 } }, 0.3, 0.65, 3);
  std::vector<Vector3> scaled = shape.points();
  for (Vector3& p : scaled)
  {
    p *= 10.0;
  }
  const TriangleMesh large(scaled, shape.triangles());
  const std::vector<double> small = isophoticEdgeLengths(shape, computeSurfaceDescriptors(shape), {});
  const std::vector<double> big = isophoticEdgeLengths(large, computeSurfaceDescriptors(large), {});
  ASSERT_EQ(small.size(), big.size());
  for (std::size_t e = 0; e < small.size(); ++e)
  {
    EXPECT_NEAR(big[e], 10.0 * small[e], 1e-9 * big[e]);
  }
}

TEST(IsophoticMetric, ConcaveEdgesCostMoreThanConvexOnes)
{
  // On the inner equator of a torus with R = 2, r = 1 the surface bends by 1 both ways: convexly
  // across the tube, concavely around the axis. In the unit box (side 6) |k| = 6: per unit of
  // length (without the normal term) a convex edge costs 1 + w* 6, a concave one
  // 1 + w* (e^6 - 1), 65 times more.
  const TriangleMesh torus = makeTorus(2.0, 1.0, 96, 48);
  IsophoticMetricOptions options;
  options.normalWeight = 0.0;
  const std::vector<double> lengths = isophoticEdgeLengths(torus, computeSurfaceDescriptors(torus), options);
  double across = 0.0, around = 0.0;
  for (int e = 0; e < torus.edgeCount(); ++e)
  {
    const auto [a, b] = torus.edgeVertices(e);
    const Vector3 pa = torus.point(a), pb = torus.point(b);
    if (std::hypot(pa.x(), pa.y()) > 1.2 || std::hypot(pb.x(), pb.y()) > 1.2 || std::abs(pa.z() + pb.z()) > 0.2)
    {
      continue; // not on the inner equator
    }
    if (std::abs(std::atan2(pa.y(), pa.x()) - std::atan2(pb.y(), pb.x())) < 1e-9)
    {
      across = lengths[e] / (pa - pb).norm();
    }
    else if (std::abs(pa.z()) < 1e-9 && std::abs(pb.z()) < 1e-9)
    {
      around = lengths[e] / (pa - pb).norm();
    }
  }
  ASSERT_GT(across, 0.0);
  ASSERT_GT(around, 0.0);
  // |k| estimated within 2% moves e^6 by 12%.
  EXPECT_GT(around / across, 50.0);
  EXPECT_LT(around / across, 80.0);
}

TEST(IsophoticMetric, CachedPerSurfaceAndOptions)
{
  const Surface surface(makeIcosphere(1.0, 2));
  const int before = surface.computations();
  const std::vector<double>& first = surfaceIsophoticEdgeLengths(surface, {});
  const int afterFirst = surface.computations();
  EXPECT_EQ(&surfaceIsophoticEdgeLengths(surface, {}), &first);
  EXPECT_EQ(surface.computations(), afterFirst);
  EXPECT_GT(afterFirst, before);
  IsophoticMetricOptions other;
  other.augmentation = CurvatureAugmentation::Linear;
  EXPECT_NE(&surfaceIsophoticEdgeLengths(surface, other), &first);
  EXPECT_EQ(surface.computations(), afterFirst + 1);
}

TEST(IsophoticMetric, RefusesInvalidWeights)
{
  const Surface surface(makeIcosphere(1.0, 1));
  IsophoticMetricOptions options;
  options.normalWeight = -1.0;
  EXPECT_THROW(surfaceIsophoticEdgeLengths(surface, options), Error);
  options.normalWeight = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(surfaceIsophoticEdgeLengths(surface, options), Error);
  options.normalWeight = 5.0;
  options.curvatureWeight = std::numeric_limits<double>::infinity();
  EXPECT_THROW(surfaceIsophoticEdgeLengths(surface, options), Error);
}
