// The anisotropic metric of Zhuang et al. 2014: lambda values, eigenvectors, umbilics and bad input.
#include "Error.h"
#include "Geodesic/AnisotropicMetric.h"
#include "Mesh/MeshGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace kerf;

TEST(AnisotropicMetric, LambdaFollowsBothMeasures)
{
  AnisotropicMetricOptions options;
  options.gamma = 0.1;
  options.measure = AnisotropyMeasure::CurvatureDifference;
  EXPECT_DOUBLE_EQ(anisotropyLambda(2.0, 0.5, options, 0.0), 1.0 + 0.1 * 1.5);
  options.measure = AnisotropyMeasure::Normalized;
  EXPECT_DOUBLE_EQ(anisotropyLambda(2.0, 0.5, options, 0.0), 1.0 + 0.1 * 1.5 / 2.5);
  // Scale-free: ten times the curvature gives the same lambda.
  EXPECT_DOUBLE_EQ(anisotropyLambda(20.0, 5.0, options, 0.0), anisotropyLambda(2.0, 0.5, options, 0.0));
  // An umbilic (flat) point is isotropic, not 0 / 0.
  EXPECT_DOUBLE_EQ(anisotropyLambda(0.0, 0.0, options, 0.0), 1.0);
  options.gamma = 0.0;
  EXPECT_DOUBLE_EQ(anisotropyLambda(2.0, 0.5, options, 0.0), 1.0);
}

TEST(AnisotropicMetric, CylinderStretchesAroundAndShrinksAlongTheAxis)
{
  const TriangleMesh cylinder = makeCylinder(1.0, 4.0, 64, 65);
  const SurfaceDescriptors descriptors = computeSurfaceDescriptors(cylinder);
  for (AnisotropyMeasure measure : { AnisotropyMeasure::Normalized, AnisotropyMeasure::CurvatureDifference })
  {
    AnisotropicMetricOptions options;
    options.gamma = 0.5;
    options.measure = measure;
    const AnisotropicMetric metric = computeAnisotropicMetric(cylinder, descriptors, options);
    EXPECT_FALSE(metric.isotropic);
    // Expected lambda1 for k1 = 1, k2 = 0 (the regularisation is 0.05 of the RMS curvature, 1).
    const double expected = measure == AnisotropyMeasure::Normalized ? 1.0 + 0.5 / 1.05 : 1.5;
    // A vertex in the middle ring, away from the boundary's curvature estimate.
    const int v = 32 * 64 + 5;
    const Vector3 p = cylinder.point(v);
    const Vector3 axial(0.0, 0.0, 1.0);
    const Vector3 around = Vector3(-p.y(), p.x(), 0.0).normalized();
    const Vector3 normal = Vector3(p.x(), p.y(), 0.0).normalized();
    const Eigen::Matrix3d& M = metric.tensors[v];
    EXPECT_NEAR(metric.lambda1[v], expected, 0.02);
    EXPECT_NEAR(around.dot(M * around), metric.lambda1[v], 1e-6);
    EXPECT_NEAR(axial.dot(M * axial), 1.0 / metric.lambda1[v], 1e-6);
    EXPECT_NEAR(normal.dot(M * normal), 1.0, 1e-9);
    EXPECT_NEAR(M.determinant(), 1.0, 1e-9);
    EXPECT_LE((M * metric.inverses[v] - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    // Mean of two equal tensors: the length along the axis shrinks by sqrt(lambda2).
    EXPECT_NEAR(metric.length(axial, v, v), std::sqrt(1.0 / metric.lambda1[v]), 1e-6);
  }
}

TEST(AnisotropicMetric, PlaneAndSphereStayIsotropic)
{
  AnisotropicMetricOptions options;
  options.gamma = 2.0;
  const TriangleMesh grid = makeGrid(1.0, 1.0, 10, 10);
  const AnisotropicMetric flat = computeAnisotropicMetric(grid, computeSurfaceDescriptors(grid), options);
  for (int v = 0; v < grid.vertexCount(); ++v)
  {
    EXPECT_DOUBLE_EQ(flat.lambda1[v], 1.0);
  }
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  const AnisotropicMetric round = computeAnisotropicMetric(sphere, computeSurfaceDescriptors(sphere), options);
  for (int v = 0; v < sphere.vertexCount(); ++v)
  {
    EXPECT_NEAR(round.lambda1[v], 1.0, 0.02);
  }
  options.gamma = 0.0;
  EXPECT_TRUE(computeAnisotropicMetric(sphere, computeSurfaceDescriptors(sphere), options).isotropic);
}

TEST(AnisotropicMetric, RefusesBadInput)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 2);
  const SurfaceDescriptors descriptors = computeSurfaceDescriptors(sphere);
  AnisotropicMetricOptions options;
  options.gamma = -1.0;
  EXPECT_THROW(computeAnisotropicMetric(sphere, descriptors, options), Error);
  options.gamma = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(computeAnisotropicMetric(sphere, descriptors, options), Error);
  options.gamma = 1.0;
  EXPECT_THROW(computeAnisotropicMetric(makeIcosphere(1.0, 1), descriptors, options), Error);
  options.measure = AnisotropyMeasure::CurvatureDifference;
  options.gamma = 1.0;
  AnisotropicMetricOptions shrinking = options;
  shrinking.gamma = 1.0;
  // lambda1 = 1 + gamma (|k1| - |k2|) with |k1| >= |k2| is never below 1 for gamma >= 0.
  EXPECT_GE(anisotropyLambda(-3.0, 1.0, shrinking, 0.0), 1.0);
}
