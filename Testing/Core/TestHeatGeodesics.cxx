// The heat method: great-circle and Euclidean distances, point and curve sources, caching, bad input.
#include "Error.h"
#include "Geodesic/HeatGeodesics.h"
#include "Mesh/MeshGenerators.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace kerf;

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct ErrorStatistics
{
  double mean = 0.0;
  double maximum = 0.0;
  int count = 0;
};

// Relative errors of `distance` against `exact` over the vertices where `include` holds.
template <typename Exact, typename Include>
ErrorStatistics relativeErrors(
  const TriangleMesh& mesh, const std::vector<double>& distance, Exact exact, Include include)
{
  ErrorStatistics s;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (!include(v))
    {
      continue;
    }
    const double reference = exact(mesh.point(v));
    const double error = std::abs(distance[v] - reference) / reference;
    s.mean += error;
    s.maximum = std::max(s.maximum, error);
    ++s.count;
  }
  s.mean /= std::max(s.count, 1);
  return s;
}

// The 40,962-vertex unit icosphere and its heat-method set-up, shared by the sphere tests.
const TriangleMesh& unitSphere()
{
  static const TriangleMesh sphere = makeIcosphere(1.0, 6);
  return sphere;
}
const HeatGeodesics& unitSphereHeat()
{
  static const HeatGeodesics heat(unitSphere());
  return heat;
}

bool inOneRing(const TriangleMesh& mesh, int center, int v)
{
  if (v == center)
  {
    return true;
  }
  for (int w : mesh.vertexNeighbors(center))
  {
    if (w == v)
    {
      return true;
    }
  }
  return false;
}
} // namespace

TEST(HeatGeodesics, SphereMatchesGreatCircleDistance)
{
  const TriangleMesh& sphere = unitSphere(); // 40,962 vertices
  ASSERT_GE(sphere.vertexCount(), 20000);
  const HeatGeodesics& heat = unitSphereHeat();
  EXPECT_EQ(heat.flips(), 0); // an icosphere is Delaunay
  const int source = 7;
  const Vector3 s = sphere.point(source);
  GeodesicSource from;
  from.vertices = { source };
  const GeodesicDistance result = heat.compute(from);
  EXPECT_DOUBLE_EQ(result.distance[source], 0.0);
  const ErrorStatistics e = relativeErrors(
    sphere, result.distance, [&](const Vector3& p) { return std::acos(std::clamp(p.dot(s), -1.0, 1.0)); },
    [&](int v) { return !inOneRing(sphere, source, v); });
  RecordProperty("MeanRelativeError", std::to_string(e.mean));
  RecordProperty("MaximumRelativeError", std::to_string(e.maximum));
  EXPECT_LE(e.mean, 0.01);
  EXPECT_LE(e.maximum, 0.03);
}

TEST(HeatGeodesics, EveryOrderingGivesTheSameDistances)
{
  // The orderings change the factor's fill, not the solution: distances equal to round-off.
  // Automatic is AMD on this sphere (below GeometricOrderingRows vertices).
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  GeodesicSource from;
  from.vertices = { 3 };
  HeatGeodesicOptions options;
  options.ordering = CholeskyOrdering::AMD;
  const std::vector<double> reference = HeatGeodesics(sphere, options).compute(from).distance;
  for (CholeskyOrdering ordering :
    { CholeskyOrdering::Automatic, CholeskyOrdering::METIS, CholeskyOrdering::Geometric })
  {
    options.ordering = ordering;
    const std::vector<double> distance = HeatGeodesics(sphere, options).compute(from).distance;
    ASSERT_EQ(distance.size(), reference.size());
    double worst = 0.0;
    for (std::size_t v = 0; v < distance.size(); ++v)
    {
      worst = std::max(worst, std::abs(distance[v] - reference[v]));
    }
    EXPECT_LE(worst, 1e-12) << "ordering " << static_cast<int>(ordering);
    if (ordering == CholeskyOrdering::Automatic)
    {
      EXPECT_EQ(distance, reference);
    }
  }
}

TEST(HeatGeodesics, PointInsideAFaceMatchesGreatCircleDistance)
{
  const TriangleMesh& sphere = unitSphere();
  const HeatGeodesics& heat = unitSphereHeat();
  SurfacePoint point;
  point.face = 1234;
  point.barycentric = Vector3(0.2, 0.3, 0.5);
  const Vector3 s = (surfacePosition(sphere, point)).normalized();
  GeodesicSource from;
  from.points = { point };
  const GeodesicDistance result = heat.compute(from);
  const Triangle& t = sphere.triangle(point.face);
  const ErrorStatistics e = relativeErrors(
    sphere, result.distance, [&](const Vector3& p) { return std::acos(std::clamp(p.dot(s), -1.0, 1.0)); },
    [&](int v) { return !inOneRing(sphere, t[0], v) && !inOneRing(sphere, t[1], v) && !inOneRing(sphere, t[2], v); });
  // Measured: mean 0.3%, maximum 4.7% (two rings out, where the heat flow's direction is
  // least accurate; a vertex source gets that ring by unfolding).
  EXPECT_LE(e.mean, 0.01);
  EXPECT_LE(e.maximum, 0.05);
}

TEST(HeatGeodesics, EquatorCurveGivesLatitude)
{
  // The source is the isoline z = 0: one curve of one segment per face that crosses it.
  const TriangleMesh sphere = makeIcosphere(1.0, 5);
  GeodesicSource from;
  for (int f = 0; f < sphere.faceCount(); ++f)
  {
    const Triangle& t = sphere.triangle(f);
    std::vector<Vector3> crossings;
    for (int k = 0; k < 3; ++k)
    {
      const Vector3& a = sphere.point(t[k]);
      const Vector3& b = sphere.point(t[(k + 1) % 3]);
      if ((a.z() < 0.0) != (b.z() < 0.0))
      {
        crossings.push_back(a + (b - a) * (a.z() / (a.z() - b.z())));
      }
    }
    if (crossings.size() == 2)
    {
      SurfaceCurve segment;
      segment.points = crossings;
      segment.faces = { f };
      from.curves.push_back(segment);
    }
  }
  ASSERT_GT(from.curves.size(), 100u);
  const HeatGeodesics heat(sphere);
  const GeodesicDistance result = heat.compute(from);
  // Latitude, away from the band of faces that hold the curve.
  const ErrorStatistics e = relativeErrors(
    sphere, result.distance, [](const Vector3& p) { return std::asin(std::min(std::abs(p.z()), 1.0)); },
    [&](int v) { return std::abs(sphere.point(v).z()) > 0.1; });
  EXPECT_LE(e.mean, 0.01);
  EXPECT_LE(e.maximum, 0.03);
}

TEST(HeatGeodesics, PlanarGridMatchesEuclideanDistance)
{
  const int cells = 120;
  const TriangleMesh grid = makeGrid(1.0, 1.0, cells, cells);
  const int center = (cells / 2) * (cells + 1) + cells / 2;
  const Vector3 c = grid.point(center);
  GeodesicSource from;
  from.vertices = { center };
  for (HeatBoundaryCondition boundary :
    { HeatBoundaryCondition::Mean, HeatBoundaryCondition::Neumann, HeatBoundaryCondition::Dirichlet })
  {
    HeatGeodesicOptions options;
    options.boundary = boundary;
    const HeatGeodesics heat(grid, options);
    const GeodesicDistance result = heat.compute(from);
    // Beyond five cells: nearer, the one-cell heat step and the triangles' one diagonal direction
    // skew the flow most (PlanarGridBiasShrinksWithTheTimeStepNotTheCells measures the bias beyond).
    const ErrorStatistics e = relativeErrors(
      grid, result.distance, [&](const Vector3& p) { return (p - c).norm(); },
      [&](int v) { return (grid.point(v) - c).norm() > 5.0 / cells; });
    RecordProperty("MeanRelativeError" + std::to_string(static_cast<int>(boundary)), std::to_string(e.mean));
    // Measured with the mean of both conditions: mean 1.2%, maximum 4.1% (just past five cells).
    if (boundary == HeatBoundaryCondition::Mean)
    {
      EXPECT_LE(e.mean, 0.015);
      EXPECT_LE(e.maximum, 0.045);
    }
    else
    {
      EXPECT_LE(e.mean, 0.03);
    }
  }
}

// The grid's bias is the lattice's, not the refinement's: with t = h^2 the heat step's kernel
// spans about one cell, where the 5-point stencil (the cotangent Laplacian of a grid of right
// isosceles triangles) is anisotropic, so distances along the axes come out short by nearly the
// same fraction at every resolution. A longer step spans more cells and the bias falls. Ring 0.25
// to 0.35 from the centre, mean relative error along the axes (within 0.1 rad), measured here:
// -2.5% at 60 cells and -2.4% at 120 (t = h^2), -0.65% and -0.19% at 120 for time factors 4 and
// 16 (Geodesics.md has 100 and 200 cells and factor 64).
TEST(HeatGeodesics, PlanarGridBiasShrinksWithTheTimeStepNotTheCells)
{
  const auto axialBias = [](int cells, double timeFactor) {
    const TriangleMesh grid = makeGrid(1.0, 1.0, cells, cells);
    const int center = (cells / 2) * (cells + 1) + cells / 2;
    const Vector3 c = grid.point(center);
    HeatGeodesicOptions options;
    options.timeFactor = timeFactor;
    GeodesicSource from;
    from.vertices = { center };
    const GeodesicDistance result = HeatGeodesics(grid, options).compute(from);
    double sum = 0.0;
    int count = 0;
    for (int v = 0; v < grid.vertexCount(); ++v)
    {
      const Vector3 d = grid.point(v) - c;
      const double r = d.norm();
      const double angle = std::fmod(std::abs(std::atan2(d.y(), d.x())), Pi / 2.0);
      if (r >= 0.25 && r <= 0.35 && (angle < 0.1 || angle > Pi / 2.0 - 0.1))
      {
        sum += result.distance[v] / r - 1.0;
        ++count;
      }
    }
    EXPECT_GT(count, 20);
    return sum / count;
  };
  const double coarse = axialBias(60, 1.0), fine = axialBias(120, 1.0);
  const double longer = axialBias(120, 4.0), longest = axialBias(120, 16.0);
  RecordProperty("AxialBias",
    std::to_string(coarse) + " " + std::to_string(fine) + " " + std::to_string(longer) + " " + std::to_string(longest));
  // Short along the axes at t = h^2, by the same fraction at both resolutions.
  EXPECT_LT(fine, -0.015);
  EXPECT_GT(fine, -0.03);
  EXPECT_NEAR(coarse, fine, 0.003);
  // Each fourfold step at least halves it.
  EXPECT_LT(std::abs(longer), 0.5 * std::abs(fine));
  EXPECT_LT(std::abs(longest), 0.5 * std::abs(longer));
  EXPECT_LT(std::abs(longest), 0.003);
}
