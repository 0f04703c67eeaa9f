// Harmonic fields (hard and soft constraints, cached solves, gradients, errors), stroke constraints and closest points.
#include "Error.h"
#include "Geometry/ClosestPoint.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/StrokeConstraints.h"
#include "Mesh/MeshGenerators.h"
#include "Numerics/FieldGradient.h"
#include "Numerics/LaplacianWeights.h"
#include "Numerics/NestedDissection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

using namespace kerf;

namespace
{
constexpr double Pi = 3.14159265358979323846;

const LaplacianWeighting AllWeightings[] = { LaplacianWeighting::Uniform, LaplacianWeighting::Cotangent,
  LaplacianWeighting::ConcavityAware, LaplacianWeighting::SmoothConcavity };

std::string weightingName(LaplacianWeighting weighting)
{
  switch (weighting)
  {
    case LaplacianWeighting::Uniform:
      return "Uniform";
    case LaplacianWeighting::Cotangent:
      return "Cotangent";
    case LaplacianWeighting::ConcavityAware:
      return "ConcavityAware";
    case LaplacianWeighting::SmoothConcavity:
      return "SmoothConcavity";
    case LaplacianWeighting::IntrinsicDelaunay:
      return "IntrinsicDelaunay";
  }
  return "?";
}

std::vector<double> weightsFor(const TriangleMesh& mesh, LaplacianWeighting weighting)
{
  LaplacianWeightOptions options;
  options.weighting = weighting;
  const SurfaceDescriptors descriptors = computeSurfaceDescriptors(mesh);
  return computeLaplacianWeights(mesh, options, &descriptors);
}

std::vector<double> cotangentWeights(const TriangleMesh& mesh)
{
  return computeLaplacianWeights(mesh, LaplacianWeightOptions());
}

// Hard values `left` on the x = 0 column and `right` on the x = width column of makeGrid(., ., columns, rows).
FieldConstraints gridColumnConstraints(int columns, int rows, double left = 0.0, double right = 1.0)
{
  FieldConstraints c;
  for (int j = 0; j <= rows; ++j)
  {
    c.dirichletVertices.push_back(j * (columns + 1));
    c.dirichletValues.push_back(left);
    c.dirichletVertices.push_back(j * (columns + 1) + columns);
    c.dirichletValues.push_back(right);
  }
  return c;
}

// Hard values on the bottom and top rings of makeCylinder(., ., around, rings).
FieldConstraints cylinderRingConstraints(int around, int rings, double bottom = 0.0, double top = 1.0)
{
  FieldConstraints c;
  for (int i = 0; i < around; ++i)
  {
    c.dirichletVertices.push_back(i);
    c.dirichletValues.push_back(bottom);
    c.dirichletVertices.push_back((rings - 1) * around + i);
    c.dirichletValues.push_back(top);
  }
  return c;
}

// A soft constraint at the surface point nearest to p.
SoftConstraint softAt(const ClosestPointLocator& locator, const Vector3& p, double value)
{
  const ClosestPointLocator::Hit hit = locator.closest(p);
  SoftConstraint s;
  s.face = hit.face;
  s.barycentric = hit.barycentric;
  s.value = value;
  return s;
}

double interpolate(const TriangleMesh& mesh, const std::vector<double>& field, const SoftConstraint& s)
{
  const Triangle& t = mesh.triangle(s.face);
  return s.barycentric[0] * field[t[0]] + s.barycentric[1] * field[t[1]] + s.barycentric[2] * field[t[2]];
}

double maximumMisfit(
  const TriangleMesh& mesh, const std::vector<double>& field, const std::vector<SoftConstraint>& soft)
{
  double misfit = 0.0;
  for (const SoftConstraint& s : soft)
  {
    misfit = std::max(misfit, std::abs(interpolate(mesh, field, s) - s.value));
  }
  return misfit;
}

const SoftConstraintFormulation BothFormulations[] = { SoftConstraintFormulation::PointValues,
  SoftConstraintFormulation::LeastSquares };

const char* formulationName(SoftConstraintFormulation formulation)
{
  return formulation == SoftConstraintFormulation::PointValues ? "point values" : "least squares";
}

bool bitwiseEqual(const HarmonicFieldSolution& a, const HarmonicFieldSolution& b)
{
  return a.field.size() == b.field.size() &&
    std::memcmp(a.field.data(), b.field.data(), a.field.size() * sizeof(double)) == 0;
}

HarmonicFieldSolution freshSolve(
  const TriangleMesh& mesh, const std::vector<double>& weights, const FieldConstraints& constraints)
{
  HarmonicFieldSolver solver;
  return solver.solve(mesh, weights, constraints);
}

// Every field value inside [low, high]; unconstrained values strictly inside.
void expectMaximumPrinciple(const TriangleMesh& mesh, const FieldConstraints& constraints,
  const std::vector<double>& field, double low, double high, const std::string& what)
{
  std::vector<char> hard(mesh.vertexCount(), 0);
  for (int v : constraints.dirichletVertices)
  {
    hard[v] = 1;
  }
  int strictlyInside = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    EXPECT_GE(field[v], low) << what << ", vertex " << v;
    EXPECT_LE(field[v], high) << what << ", vertex " << v;
    if (!hard[v])
    {
      EXPECT_GT(field[v], low) << what << ", free vertex " << v;
      EXPECT_LT(field[v], high) << what << ", free vertex " << v;
      strictlyInside += field[v] > low && field[v] < high ? 1 : 0;
    }
  }
  EXPECT_GT(strictlyInside, 0) << what;
}

template <typename F>
void expectKerfError(F&& call, const std::string& expectedFragment)
{
  try
  {
    call();
    ADD_FAILURE() << "no kerf::Error thrown (expected one mentioning \"" << expectedFragment << "\")";
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find(expectedFragment), std::string::npos) << "message: " << error.what();
  }
}

// Two icospheres side by side in one mesh: component 0 at the origin, component 1 at x = 5.
TriangleMesh twoSpheres(int levels)
{
  const TriangleMesh a = makeIcosphere(1.0, levels);
  const TriangleMesh b = makeIcosphere(1.0, levels);
  std::vector<Vector3> points = a.points();
  std::vector<Triangle> triangles = a.triangles();
  for (const Vector3& p : b.points())
  {
    points.push_back(p + Vector3(5.0, 0.0, 0.0));
  }
  for (Triangle t : b.triangles())
  {
    for (int& v : t)
    {
      v += a.vertexCount();
    }
    triangles.push_back(t);
  }
  return TriangleMesh(points, triangles);
}
} // namespace

// ---------------------------------------------------------------------------------------------
// Hard constraints: linear harmonic functions and the maximum principle.

// Point values where the default stroke offset (0.005 of the diagonal) spans 0.9 mean edges or
// more: on an n x n grid of the unit square (mean edge (2 (n + 1) + sqrt(2) n) / (n (3 n + 2)),
// diagonal sqrt(2)) from n = 145; the size of the square does not matter.
TEST(HarmonicField, AutomaticFormulationTakesPointValuesWhereTheOffsetSpansAnEdge)
{
  EXPECT_EQ(automaticFormulation(TriangleMesh()), SoftConstraintFormulation::LeastSquares);
  for (int n : { 10, 144, 145, 400 })
  {
    const double expectedEdge = (2.0 * (n + 1) + std::sqrt(2.0) * n) / (n * (3.0 * n + 2.0));
    for (double size : { 1.0, 1000.0 })
    {
      const TriangleMesh grid = makeGrid(size, size, n, n);
      EXPECT_NEAR(grid.meanEdgeLength(), size * expectedEdge, 1e-12 * size) << n;
      EXPECT_EQ(automaticFormulation(grid),
        n >= 145 ? SoftConstraintFormulation::PointValues : SoftConstraintFormulation::LeastSquares)
        << n << " x " << n << ", size " << size;
    }
  }
  EXPECT_DOUBLE_EQ(PointValueEdgeFraction, 0.005 / 0.9);
}

TEST(HarmonicField, FormulationNamesParse)
{
  EXPECT_EQ(parseSoftConstraintFormulation("least-squares"), SoftConstraintFormulation::LeastSquares);
  EXPECT_EQ(parseSoftConstraintFormulation("point-values"), SoftConstraintFormulation::PointValues);
  for (const char* bad : { "", "auto", "Least-Squares", "point values" })
  {
    try
    {
      parseSoftConstraintFormulation(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    }
    catch (const Error& e)
    {
      EXPECT_NE(std::string(e.what()).find("formulation must be least-squares or point-values"), std::string::npos);
    }
  }
}

TEST(HarmonicField, CornerCotangentsOfRightAndNeedleTriangles)
{
  // A right isosceles triangle (corners 90, 45, 45 degrees), a needle whose corner at vertex 3
  // is below CotangentLimit's angle, and a triangle of three collinear points.
  const double tiny = 1e-7;
  const TriangleMesh mesh({ Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 5), Vector3(tiny, 0, 6),
                            Vector3(0, 0, 7), Vector3(1, 0, 9), Vector3(2, 0, 9), Vector3(3, 0, 9) },
    { { 0, 1, 2 }, { 3, 4, 5 }, { 6, 7, 8 } });
  const std::vector<double> cotangents = cornerCotangents(mesh);
  ASSERT_EQ(cotangents.size(), 9u);
  EXPECT_NEAR(cotangents[0], 0.0, 1e-15);
  EXPECT_NEAR(cotangents[1], 1.0, 1e-15);
  EXPECT_NEAR(cotangents[2], 1.0, 1e-15);
  // Corner 3: the angle between (tiny, 0, 1) and (0, 0, 2) is about tiny radians, cot 1e7 > the limit.
  EXPECT_EQ(cotangents[3], CotangentLimit);
  EXPECT_EQ(cotangents[5], CotangentLimit); // the corner at vertex 5 likewise
  // Corner 4 is nearly a straight angle: cotangent about -1e7, clamped.
  EXPECT_EQ(cotangents[4], -CotangentLimit);
  for (int k = 6; k < 9; ++k)
  {
    EXPECT_EQ(cotangents[static_cast<std::size_t>(k)], 0.0) << "corner " << k << " of a zero-area triangle";
  }
}

TEST(HarmonicField, GridColumnsGiveLinearFieldWithCotangentWeights)
{
  const double width = 2.0, height = 1.5;
  const int columns = 12, rows = 9;
  const TriangleMesh grid = makeGrid(width, height, columns, rows);
  const FieldConstraints constraints = gridColumnConstraints(columns, rows);
  const HarmonicFieldSolution solution = freshSolve(grid, cotangentWeights(grid), constraints);
  ASSERT_EQ(static_cast<int>(solution.field.size()), grid.vertexCount());
  EXPECT_EQ(solution.work, HarmonicFieldSolution::Work::Factorization);
  EXPECT_LE(solution.relativeResidual, 1e-10);
  double worst = 0.0;
  int worstVertex = -1;
  for (int v = 0; v < grid.vertexCount(); ++v)
  {
    const double error = std::abs(solution.field[v] - grid.point(v).x() / width);
    if (error > worst)
    {
      worst = error;
      worstVertex = v;
    }
  }
  EXPECT_LE(worst, 1e-9) << "largest error at vertex " << worstVertex;
}

TEST(HarmonicField, GeometricOrderingGivesTheSameField)
{
  // Large meshes are ordered by geometricNestedDissection (forced here from 1 row): the same
  // linear field as with AMD, to round-off.
  const double width = 2.0, height = 1.5;
  const int columns = 40, rows = 30;
  const TriangleMesh grid = makeGrid(width, height, columns, rows);
  const FieldConstraints constraints = gridColumnConstraints(columns, rows);
  HarmonicFieldSolver amd, geometric;
  EXPECT_EQ(amd.geometricOrderingRows(), GeometricOrderingRows);
  geometric.setGeometricOrderingRows(1);
  const std::vector<double> weights = cotangentWeights(grid);
  const HarmonicFieldSolution a = amd.solve(grid, weights, constraints);
  const HarmonicFieldSolution g = geometric.solve(grid, weights, constraints);
  ASSERT_EQ(a.field.size(), g.field.size());
  double worst = 0.0;
  for (std::size_t v = 0; v < a.field.size(); ++v)
  {
    worst = std::max(worst, std::abs(a.field[v] - g.field[v]));
    EXPECT_NEAR(g.field[v], grid.point(static_cast<int>(v)).x() / width, 1e-9);
  }
  EXPECT_LE(worst, 1e-12);
}

TEST(HarmonicField, GridMaximumPrincipleForEveryWeighting)
{
  const TriangleMesh grid = makeGrid(2.0, 1.5, 12, 9);
  const FieldConstraints constraints = gridColumnConstraints(12, 9);
  for (LaplacianWeighting weighting : AllWeightings)
  {
    const std::vector<double> weights = weightsFor(grid, weighting);
    for (double w : weights)
    {
      ASSERT_GE(w, 0.0) << weightingName(weighting);
    }
    const HarmonicFieldSolution solution = freshSolve(grid, weights, constraints);
    expectMaximumPrinciple(grid, constraints, solution.field, 0.0, 1.0, weightingName(weighting));
  }
}

TEST(HarmonicField, GridResidualIsReportedForEveryWeighting)
{
  // On a flat grid every Gaussian curvature is 0: the concavity-aware weights must still give a
  // solve whose reported residual is a small finite number.
  const TriangleMesh grid = makeGrid(2.0, 1.5, 12, 9);
  const FieldConstraints constraints = gridColumnConstraints(12, 9);
  for (LaplacianWeighting weighting : AllWeightings)
  {
    const HarmonicFieldSolution solution = freshSolve(grid, weightsFor(grid, weighting), constraints);
    EXPECT_TRUE(std::isfinite(solution.relativeResidual)) << weightingName(weighting);
    EXPECT_LE(solution.relativeResidual, 1e-10) << weightingName(weighting);
  }
}

TEST(HarmonicField, ConcavityWeightsComputeDescriptorsWhenNotGiven)
{
  const TriangleMesh torus = makeTorus(2.0, 0.7, 40, 16);
  const SurfaceDescriptors descriptors = computeSurfaceDescriptors(torus);
  for (LaplacianWeighting weighting : { LaplacianWeighting::ConcavityAware, LaplacianWeighting::SmoothConcavity })
  {
    LaplacianWeightOptions options;
    options.weighting = weighting;
    EXPECT_EQ(computeLaplacianWeights(torus, options, &descriptors), computeLaplacianWeights(torus, options))
      << weightingName(weighting);
  }
}

TEST(HarmonicField, BumpyGridMaximumPrincipleForEveryWeighting)
{
  // Jittered, bumpy grid: obtuse triangles (negative cotangent weights), concave and convex vertices.
  const int columns = 16, rows = 16;
  const TriangleMesh flat = makeGrid(1.0, 1.0, columns, rows);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.3 / columns, 0.3 / columns);
  std::vector<Vector3> points = flat.points();
  for (Vector3& p : points)
  {
    const bool boundaryX = p.x() == 0.0 || p.x() == 1.0;
    const bool boundaryY = p.y() == 0.0 || p.y() == 1.0;
    p.x() += boundaryX ? 0.0 : jitter(random);
    p.y() += boundaryY ? 0.0 : jitter(random);
    p.z() = 0.15 * std::sin(3.0 * Pi * p.x()) * std::cos(2.0 * Pi * p.y());
  }
  const TriangleMesh bumpy(points, flat.triangles());
  // Some edges have opposite angles summing to more than pi (negative cotangent weights, set to 0).
  int obtuseEdges = 0;
  for (int e = 0; e < bumpy.edgeCount(); ++e)
  {
    if (bumpy.edgeFaceCount(e) != 2)
    {
      continue;
    }
    double angles = 0.0;
    for (int f : bumpy.edgeFaces(e))
    {
      const Triangle& t = bumpy.triangle(f);
      for (int k = 0; k < 3; ++k)
      {
        if (bumpy.faceEdge(f, k) == e)
        {
          const Vector3& apex = bumpy.point(t[(k + 2) % 3]);
          const Vector3 a = bumpy.point(t[k]) - apex, b = bumpy.point(t[(k + 1) % 3]) - apex;
          angles += std::atan2(a.cross(b).norm(), a.dot(b));
        }
      }
    }
    obtuseEdges += angles > Pi ? 1 : 0;
  }
  ASSERT_GT(obtuseEdges, 10);
  const FieldConstraints constraints = gridColumnConstraints(columns, rows);
  for (LaplacianWeighting weighting : AllWeightings)
  {
    const HarmonicFieldSolution solution = freshSolve(bumpy, weightsFor(bumpy, weighting), constraints);
    expectMaximumPrinciple(bumpy, constraints, solution.field, 0.0, 1.0, weightingName(weighting));
    EXPECT_LE(solution.relativeResidual, 1e-10) << weightingName(weighting);
  }
}

TEST(HarmonicField, CylinderRingsGiveLinearFieldInZ)
{
  const double radius = 1.0, height = 3.0;
  const int around = 40, rings = 21;
  const TriangleMesh cylinder = makeCylinder(radius, height, around, rings);
  const FieldConstraints constraints = cylinderRingConstraints(around, rings);
  const HarmonicFieldSolution solution = freshSolve(cylinder, cotangentWeights(cylinder), constraints);
  EXPECT_LE(solution.relativeResidual, 1e-10);
  for (int v = 0; v < cylinder.vertexCount(); ++v)
  {
    EXPECT_NEAR(solution.field[v], cylinder.point(v).z() / height, 1e-9) << "vertex " << v;
  }
}

TEST(HarmonicField, CylinderMaximumPrincipleForEveryWeighting)
{
  const int around = 40, rings = 21;
  const TriangleMesh cylinder = makeCylinder(1.0, 3.0, around, rings);
  const FieldConstraints constraints = cylinderRingConstraints(around, rings);
  for (LaplacianWeighting weighting : AllWeightings)
  {
    const HarmonicFieldSolution solution = freshSolve(cylinder, weightsFor(cylinder, weighting), constraints);
    expectMaximumPrinciple(cylinder, constraints, solution.field, 0.0, 1.0, weightingName(weighting));
    EXPECT_LE(solution.relativeResidual, 1e-10) << weightingName(weighting);
    // The mean value of a ring increases with z.
    double previous = -1.0;
    for (int j = 0; j < rings; ++j)
    {
      double mean = 0.0;
      for (int i = 0; i < around; ++i)
      {
        mean += solution.field[j * around + i] / around;
      }
      EXPECT_GT(mean, previous) << weightingName(weighting) << ", ring " << j;
      previous = mean;
    }
  }
}

TEST(HarmonicField, CylinderFieldIsRotationallySymmetricForEveryWeighting)
{
  // The mesh and the constraints are invariant under a rotation by 2 pi / around (up to rounding
  // of the coordinates), so each ring must be at one value.
  const int around = 40, rings = 21;
  const TriangleMesh cylinder = makeCylinder(1.0, 3.0, around, rings);
  const FieldConstraints constraints = cylinderRingConstraints(around, rings);
  for (LaplacianWeighting weighting : AllWeightings)
  {
    const HarmonicFieldSolution solution = freshSolve(cylinder, weightsFor(cylinder, weighting), constraints);
    double worst = 0.0;
    int worstVertex = -1;
    for (int v = 0; v < cylinder.vertexCount(); ++v)
    {
      const double spread = std::abs(solution.field[v] - solution.field[(v / around) * around]);
      if (spread > worst)
      {
        worst = spread;
        worstVertex = v;
      }
    }
    EXPECT_LE(worst, 1e-9) << weightingName(weighting) << ": ring of vertex " << worstVertex;
  }
}

// ---------------------------------------------------------------------------------------------
// Gradients.

TEST(HarmonicField, FaceGradientsOfLinearFieldOnTiltedPlane)
{
  const TriangleMesh flat = makeGrid(3.0, 2.0, 15, 10);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vector3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  const Vector3 shift(0.3, -1.2, 2.5);
  std::vector<Vector3> points;
  for (const Vector3& p : flat.points())
  {
    points.push_back(rotation * p + shift);
  }
  const TriangleMesh plane(points, flat.triangles());
  const Vector3 normal = rotation * Vector3::UnitZ();
  const Vector3 a(0.8, -1.7, 2.3); // has a component along the normal
  std::vector<double> field;
  for (const Vector3& p : plane.points())
  {
    field.push_back(a.dot(p) + 4.0);
  }
  const Vector3 expected = a - a.dot(normal) * normal;
  ASSERT_GT((a - expected).norm(), 0.5);
  const std::vector<Vector3> gradients = computeFaceGradients(plane, field);
  ASSERT_EQ(static_cast<int>(gradients.size()), plane.faceCount());
  for (int f = 0; f < plane.faceCount(); ++f)
  {
    EXPECT_LE((gradients[f] - expected).norm(), 1e-12) << "face " << f << ": " << gradients[f].transpose();
  }
}

TEST(HarmonicField, FaceGradientsOnSphereFacesAndDegenerateFaces)
{
  // Each face of a sphere is planar: the gradient of a linear field is its projection on the face.
  const TriangleMesh sphere = makeIcosphere(1.3, 3);
  const Vector3 a(-0.4, 1.1, 0.6);
  std::vector<double> field;
  for (const Vector3& p : sphere.points())
  {
    field.push_back(a.dot(p));
  }
  const std::vector<Vector3> gradients = computeFaceGradients(sphere, field);
  for (int f = 0; f < sphere.faceCount(); ++f)
  {
    const Triangle& t = sphere.triangle(f);
    const Vector3 n =
      (sphere.point(t[1]) - sphere.point(t[0])).cross(sphere.point(t[2]) - sphere.point(t[0])).normalized();
    EXPECT_LE((gradients[f] - (a - a.dot(n) * n)).norm(), 1e-12) << "face " << f;
  }

  // A zero-area (collinear) triangle gets a zero gradient, its neighbour the exact one.
  const TriangleMesh mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 1, 3 } });
  const std::vector<Vector3> g = computeFaceGradients(mesh, { 0.0, 1.0, 2.0, 5.0 });
  EXPECT_EQ(g[0], Vector3::Zero());
  EXPECT_LE((g[1] - Vector3(1.0, 5.0, 0.0)).norm(), 1e-14);
}

// ---------------------------------------------------------------------------------------------
// Soft constraints (SeamCut, Eq. 1) and the cached factorization.

namespace
{
struct SoftGrid
{
  TriangleMesh mesh = makeGrid(1.0, 1.0, 16, 16);
  ClosestPointLocator locator{ mesh };
  std::vector<double> weights = cotangentWeights(mesh);
  SoftConstraintFormulation formulation = FieldConstraints().formulation;

  SoftGrid() = default;
  explicit SoftGrid(SoftConstraintFormulation f)
    : formulation(f)
  {
  }

  // +1 at x = 0.4 and -1 at x = 0.6 on three heights, shifted by `shift`.
  FieldConstraints pairs(double shift, double softWeight, double plus = 1.0, double minus = -1.0) const
  {
    FieldConstraints c;
    c.softWeight = softWeight;
    c.formulation = this->formulation;
    for (double y : { 0.31, 0.52, 0.73 })
    {
      c.soft.push_back(softAt(this->locator, Vector3(0.4 + shift, y + shift, 0.0), plus));
      c.soft.push_back(softAt(this->locator, Vector3(0.6 + shift, y + shift, 0.0), minus));
    }
    return c;
  }
};
} // namespace

TEST(HarmonicField, SoftOnlyConstantConstraintsGiveConstantField)
{
  const SoftGrid g;
  FieldConstraints c = g.pairs(0.0, 1.0, 0.7, 0.7);
  const HarmonicFieldSolution solution = freshSolve(g.mesh, g.weights, c);
  EXPECT_LE(solution.relativeResidual, 1e-8);
  // The pin of the component (weight 1e-10 of the system's scale) may change the solution only to
  // that relative precision (HarmonicField.h); allow ten times more.
  double worst = 0.0;
  for (int v = 0; v < g.mesh.vertexCount(); ++v)
  {
    worst = std::max(worst, std::abs(solution.field[v] - 0.7));
  }
  EXPECT_LE(worst, 10.0 * 1e-10 * 0.7);
  EXPECT_LE(maximumMisfit(g.mesh, solution.field, c.soft), 10.0 * 1e-10 * 0.7);
}

TEST(HarmonicField, SoftOnlyMisfitShrinksAsWeightGrows)
{
  const SoftGrid g;
  double previous = std::numeric_limits<double>::infinity();
  for (double w : { 0.1, 1.0, 10.0, 100.0, 1000.0 })
  {
    FieldConstraints c = g.pairs(0.0, w);
    c.formulation = SoftConstraintFormulation::LeastSquares;
    const HarmonicFieldSolution solution = freshSolve(g.mesh, g.weights, c);
    const double misfit = maximumMisfit(g.mesh, solution.field, c.soft);
    EXPECT_LT(misfit, previous) << "softWeight " << w;
    EXPECT_LE(solution.relativeResidual, 1e-8) << "softWeight " << w;
    // The +1 side stays above the -1 side, and the zero level passes between them.
    for (std::size_t i = 0; i < c.soft.size(); i += 2)
    {
      EXPECT_GT(interpolate(g.mesh, solution.field, c.soft[i]), 0.0) << "softWeight " << w;
      EXPECT_LT(interpolate(g.mesh, solution.field, c.soft[i + 1]), 0.0) << "softWeight " << w;
    }
    if (w >= 1.0)
    {
      EXPECT_LT(misfit, 0.5) << "softWeight " << w;
    }
    if (w >= 100.0)
    {
      // The penalty is quadratic: for large w the misfit falls like 1 / w^2.
      EXPECT_LT(misfit, 1e-4) << "softWeight " << w;
      EXPECT_LT(misfit, 0.02 * previous) << "softWeight " << w;
    }
    previous = misfit;
  }
}

TEST(HarmonicField, SoftConstraintsOnFlatGridForEveryWeighting)
{
  // Flat grid (every Gaussian curvature 0): each weighting must give a finite field that
  // separates the +1 and -1 constraints.
  for (const SoftConstraintFormulation formulation : BothFormulations)
  {
    SCOPED_TRACE(formulationName(formulation));
    const SoftGrid g(formulation);
    const FieldConstraints c = g.pairs(0.0, 10.0);
    for (LaplacianWeighting weighting : AllWeightings)
    {
      HarmonicFieldSolution solution;
      try
      {
        solution = freshSolve(g.mesh, weightsFor(g.mesh, weighting), c);
      }
      catch (const Error& error)
      {
        ADD_FAILURE() << weightingName(weighting) << ": " << error.what();
        continue;
      }
      EXPECT_TRUE(std::isfinite(solution.relativeResidual)) << weightingName(weighting);
      for (std::size_t i = 0; i < c.soft.size(); i += 2)
      {
        EXPECT_GT(interpolate(g.mesh, solution.field, c.soft[i]), 0.0) << weightingName(weighting);
        EXPECT_LT(interpolate(g.mesh, solution.field, c.soft[i + 1]), 0.0) << weightingName(weighting);
      }
    }
  }
}

TEST(HarmonicField, NewSoftValuesCostOnlyBackSubstitution)
{
  for (const SoftConstraintFormulation formulation : BothFormulations)
  {
    SCOPED_TRACE(formulationName(formulation));
    const SoftGrid g(formulation);
    HarmonicFieldSolver solver;
    const FieldConstraints first = g.pairs(0.0, 2.0);
    const HarmonicFieldSolution a = solver.solve(g.mesh, g.weights, first);
    EXPECT_EQ(a.work, HarmonicFieldSolution::Work::Factorization);
    EXPECT_TRUE(bitwiseEqual(a, freshSolve(g.mesh, g.weights, first)));

    const HarmonicFieldSolution again = solver.solve(g.mesh, g.weights, first);
    EXPECT_EQ(again.work, HarmonicFieldSolution::Work::BackSubstitution);
    EXPECT_TRUE(bitwiseEqual(again, a));

    const FieldConstraints shifted = g.pairs(0.0, 2.0, 3.5, 0.25); // same points, new values
    const HarmonicFieldSolution b = solver.solve(g.mesh, g.weights, shifted);
    EXPECT_EQ(b.work, HarmonicFieldSolution::Work::BackSubstitution);
    const HarmonicFieldSolution fresh = freshSolve(g.mesh, g.weights, shifted);
    EXPECT_TRUE(bitwiseEqual(b, fresh));
    EXPECT_EQ(b.relativeResidual, fresh.relativeResidual);
    EXPECT_FALSE(bitwiseEqual(b, a));
  }
}

TEST(HarmonicField, NewSoftLocationsCostAnUpdate)
{
  for (const SoftConstraintFormulation formulation : BothFormulations)
  {
    SCOPED_TRACE(formulationName(formulation));
    const SoftGrid g(formulation);
    HarmonicFieldSolver solver;
    const FieldConstraints first = g.pairs(0.0, 2.0);
    const HarmonicFieldSolution a = solver.solve(g.mesh, g.weights, first);
    ASSERT_EQ(a.work, HarmonicFieldSolution::Work::Factorization);

    const FieldConstraints moved = g.pairs(0.07, 2.0); // same values, other points
    const HarmonicFieldSolution b = solver.solve(g.mesh, g.weights, moved);
    EXPECT_EQ(b.work, HarmonicFieldSolution::Work::Update);
    EXPECT_TRUE(bitwiseEqual(b, freshSolve(g.mesh, g.weights, moved)));
    EXPECT_FALSE(bitwiseEqual(b, a));

    // One more constraint: an update too.
    FieldConstraints more = moved;
    more.soft.push_back(softAt(g.locator, Vector3(0.2, 0.2, 0.0), 0.5));
    const HarmonicFieldSolution c = solver.solve(g.mesh, g.weights, more);
    EXPECT_EQ(c.work, HarmonicFieldSolution::Work::Update);
    EXPECT_TRUE(bitwiseEqual(c, freshSolve(g.mesh, g.weights, more)));

    // Updates start from the base factor: going back reproduces the first result exactly.
    const HarmonicFieldSolution back = solver.solve(g.mesh, g.weights, first);
    EXPECT_EQ(back.work, HarmonicFieldSolution::Work::Update);
    EXPECT_TRUE(bitwiseEqual(back, a));

    // A new soft weight changes the constraint term only.
    FieldConstraints heavier = first;
    heavier.softWeight = 5.0;
    const HarmonicFieldSolution d = solver.solve(g.mesh, g.weights, heavier);
    EXPECT_NE(d.work, HarmonicFieldSolution::Work::BackSubstitution);
    EXPECT_TRUE(bitwiseEqual(d, freshSolve(g.mesh, g.weights, heavier)));
  }
}

TEST(HarmonicField, NewFormulationCostsAFactorization)
{
  // The formulations factor different matrices: switching refactors, and switching back gives
  // the first field bit for bit.
  const SoftGrid g;
  HarmonicFieldSolver solver;
  FieldConstraints c = g.pairs(0.0, 2.0);
  c.formulation = SoftConstraintFormulation::PointValues;
  const HarmonicFieldSolution points = solver.solve(g.mesh, g.weights, c);
  EXPECT_EQ(points.work, HarmonicFieldSolution::Work::Factorization);
  c.formulation = SoftConstraintFormulation::LeastSquares;
  const HarmonicFieldSolution squares = solver.solve(g.mesh, g.weights, c);
  EXPECT_EQ(squares.work, HarmonicFieldSolution::Work::Factorization);
  EXPECT_TRUE(bitwiseEqual(squares, freshSolve(g.mesh, g.weights, c)));
  EXPECT_FALSE(bitwiseEqual(squares, points));
  c.formulation = SoftConstraintFormulation::PointValues;
  const HarmonicFieldSolution again = solver.solve(g.mesh, g.weights, c);
  EXPECT_EQ(again.work, HarmonicFieldSolution::Work::Factorization);
  EXPECT_TRUE(bitwiseEqual(again, points));
  // Point values hold the values within 0.5% (least squares, at this weight, within 10%).
  EXPECT_LE(maximumMisfit(g.mesh, points.field, c.soft), 0.005);
  EXPECT_LE(maximumMisfit(g.mesh, squares.field, c.soft), 0.1);
}

TEST(HarmonicField, NewLaplacianWeightsCostAFactorization)
{
  for (const SoftConstraintFormulation formulation : BothFormulations)
  {
    SCOPED_TRACE(formulationName(formulation));
    const SoftGrid g(formulation);
    HarmonicFieldSolver solver;
    const FieldConstraints c = g.pairs(0.0, 2.0);
    ASSERT_EQ(solver.solve(g.mesh, g.weights, c).work, HarmonicFieldSolution::Work::Factorization);
    const std::vector<double> uniform = weightsFor(g.mesh, LaplacianWeighting::Uniform);
    const HarmonicFieldSolution b = solver.solve(g.mesh, uniform, c);
    EXPECT_EQ(b.work, HarmonicFieldSolution::Work::Factorization);
    EXPECT_TRUE(bitwiseEqual(b, freshSolve(g.mesh, uniform, c)));

    // One weight changed slightly is a new operator too.
    std::vector<double> edited = uniform;
    edited[5] *= 1.5;
    const HarmonicFieldSolution d = solver.solve(g.mesh, edited, c);
    EXPECT_EQ(d.work, HarmonicFieldSolution::Work::Factorization);
    EXPECT_TRUE(bitwiseEqual(d, freshSolve(g.mesh, edited, c)));

    // reset() forgets the factorization.
    solver.reset();
    EXPECT_EQ(solver.solve(g.mesh, edited, c).work, HarmonicFieldSolution::Work::Factorization);
  }
}

TEST(HarmonicField, HardOnlyCaching)
{
  const int columns = 12, rows = 9;
  const TriangleMesh grid = makeGrid(2.0, 1.5, columns, rows);
  const std::vector<double> weights = cotangentWeights(grid);
  HarmonicFieldSolver solver;
  ASSERT_EQ(
    solver.solve(grid, weights, gridColumnConstraints(columns, rows)).work, HarmonicFieldSolution::Work::Factorization);
  const FieldConstraints other = gridColumnConstraints(columns, rows, -3.0, 2.0);
  const HarmonicFieldSolution b = solver.solve(grid, weights, other);
  EXPECT_EQ(b.work, HarmonicFieldSolution::Work::BackSubstitution);
  EXPECT_TRUE(bitwiseEqual(b, freshSolve(grid, weights, other)));
  FieldConstraints moreVertices = other;
  moreVertices.dirichletVertices.push_back(5 * (columns + 1) + 6);
  moreVertices.dirichletValues.push_back(0.0);
  const HarmonicFieldSolution c = solver.solve(grid, weights, moreVertices);
  EXPECT_EQ(c.work, HarmonicFieldSolution::Work::Factorization);
  EXPECT_TRUE(bitwiseEqual(c, freshSolve(grid, weights, moreVertices)));
}

namespace
{
struct MixedCylinder
{
  static constexpr int Around = 36, Rings = 19;
  static constexpr double Height = 2.0;
  TriangleMesh mesh = makeCylinder(1.0, Height, Around, Rings);
  ClosestPointLocator locator{ mesh };
  std::vector<double> weights = cotangentWeights(mesh);
  SoftConstraintFormulation formulation = FieldConstraints().formulation;

  MixedCylinder() = default;
  explicit MixedCylinder(SoftConstraintFormulation f)
    : formulation(f)
  {
  }

  // Hard 2 at the bottom, 5 at the top; soft constraints at points given as (angle, z), with
  // values of the linear field 2 + 3 z / height plus `offset`.
  FieldConstraints constraints(const std::vector<std::pair<double, double>>& at, double offset, double w) const
  {
    FieldConstraints c = cylinderRingConstraints(Around, Rings, 2.0, 5.0);
    c.softWeight = w;
    c.formulation = this->formulation;
    for (const auto& [angle, z] : at)
    {
      const Vector3 p(std::cos(angle), std::sin(angle), z);
      SoftConstraint s = softAt(this->locator, p, 0.0);
      const Vector3 q = s.barycentric[0] * this->mesh.point(this->mesh.triangle(s.face)[0]) +
        s.barycentric[1] * this->mesh.point(this->mesh.triangle(s.face)[1]) +
        s.barycentric[2] * this->mesh.point(this->mesh.triangle(s.face)[2]);
      s.value = 2.0 + 3.0 * q.z() / Height + offset;
      c.soft.push_back(s);
    }
    return c;
  }
};
// Next to the bottom ring (faces with hard corners), in the middle, next to the top ring.
const std::vector<std::pair<double, double>> MixedPoints = { { 0.05, 0.03 }, { 1.3, 0.04 }, { 2.0, 1.01 },
  { 3.3, 0.77 }, { 4.4, 1.97 } };
} // namespace

TEST(HarmonicField, MixedHardAndConsistentSoftKeepLinearField)
{
  for (const SoftConstraintFormulation formulation : BothFormulations)
  {
    SCOPED_TRACE(formulationName(formulation));
    const MixedCylinder m(formulation);
    const FieldConstraints c = m.constraints(MixedPoints, 0.0, 3.0);
    // At least one soft constraint has a hard corner with a non-zero value.
    bool touchesHard = false;
    for (const SoftConstraint& s : c.soft)
    {
      for (int v : m.mesh.triangle(s.face))
      {
        touchesHard =
          touchesHard || v < MixedCylinder::Around || v >= (MixedCylinder::Rings - 1) * MixedCylinder::Around;
      }
    }
    ASSERT_TRUE(touchesHard);
    const HarmonicFieldSolution solution = freshSolve(m.mesh, m.weights, c);
    EXPECT_LE(solution.relativeResidual, 1e-10);
    for (int v = 0; v < m.mesh.vertexCount(); ++v)
    {
      EXPECT_NEAR(solution.field[v], 2.0 + 3.0 * m.mesh.point(v).z() / MixedCylinder::Height, 1e-9) << "vertex " << v;
    }
    EXPECT_LE(maximumMisfit(m.mesh, solution.field, c.soft), 1e-9);
  }
}

TEST(HarmonicField, MixedHardAndSoftCaching)
{
  for (const SoftConstraintFormulation formulation : BothFormulations)
  {
    SCOPED_TRACE(formulationName(formulation));
    const MixedCylinder m(formulation);
    HarmonicFieldSolver solver;
    double previous = std::numeric_limits<double>::infinity();
    // The soft values pull the field away from the linear one; more weight, smaller misfit.
    for (double w : { 0.3, 3.0, 30.0 })
    {
      const FieldConstraints c = m.constraints(MixedPoints, 0.4, w);
      const HarmonicFieldSolution s = freshSolve(m.mesh, m.weights, c);
      const double misfit = maximumMisfit(m.mesh, s.field, c.soft);
      EXPECT_LT(misfit, previous) << "softWeight " << w;
      EXPECT_LT(misfit, 0.4) << "softWeight " << w;
      previous = misfit;
      for (int i = 0; i < MixedCylinder::Around; ++i)
      {
        EXPECT_EQ(s.field[i], 2.0);
        EXPECT_EQ(s.field[(MixedCylinder::Rings - 1) * MixedCylinder::Around + i], 5.0);
      }
    }

    const FieldConstraints first = m.constraints(MixedPoints, 0.4, 3.0);
    const HarmonicFieldSolution a = solver.solve(m.mesh, m.weights, first);
    EXPECT_EQ(a.work, HarmonicFieldSolution::Work::Factorization);

    const FieldConstraints newValues = m.constraints(MixedPoints, -0.2, 3.0);
    const HarmonicFieldSolution b = solver.solve(m.mesh, m.weights, newValues);
    EXPECT_EQ(b.work, HarmonicFieldSolution::Work::BackSubstitution);
    EXPECT_TRUE(bitwiseEqual(b, freshSolve(m.mesh, m.weights, newValues)));

    // New hard values at the same vertices: a back-substitution as well.
    FieldConstraints newHard = newValues;
    std::fill(newHard.dirichletValues.begin(), newHard.dirichletValues.end(), 1.0);
    const HarmonicFieldSolution h = solver.solve(m.mesh, m.weights, newHard);
    EXPECT_EQ(h.work, HarmonicFieldSolution::Work::BackSubstitution);
    EXPECT_TRUE(bitwiseEqual(h, freshSolve(m.mesh, m.weights, newHard)));

    std::vector<std::pair<double, double>> movedPoints = MixedPoints;
    movedPoints[2].second += 0.2;
    const FieldConstraints moved = m.constraints(movedPoints, -0.2, 3.0);
    const HarmonicFieldSolution c = solver.solve(m.mesh, m.weights, moved);
    EXPECT_EQ(c.work, HarmonicFieldSolution::Work::Update);
    EXPECT_TRUE(bitwiseEqual(c, freshSolve(m.mesh, m.weights, moved)));

    const std::vector<double> uniform = weightsFor(m.mesh, LaplacianWeighting::Uniform);
    const HarmonicFieldSolution d = solver.solve(m.mesh, uniform, moved);
    EXPECT_EQ(d.work, HarmonicFieldSolution::Work::Factorization);
    EXPECT_TRUE(bitwiseEqual(d, freshSolve(m.mesh, uniform, moved)));
  }
}

// ---------------------------------------------------------------------------------------------
// Errors.

namespace
{
// `count` soft constraints at pseudo-random points of pseudo-random faces.
std::vector<SoftConstraint> scatteredConstraints(const TriangleMesh& mesh, int count, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> face(0, mesh.faceCount() - 1);
  std::uniform_real_distribution<double> unit(0.05, 1.0), value(-1.0, 1.0);
  std::vector<SoftConstraint> soft;
  for (int i = 0; i < count; ++i)
  {
    Vector3 b(unit(random), unit(random), unit(random));
    soft.push_back({ face(random), b / b.sum(), value(random) });
  }
  return soft;
}

// The field by dense normal equations over every non-hard vertex, L_F the Laplacian rows of the
// non-hard vertices. Least squares (SeamCut, Eq. 1): (L_F^T L_F + w^2 C_F^T C_F) f_F =
// -L_F^T L_D f_D + w^2 C_F^T (c - C_D f_D). Point values: (L_FF + K w C_F^T C_F) f_F = -L_FD f_D +
// K w C_F^T (c - C_D f_D), K = HarmonicFieldSolver::PointValueStiffness.
std::vector<double> denseReference(
  const TriangleMesh& mesh, const std::vector<double>& weights, const FieldConstraints& c)
{
  const int n = mesh.vertexCount();
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const int i = mesh.edgeVertices(e)[0], j = mesh.edgeVertices(e)[1];
    L(i, j) -= weights[e];
    L(j, i) -= weights[e];
    L(i, i) += weights[e];
    L(j, j) += weights[e];
  }
  std::vector<double> hard(n, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < c.dirichletVertices.size(); ++i)
  {
    hard[c.dirichletVertices[i]] = c.dirichletValues[i];
  }
  std::vector<int> freeIndex(n, -1), freeVertices;
  for (int v = 0; v < n; ++v)
  {
    if (std::isnan(hard[v]))
    {
      freeIndex[v] = static_cast<int>(freeVertices.size());
      freeVertices.push_back(v);
    }
  }
  const int m = static_cast<int>(freeVertices.size());
  Eigen::MatrixXd LF(m, m);
  Eigen::VectorXd known = Eigen::VectorXd::Zero(m);
  for (int r = 0; r < m; ++r)
  {
    for (int v = 0; v < n; ++v)
    {
      if (freeIndex[v] >= 0)
      {
        LF(r, freeIndex[v]) = L(freeVertices[r], v);
      }
      else
      {
        known[r] += L(freeVertices[r], v) * hard[v];
      }
    }
  }
  const bool squared = c.formulation == SoftConstraintFormulation::LeastSquares;
  Eigen::MatrixXd M = squared ? Eigen::MatrixXd(LF.transpose() * LF) : LF;
  Eigen::VectorXd b = squared ? Eigen::VectorXd(-LF.transpose() * known) : Eigen::VectorXd(-known);
  const double w2 = squared ? c.softWeight * c.softWeight : HarmonicFieldSolver::PointValueStiffness * c.softWeight;
  const int k = static_cast<int>(c.soft.size());
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(m, k); // C_F^T
  Eigen::VectorXd target(k);
  for (int i = 0; i < k; ++i)
  {
    target[i] = c.soft[i].value;
    for (int j = 0; j < 3; ++j)
    {
      const int v = mesh.triangle(c.soft[i].face)[j];
      if (freeIndex[v] >= 0)
      {
        C(freeIndex[v], i) += c.soft[i].barycentric[j];
      }
      else
      {
        target[i] -= c.soft[i].barycentric[j] * hard[v];
      }
    }
  }
  M += w2 * C * C.transpose();
  b += w2 * C * target;
  const Eigen::VectorXd f = M.ldlt().solve(b);
  std::vector<double> field(n);
  for (int v = 0; v < n; ++v)
  {
    field[v] = freeIndex[v] >= 0 ? f[freeIndex[v]] : hard[v];
  }
  return field;
}

double largestDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    worst = std::max(worst, std::abs(a[i] - b[i]));
  }
  return worst;
}
} // namespace

// The squared Laplacian of least squares has its own threshold for the geometric ordering: on
// two spheres, with it forced from one row for the squared Laplacian only, least squares is
// ordered otherwise than with AMD and gives the dense solution, and a new stroke (low-rank update
// of the nested-dissection factor) too; point values keep AMD's ordering.
TEST(HarmonicField, SquaredLaplacianTakesItsOwnGeometricOrderingThreshold)
{
  HarmonicFieldSolver defaults;
  EXPECT_EQ(defaults.geometricOrderingRows(), GeometricOrderingRows);
  EXPECT_EQ(defaults.geometricOrderingRowsSquared(), GeometricOrderingRowsSquared);
  EXPECT_LT(GeometricOrderingRowsSquared, GeometricOrderingRows);
  const TriangleMesh mesh = twoSpheres(2);
  const std::vector<double> weights = cotangentWeights(mesh);
  FieldConstraints c;
  c.softWeight = 0.7;
  c.soft = scatteredConstraints(mesh, 12, 19u);
  c.dirichletVertices = { 0, 5 };
  c.dirichletValues = { 2.0, -1.5 };
  HarmonicFieldSolver geometric;
  geometric.setGeometricOrderingRows(std::numeric_limits<int>::max(), 1);
  EXPECT_EQ(geometric.geometricOrderingRows(), std::numeric_limits<int>::max());
  EXPECT_EQ(geometric.geometricOrderingRowsSquared(), 1);
  const HarmonicFieldSolution first = geometric.solve(mesh, weights, c);
  EXPECT_EQ(first.work, HarmonicFieldSolution::Work::Factorization);
  EXPECT_LE(largestDifference(first.field, denseReference(mesh, weights, c)), 1e-8);
  HarmonicFieldSolver amd;
  amd.setGeometricOrderingRows(std::numeric_limits<int>::max());
  EXPECT_LE(largestDifference(first.field, amd.solve(mesh, weights, c).field), 1e-10);
#ifdef KERF_HAVE_CHOLMOD
  // Another ordering of the same squared Laplacian.
  ASSERT_EQ(geometric.factorPermutation().size(), amd.factorPermutation().size());
  EXPECT_FALSE(amd.factorPermutation().empty());
  EXPECT_NE(geometric.factorPermutation(), amd.factorPermutation());
#endif
  // Another stroke's constraints: a low-rank update of the same factor.
  c.soft = scatteredConstraints(mesh, 12, 23u);
  const HarmonicFieldSolution next = geometric.solve(mesh, weights, c);
  EXPECT_NE(next.work, HarmonicFieldSolution::Work::Factorization);
  EXPECT_LE(largestDifference(next.field, denseReference(mesh, weights, c)), 1e-8);
  // Point values factor the Laplacian, whose threshold is not reached: AMD's ordering.
  c.formulation = SoftConstraintFormulation::PointValues;
  EXPECT_LE(largestDifference(geometric.solve(mesh, weights, c).field, denseReference(mesh, weights, c)), 1e-8);
  EXPECT_LE(largestDifference(amd.solve(mesh, weights, c).field, denseReference(mesh, weights, c)), 1e-8);
#ifdef KERF_HAVE_CHOLMOD
  EXPECT_FALSE(amd.factorPermutation().empty());
  EXPECT_EQ(geometric.factorPermutation(), amd.factorPermutation());
#endif
}

// Few constraints go through the Woodbury identity, many through the factor of the whole
// system: both give the dense solution of either formulation, with and without hard values, on
// two components (one of them without hard values, so with an offset unknown).
TEST(HarmonicField, FewAndManySoftConstraintsMatchDenseReference)
{
  const TriangleMesh mesh = twoSpheres(2); // 2 x 162 vertices
  const std::vector<double> weights = cotangentWeights(mesh);
  for (const auto formulation : { SoftConstraintFormulation::LeastSquares, SoftConstraintFormulation::PointValues })
  {
    for (const bool withHard : { false, true })
    {
      for (const int count : { 12, 400 }) // 400 constraints exceed half the unknowns
      {
        SCOPED_TRACE(std::string(formulation == SoftConstraintFormulation::PointValues ? "point values, " : "") +
          (withHard ? "hard and " : "") + std::to_string(count) + " soft");
        FieldConstraints c;
        c.formulation = formulation;
        c.softWeight = 0.7;
        c.soft = scatteredConstraints(mesh, count, 7u + static_cast<unsigned>(count));
        if (withHard)
        {
          c.dirichletVertices = { 0, 5 };
          c.dirichletValues = { 2.0, -1.5 };
        }
        const std::vector<double> reference = denseReference(mesh, weights, c);
        HarmonicFieldSolver solver;
        const HarmonicFieldSolution solution = solver.solve(mesh, weights, c);
        EXPECT_LE(largestDifference(solution.field, reference), 1e-8);
        EXPECT_LE(solution.relativeResidual, 1e-9);
        // New values only: a back-substitution, still the reference.
        for (SoftConstraint& k : c.soft)
        {
          k.value = 0.5 - k.value;
        }
        const HarmonicFieldSolution again = solver.solve(mesh, weights, c);
        EXPECT_EQ(again.work, HarmonicFieldSolution::Work::BackSubstitution);
        EXPECT_LE(largestDifference(again.field, denseReference(mesh, weights, c)), 1e-8);
      }
    }
  }
}

// Thousands of constraints (a long, densely sampled stroke) take a sparse factorization, not a
// dense k x k one: 6000 constraints on 642 vertices solve like the reference.
TEST(HarmonicField, ThousandsOfSoftConstraints)
{
  const TriangleMesh mesh = makeIcosphere(1.0, 3);
  const std::vector<double> weights = cotangentWeights(mesh);
  for (const auto formulation : { SoftConstraintFormulation::LeastSquares, SoftConstraintFormulation::PointValues })
  {
    FieldConstraints c;
    c.formulation = formulation;
    c.soft = scatteredConstraints(mesh, 6000, 11u);
    HarmonicFieldSolver solver;
    const HarmonicFieldSolution solution = solver.solve(mesh, weights, c);
    EXPECT_EQ(solution.work, HarmonicFieldSolution::Work::Factorization);
    EXPECT_LE(largestDifference(solution.field, denseReference(mesh, weights, c)), 1e-8);
  }
}

TEST(HarmonicField, RefusesMissingConstraints)
{
  const TriangleMesh grid = makeGrid(1.0, 1.0, 4, 4);
  const std::vector<double> weights = cotangentWeights(grid);
  HarmonicFieldSolver solver;
  EXPECT_THROW(solver.solve(grid, weights, FieldConstraints()), Error);
  expectKerfError([&] { solver.solve(grid, weights, FieldConstraints()); }, "no constraint");
}

TEST(HarmonicField, RefusesComponentWithoutConstraint)
{
  const TriangleMesh mesh = twoSpheres(2);
  ASSERT_EQ(mesh.componentCount(), 2);
  const int perSphere = mesh.faceCount() / 2;
  const std::vector<double> weights = cotangentWeights(mesh);
  HarmonicFieldSolver solver;
  // Hard values on the first sphere only.
  FieldConstraints hard;
  hard.dirichletVertices = { 0, 3 };
  hard.dirichletValues = { 0.0, 1.0 };
  const int unconstrained = 1 - mesh.vertexComponent(0);
  expectKerfError([&] { solver.solve(mesh, weights, hard); }, "component " + std::to_string(unconstrained));
  expectKerfError([&] { solver.solve(mesh, weights, hard); }, std::to_string(perSphere) + " triangles");

  // Soft values on the second sphere only.
  FieldConstraints soft;
  SoftConstraint s;
  s.face = mesh.faceCount() - 1;
  s.barycentric = Vector3(0.2, 0.3, 0.5);
  s.value = 1.0;
  soft.soft = { s };
  const int otherComponent = 1 - mesh.faceComponent(s.face);
  expectKerfError([&] { solver.solve(mesh, weights, soft); }, "component " + std::to_string(otherComponent));

  // A constraint on each sphere is enough.
  FieldConstraints both = hard;
  both.soft = { s };
  const HarmonicFieldSolution solution = solver.solve(mesh, weights, both);
  // The softly constrained sphere takes the constraint's value everywhere.
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (mesh.vertexComponent(v) == mesh.faceComponent(s.face))
    {
      EXPECT_NEAR(solution.field[v], 1.0, 1e-8) << "vertex " << v;
    }
  }
}

TEST(HarmonicField, RefusesBadHardConstraints)
{
  const TriangleMesh grid = makeGrid(1.0, 1.0, 4, 4);
  const std::vector<double> weights = cotangentWeights(grid);
  HarmonicFieldSolver solver;
  auto hard = [](std::vector<int> vertices, std::vector<double> values) {
    FieldConstraints c;
    c.dirichletVertices = std::move(vertices);
    c.dirichletValues = std::move(values);
    return c;
  };
  const int n = grid.vertexCount();
  expectKerfError([&] { solver.solve(grid, weights, hard({ 0, n }, { 0.0, 1.0 })); }, std::to_string(n));
  expectKerfError([&] { solver.solve(grid, weights, hard({ -1, 3 }, { 0.0, 1.0 })); }, "-1");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectKerfError([&] { solver.solve(grid, weights, hard({ 0, 3 }, { 0.0, nan })); }, "NaN");
  expectKerfError(
    [&] {
      solver.solve(grid, weights, hard({ 0, 3 }, { std::numeric_limits<double>::infinity(), 1.0 }));
    },
    "infinite");
  expectKerfError([&] { solver.solve(grid, weights, hard({ 0, 3, 0 }, { 0.0, 1.0, 0.5 })); }, "vertex 0");
  expectKerfError([&] { solver.solve(grid, weights, hard({ 0, 3 }, { 0.0 })); }, "values");
  // The same value twice is not a conflict.
  EXPECT_NO_THROW(solver.solve(grid, weights, hard({ 0, 3, 0 }, { 0.0, 1.0, 0.0 })));
  // Wrong number of weights.
  expectKerfError(
    [&] {
      solver.solve(grid, std::vector<double>(weights.size() - 1, 1.0), hard({ 0, 3 }, { 0.0, 1.0 }));
    },
    "weight");
}

TEST(HarmonicField, RefusesBadSoftConstraints)
{
  const TriangleMesh grid = makeGrid(1.0, 1.0, 4, 4);
  const std::vector<double> weights = cotangentWeights(grid);
  HarmonicFieldSolver solver;
  auto soft = [](int face, double value, double w) {
    FieldConstraints c;
    SoftConstraint s;
    s.face = face;
    s.barycentric = Vector3(0.25, 0.25, 0.5);
    s.value = value;
    c.soft = { s };
    c.softWeight = w;
    return c;
  };
  const int faces = grid.faceCount();
  EXPECT_NO_THROW(solver.solve(grid, weights, soft(faces - 1, 1.0, 1.0)));
  expectKerfError([&] { solver.solve(grid, weights, soft(faces, 1.0, 1.0)); }, "face " + std::to_string(faces));
  expectKerfError([&] { solver.solve(grid, weights, soft(-1, 1.0, 1.0)); }, "face -1");
  expectKerfError([&] { solver.solve(grid, weights, soft(0, std::numeric_limits<double>::quiet_NaN(), 1.0)); }, "NaN");
  FieldConstraints nanBarycentric = soft(0, 1.0, 1.0);
  nanBarycentric.soft[0].barycentric.x() = std::numeric_limits<double>::quiet_NaN();
  expectKerfError([&] { solver.solve(grid, weights, nanBarycentric); }, "NaN");
  expectKerfError([&] { solver.solve(grid, weights, soft(0, 1.0, 0.0)); }, "weight");
  expectKerfError([&] { solver.solve(grid, weights, soft(0, 1.0, -2.0)); }, "weight");
  expectKerfError(
    [&] { solver.solve(grid, weights, soft(0, 1.0, std::numeric_limits<double>::quiet_NaN())); }, "weight");
  FieldConstraints unknown = soft(0, 1.0, 1.0);
  unknown.formulation = static_cast<SoftConstraintFormulation>(7);
  expectKerfError([&] { solver.solve(grid, weights, unknown); }, "formulation");
  // The solver still works after every refusal.
  EXPECT_EQ(solver.solve(grid, weights, soft(0, 1.0, 1.0)).relativeResidual,
    freshSolve(grid, weights, soft(0, 1.0, 1.0)).relativeResidual);
}

// ---------------------------------------------------------------------------------------------
// Strokes to constraints (SeamCut, section 2.1.1).

TEST(StrokeConstraints, StraightStrokeOnPlane)
{
  const TriangleMesh grid = makeGrid(2.0, 2.0, 20, 20);
  const ClosestPointLocator locator(grid);
  const std::vector<Vector3> normals = computeVertexNormals(grid);
  // Three collinear segments of different lengths.
  const std::vector<Vector3> stroke = { { 0.5, 0.6, 0.0 }, { 0.8, 0.75, 0.0 }, { 1.0, 0.85, 0.0 }, { 1.4, 1.05, 0.0 } };
  StrokeOptions options;
  options.samplesPerSegment = 4;
  options.offset = 0.03;
  options.isoValue = 0.25;
  options.maximumDistance = 0.1;
  const StrokeConstraintSet set = strokeConstraints(grid, locator, normals, { stroke }, options);
  const int segments = 3;
  ASSERT_EQ(static_cast<int>(set.constraints.size()), 2 * options.samplesPerSegment * segments);
  ASSERT_EQ(set.positions.size(), set.constraints.size());
  ASSERT_EQ(static_cast<int>(set.strokeSamples.size()), options.samplesPerSegment * segments);
  const Vector3 side = Vector3::UnitZ().cross(stroke[1] - stroke[0]).normalized(); // n x t
  for (int j = 0; j < segments; ++j)
  {
    for (int k = 0; k < options.samplesPerSegment; ++k)
    {
      const int i = j * options.samplesPerSegment + k;
      const double t = (k + 0.5) / options.samplesPerSegment;
      const Vector3 sample = set.strokeSamples[i];
      EXPECT_LE((sample - (stroke[j] + t * (stroke[j + 1] - stroke[j]))).norm(), 1e-12) << "sample " << i;
      const SoftConstraint& plus = set.constraints[2 * i];
      const SoftConstraint& minus = set.constraints[2 * i + 1];
      EXPECT_EQ(plus.value, options.isoValue + 1.0);
      EXPECT_EQ(minus.value, options.isoValue - 1.0);
      const Vector3& p = set.positions[2 * i];
      const Vector3& q = set.positions[2 * i + 1];
      EXPECT_NEAR((p - sample).norm(), options.offset, 1e-9) << "sample " << i;
      EXPECT_NEAR((q - sample).norm(), options.offset, 1e-9) << "sample " << i;
      EXPECT_LE((p - (sample + options.offset * side)).norm(), 1e-9) << "sample " << i;
      EXPECT_LE((q - (sample - options.offset * side)).norm(), 1e-9) << "sample " << i;
      // The constraints sit where their positions say.
      for (int m = 0; m < 2; ++m)
      {
        const SoftConstraint& c = set.constraints[2 * i + m];
        ASSERT_GE(c.face, 0);
        ASSERT_LT(c.face, grid.faceCount());
        const Triangle& tri = grid.triangle(c.face);
        const Vector3 at = c.barycentric[0] * grid.point(tri[0]) + c.barycentric[1] * grid.point(tri[1]) +
          c.barycentric[2] * grid.point(tri[2]);
        EXPECT_LE((at - set.positions[2 * i + m]).norm(), 1e-12);
        EXPECT_NEAR(c.barycentric.sum(), 1.0, 1e-12);
        EXPECT_GE(c.barycentric.minCoeff(), -1e-12);
      }
    }
  }
}

TEST(StrokeConstraints, ShortStrokeOffsetIsAFractionOfItsLength)
{
  // A stroke 0.2 long with the offset 0.03: its constraints sit 0.05 x 0.2 = 0.01 beside it (by
  // default), or at the full offset with the cap off; a stroke 1 long keeps the offset.
  const TriangleMesh grid = makeGrid(2.0, 2.0, 20, 20);
  const ClosestPointLocator locator(grid);
  const std::vector<Vector3> normals = computeVertexNormals(grid);
  StrokeOptions options;
  options.offset = 0.03;
  ASSERT_EQ(options.offsetLengthFraction, 0.05);
  for (const double length : { 0.2, 1.0 })
  {
    const std::vector<Vector3> stroke = { { 0.5, 0.9, 0.0 }, { 0.5 + length, 0.9, 0.0 } };
    for (const double fraction : { 0.05, 0.0 })
    {
      options.offsetLengthFraction = fraction;
      const StrokeConstraintSet set = strokeConstraints(grid, locator, normals, { stroke }, options);
      const double expected = fraction > 0.0 ? std::min(0.03, fraction * length) : 0.03;
      ASSERT_EQ(set.positions.size(), 2 * set.strokeSamples.size());
      for (std::size_t i = 0; i < set.positions.size(); ++i)
      {
        EXPECT_NEAR((set.positions[i] - set.strokeSamples[i / 2]).norm(), expected, 1e-9)
          << "length " << length << ", fraction " << fraction;
      }
    }
  }
}

TEST(StrokeConstraints, StrokeAboveThePlaneIsProjected)
{
  const TriangleMesh grid = makeGrid(2.0, 2.0, 20, 20);
  const ClosestPointLocator locator(grid);
  const std::vector<Vector3> normals = computeVertexNormals(grid);
  StrokeOptions options;
  options.samplesPerSegment = 2;
  options.offset = 0.05;
  options.maximumDistance = 0.1;
  const StrokeConstraintSet set =
    strokeConstraints(grid, locator, normals, { { { 1.2, 0.5, 0.04 }, { 1.2, 1.5, 0.04 } } }, options);
  ASSERT_EQ(set.constraints.size(), 4u);
  for (std::size_t i = 0; i < set.strokeSamples.size(); ++i)
  {
    EXPECT_NEAR(set.strokeSamples[i].z(), 0.0, 1e-15);
    // Walking along +y with the normal +z, n x t is -x: the +1 point has the smaller x.
    EXPECT_NEAR(set.positions[2 * i].x(), 1.2 - 0.05, 1e-12);
    EXPECT_NEAR(set.positions[2 * i + 1].x(), 1.2 + 0.05, 1e-12);
    EXPECT_EQ(set.constraints[2 * i].value, 1.0);
    EXPECT_EQ(set.constraints[2 * i + 1].value, -1.0);
  }
}

TEST(StrokeConstraints, RefusesFarAndDegenerateStrokes)
{
  const TriangleMesh grid = makeGrid(2.0, 2.0, 10, 10);
  const ClosestPointLocator locator(grid);
  const std::vector<Vector3> normals = computeVertexNormals(grid);
  StrokeOptions options;
  options.offset = 0.02;
  options.maximumDistance = 0.1;
  // The second half of the stroke leaves the surface.
  expectKerfError(
    [&] {
      strokeConstraints(grid, locator, normals, { { { 0.5, 0.5, 0.0 }, { 1.0, 1.0, 1.0 } } }, options);
    },
    "away from the surface");
  // One point, or the same point twice.
  expectKerfError(
    [&] {
      strokeConstraints(grid, locator, normals, { { { 0.5, 0.5, 0.0 } } }, options);
    },
    "two distinct points");
  expectKerfError(
    [&] {
      strokeConstraints(grid, locator, normals, { { { 0.5, 0.5, 0.0 }, { 0.5, 0.5, 0.0 } } }, options);
    },
    "two distinct points");
  expectKerfError([&] { strokeConstraints(grid, locator, normals, {}, options); }, "no constraint");
  // A stroke along the normal gives no constraint.
  expectKerfError(
    [&] {
      strokeConstraints(grid, locator, normals, { { { 0.5, 0.5, 0.0 }, { 0.5, 0.5, 0.05 } } }, options);
    },
    "no constraint");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectKerfError(
    [&] {
      strokeConstraints(grid, locator, normals, { { { 0.5, 0.5, 0.0 }, { nan, 0.5, 0.0 } } }, options);
    },
    "NaN");
  StrokeOptions noOffset = options;
  noOffset.offset = 0.0;
  expectKerfError(
    [&] {
      strokeConstraints(grid, locator, normals, { { { 0.5, 0.5, 0.0 }, { 1.0, 0.5, 0.0 } } }, noOffset);
    },
    "offset");
}

TEST(StrokeConstraints, StrokeAroundACylinder)
{
  // A closed stroke around a cylinder at mid-height: the field's zero level follows it.
  const int around = 48, rings = 25;
  const double height = 2.0;
  const TriangleMesh cylinder = makeCylinder(1.0, height, around, rings);
  const ClosestPointLocator locator(cylinder);
  const std::vector<Vector3> normals = computeVertexNormals(cylinder);
  std::vector<Vector3> stroke;
  const int segments = 16;
  for (int i = 0; i <= segments; ++i)
  {
    const double angle = 2.0 * Pi * (i + 0.5) / segments;
    stroke.emplace_back(std::cos(angle), std::sin(angle), 1.0);
  }
  StrokeOptions options;
  options.offset = 0.05;
  options.maximumDistance = 0.1;
  const StrokeConstraintSet set = strokeConstraints(cylinder, locator, normals, { stroke }, options);
  ASSERT_EQ(static_cast<int>(set.constraints.size()), 2 * options.samplesPerSegment * segments);
  for (std::size_t i = 0; i < set.strokeSamples.size(); ++i)
  {
    // The stroke turns counter-clockwise seen from +z and n points out, so n x t points up.
    EXPECT_NEAR(set.positions[2 * i].z() - set.strokeSamples[i].z(), options.offset, 1e-9) << "sample " << i;
    EXPECT_NEAR(set.positions[2 * i + 1].z() - set.strokeSamples[i].z(), -options.offset, 1e-9) << "sample " << i;
    EXPECT_NEAR(set.strokeSamples[i].z(), 1.0, 1e-12);
  }
  FieldConstraints c;
  c.soft = set.constraints;
  c.softWeight = 10.0;
  HarmonicFieldSolver solver;
  const HarmonicFieldSolution solution = solver.solve(cylinder, cotangentWeights(cylinder), c);
  EXPECT_LE(solution.relativeResidual, 1e-8);
  EXPECT_LE(maximumMisfit(cylinder, solution.field, c.soft), 0.1);
  const int middle = (rings - 1) / 2; // the ring at z = 1
  for (int i = 0; i < around; ++i)
  {
    EXPECT_LT(solution.field[(middle - 1) * around + i], 0.0) << "column " << i;
    EXPECT_GT(solution.field[(middle + 1) * around + i], 0.0) << "column " << i;
    EXPECT_NEAR(solution.field[middle * around + i], 0.0, 0.05) << "column " << i;
  }
}

TEST(StrokeConstraints, SparseStrokeFollowsTheSphere)
{
  // Three points a third of the equator apart on a sphere of radius 0.5: each chord passes 0.25
  // from the surface, far beyond the allowed distance, so the samples are placed along the
  // surface instead, at the chords' fractions of each great-circle arc.
  const double radius = 0.5;
  const TriangleMesh sphere = makeIcosphere(radius, 5);
  const ClosestPointLocator locator(sphere);
  const std::vector<Vector3> normals = computeVertexNormals(sphere);
  std::vector<Vector3> stroke;
  for (int i = 0; i < 3; ++i)
  {
    const double angle = 2.0 * Pi * i / 3.0;
    stroke.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0);
  }
  StrokeOptions options;
  options.offset = 0.005 * 2.0 * std::sqrt(3.0) * radius;
  options.maximumDistance = 0.05 * 2.0 * std::sqrt(3.0) * radius;
  const StrokeConstraintSet set = strokeConstraints(sphere, locator, normals, { stroke }, options);
  ASSERT_EQ(static_cast<int>(set.strokeSamples.size()), 2 * options.samplesPerSegment);
  // The icosphere's triangles lie inside the sphere by at most radius (1 - cos(edge / 2r)).
  const double chordDepth = 0.002 * radius;
  for (std::size_t i = 0; i < set.strokeSamples.size(); ++i)
  {
    const Vector3& p = set.strokeSamples[i];
    EXPECT_NEAR(p.norm(), radius, chordDepth) << "sample " << i;
    EXPECT_NEAR(p.z(), 0.0, 1e-3 * radius) << "sample " << i;
    // Sample k of segment j at longitude (j + (k + 1/2) / 4) * 120 degrees.
    const double expected = 120.0 * (static_cast<double>(i / 4) + (static_cast<double>(i % 4) + 0.5) / 4.0);
    EXPECT_NEAR(std::atan2(p.y(), p.x()) * 180.0 / Pi + (expected > 180.0 ? 360.0 : 0.0), expected, 1.0)
      << "sample " << i;
  }
  for (std::size_t i = 0; i < set.positions.size(); ++i)
  {
    EXPECT_NEAR(set.positions[i].norm(), radius, chordDepth) << "constraint " << i;
  }
  // The stroke's own points are still held to the allowed distance.
  std::vector<Vector3> away = stroke;
  away[1] *= 1.5;
  expectKerfError([&] { strokeConstraints(sphere, locator, normals, { away }, options); }, "stroke 0 point 1 is");
}

// ---------------------------------------------------------------------------------------------
// Closest points.

TEST(ClosestPoint, TriangleRegions)
{
  const Vector3 a(0.2, -0.1, 0.3), b(1.7, 0.4, 0.1), c(0.5, 1.6, -0.2);
  const Vector3 n = (b - a).cross(c - a).normalized();
  Vector3 barycentric;
  // Inside, above and below the plane.
  for (const Vector3& w : { Vector3(0.2, 0.3, 0.5), Vector3(0.6, 0.2, 0.2), Vector3(1.0 / 3, 1.0 / 3, 1.0 / 3) })
  {
    for (double h : { 0.0, 0.4, -0.7 })
    {
      const Vector3 onPlane = w[0] * a + w[1] * b + w[2] * c;
      const Vector3 p = closestPointOnTriangle(onPlane + h * n, a, b, c, barycentric);
      EXPECT_LE((barycentric - w).norm(), 1e-12) << w.transpose() << " h " << h;
      EXPECT_LE((p - onPlane).norm(), 1e-12);
    }
  }
  // On and beyond each edge (moved outwards in the plane, perpendicular to the edge).
  const Vector3 corners[3] = { a, b, c };
  for (int k = 0; k < 3; ++k)
  {
    const Vector3& p0 = corners[k];
    const Vector3& p1 = corners[(k + 1) % 3];
    const Vector3& opposite = corners[(k + 2) % 3];
    Vector3 outwards = (p1 - p0).cross(n).normalized();
    if (outwards.dot(opposite - p0) > 0.0)
    {
      outwards = -outwards;
    }
    for (double s : { 0.1, 0.45, 0.9 })
    {
      for (double d : { 0.0, 0.3 })
      {
        const Vector3 onEdge = (1.0 - s) * p0 + s * p1;
        const Vector3 p = closestPointOnTriangle(onEdge + d * outwards + 0.2 * n, a, b, c, barycentric);
        Vector3 expected = Vector3::Zero();
        expected[k] = 1.0 - s;
        expected[(k + 1) % 3] = s;
        EXPECT_LE((barycentric - expected).norm(), 1e-12) << "edge " << k << " s " << s << " d " << d;
        EXPECT_LE((p - onEdge).norm(), 1e-12) << "edge " << k;
      }
    }
    // At and beyond the corner (along the bisector of the outer angle).
    const Vector3 away = ((p0 - p1).normalized() + (p0 - opposite).normalized()).normalized();
    for (double d : { 0.0, 0.5 })
    {
      const Vector3 p = closestPointOnTriangle(p0 + d * away - 0.3 * n, a, b, c, barycentric);
      Vector3 expected = Vector3::Zero();
      expected[k] = 1.0;
      EXPECT_LE((barycentric - expected).norm(), 1e-12) << "corner " << k << " d " << d;
      EXPECT_LE((p - p0).norm(), 1e-12) << "corner " << k;
    }
  }
}

TEST(ClosestPoint, LocatorMatchesBruteForceAroundTorus)
{
  const TriangleMesh torus = makeTorus(2.0, 0.6, 48, 20);
  const ClosestPointLocator locator(torus);
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> coordinate(-3.2, 3.2);
  std::uniform_real_distribution<double> height(-1.2, 1.2);
  int differentFaces = 0;
  for (int q = 0; q < 400; ++q)
  {
    Vector3 query(coordinate(random), coordinate(random), height(random));
    if (q % 4 == 0)
    {
      query = torus.point(q % torus.vertexCount()); // on a vertex: ties between faces
    }
    int bestFace = -1;
    double best = std::numeric_limits<double>::infinity();
    Vector3 bestPosition = Vector3::Zero(), bestBarycentric = Vector3::Zero();
    for (int f = 0; f < torus.faceCount(); ++f)
    {
      const Triangle& t = torus.triangle(f);
      Vector3 barycentric;
      const Vector3 p =
        closestPointOnTriangle(query, torus.point(t[0]), torus.point(t[1]), torus.point(t[2]), barycentric);
      const double d = (p - query).norm();
      if (d < best)
      {
        best = d;
        bestFace = f;
        bestPosition = p;
        bestBarycentric = barycentric;
      }
    }
    const ClosestPointLocator::Hit hit = locator.closest(query);
    ASSERT_GE(hit.face, 0);
    EXPECT_NEAR(hit.distance, best, 1e-12) << "query " << query.transpose();
    EXPECT_NEAR((hit.position - query).norm(), hit.distance, 1e-12);
    const Triangle& t = torus.triangle(hit.face);
    const Vector3 at = hit.barycentric[0] * torus.point(t[0]) + hit.barycentric[1] * torus.point(t[1]) +
      hit.barycentric[2] * torus.point(t[2]);
    EXPECT_LE((at - hit.position).norm(), 1e-12);
    if (hit.face == bestFace)
    {
      EXPECT_LE((hit.position - bestPosition).norm(), 1e-12);
      EXPECT_LE((hit.barycentric - bestBarycentric).norm(), 1e-12);
    }
    else
    {
      ++differentFaces;
      // Only a tie may pick another face.
      Vector3 barycentric;
      const Triangle& u = torus.triangle(hit.face);
      const Vector3 p =
        closestPointOnTriangle(query, torus.point(u[0]), torus.point(u[1]), torus.point(u[2]), barycentric);
      EXPECT_NEAR((p - query).norm(), best, 1e-12) << "query " << query.transpose();
    }
  }
  RecordProperty("DifferentFacesOnTies", std::to_string(differentFaces));
}

TEST(ClosestPoint, EmptyMeshGivesNoFace)
{
  const TriangleMesh empty;
  const ClosestPointLocator locator(empty);
  EXPECT_EQ(locator.closest(Vector3(1, 2, 3)).face, -1);
}

TEST(HarmonicField, ClampToConstraintRangeUsesHardAndSoftValues)
{
  FieldConstraints constraints;
  const std::vector<double> field{ -12.0, -1.0, 0.25, 0.5, 26.0 };
  EXPECT_EQ(clampToConstraintRange(field, constraints), field); // nothing to clamp to
  constraints.soft.push_back({ 0, Vector3(1.0, 0.0, 0.0), 1.0 });
  constraints.soft.push_back({ 0, Vector3(0.0, 1.0, 0.0), -1.0 });
  EXPECT_EQ(clampToConstraintRange(field, constraints), (std::vector<double>{ -1.0, -1.0, 0.25, 0.5, 1.0 }));
  constraints.soft.clear();
  constraints.dirichletVertices = { 0, 1 };
  constraints.dirichletValues = { 0.0, 0.5 };
  EXPECT_EQ(clampToConstraintRange(field, constraints), (std::vector<double>{ 0.0, 0.0, 0.25, 0.5, 0.5 }));
}
