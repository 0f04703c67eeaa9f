// Isolines of piecewise-linear fields: extraction on analytic fields, ROI Scissor scores and cut sides.
#include "Error.h"
#include "Evaluation/SegmentationMetrics.h"
#include "Evaluation/SimulatedStrokes.h"
#include "Geometry/ClosestPoint.h"
#include "Harmonic/HarmonicCutSession.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/Isolines.h"
#include "Mesh/MeshGenerators.h"
#include "Numerics/FieldGradient.h"
#include "Numerics/LaplacianWeights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <string>

using namespace kerf;

namespace
{
constexpr double Pi = 3.14159265358979323846;

std::vector<double> sampleField(const TriangleMesh& mesh, const std::function<double(const Vector3&)>& f)
{
  std::vector<double> field;
  for (const Vector3& p : mesh.points())
  {
    field.push_back(f(p));
  }
  return field;
}

std::vector<double> gradientMagnitudes(const TriangleMesh& mesh, const std::vector<double>& field)
{
  std::vector<double> magnitudes;
  for (const Vector3& g : computeFaceGradients(mesh, field))
  {
    magnitudes.push_back(g.norm());
  }
  return magnitudes;
}

// Structural invariants of one extracted isoline: as many faces as segments, every segment inside
// its face, no zero-length segment (no repeated consecutive point), the stored length.
void expectWellFormed(const TriangleMesh& mesh, const Isoline& line, const std::string& what)
{
  const std::size_t n = line.points.size();
  ASSERT_GE(n, 2u) << what;
  ASSERT_EQ(line.faces.size(), line.closed ? n : n - 1) << what;
  double length = 0.0;
  for (std::size_t i = 0; i < line.faces.size(); ++i)
  {
    const Vector3& a = line.points[i];
    const Vector3& b = line.points[(i + 1) % n];
    EXPECT_GT((b - a).norm(), 1e-9) << what << ": repeated point " << i << " at " << a.transpose();
    length += (b - a).norm();
    const Triangle& t = mesh.triangle(line.faces[i]);
    for (const Vector3& p : { a, b })
    {
      Vector3 barycentric;
      const Vector3 q = closestPointOnTriangle(p, mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), barycentric);
      EXPECT_LE((q - p).norm(), 1e-12) << what << ": segment " << i << " leaves face " << line.faces[i];
    }
  }
  EXPECT_NEAR(line.length, length, 1e-12 * std::max(1.0, length)) << what;
}

// Walking along every isoline, the values above lie on one side: the sign of (n x d) . grad f
// (n the face normal, d the segment direction) is the same on every segment. Returns that sign.
int consistentSide(const TriangleMesh& mesh, const std::vector<double>& field, const std::vector<Isoline>& lines,
  const std::string& what)
{
  const std::vector<Vector3> gradients = computeFaceGradients(mesh, field);
  int sign = 0;
  for (const Isoline& line : lines)
  {
    const std::size_t n = line.points.size();
    for (std::size_t i = 0; i < line.faces.size(); ++i)
    {
      const int f = line.faces[i];
      const Triangle& t = mesh.triangle(f);
      const Vector3 normal = (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0]));
      const Vector3 d = line.points[(i + 1) % n] - line.points[i];
      const double side = normal.cross(d).dot(gradients[f]);
      if (side == 0.0)
      {
        continue;
      }
      const int s = side > 0.0 ? 1 : -1;
      if (sign == 0)
      {
        sign = s;
      }
      EXPECT_EQ(s, sign) << what << ": segment " << i << " in face " << f << " turns the other way";
    }
  }
  EXPECT_NE(sign, 0) << what;
  return sign;
}

// Area enclosed by a closed polyline, projected on the xy plane (positive when counter-clockwise
// seen from +z).
double signedAreaSeenFromZ(const Isoline& line)
{
  double area = 0.0;
  const std::size_t n = line.points.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vector3& a = line.points[i];
    const Vector3& b = line.points[(i + 1) % n];
    area += 0.5 * (a.x() * b.y() - b.x() * a.y());
  }
  return area;
}

// Smallest and largest z of a polyline's points.
std::pair<double, double> zRange(const Isoline& line)
{
  std::pair<double, double> range(std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity());
  for (const Vector3& p : line.points)
  {
    range.first = std::min(range.first, p.z());
    range.second = std::max(range.second, p.z());
  }
  return range;
}

Vector3 centroid(const TriangleMesh& mesh, int f)
{
  const Triangle& t = mesh.triangle(f);
  return (mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0;
}

int labelCount(const std::vector<int>& labels)
{
  return static_cast<int>(std::set<int>(labels.begin(), labels.end()).size());
}

// Labels are numbered 0, 1, ... in order of their first face.
void expectLabelsInFaceOrder(const std::vector<int>& labels)
{
  int next = 0;
  for (int label : labels)
  {
    ASSERT_GE(label, 0);
    ASSERT_LE(label, next);
    next = std::max(next, label + 1);
  }
}
} // namespace

// ---------------------------------------------------------------------------------------------
// Extraction.

TEST(Isolines, GridGenericValueIsOneStraightOpenLine)
{
  const double width = 1.0, height = 1.5;
  const int columns = 10, rows = 12;
  const TriangleMesh grid = makeGrid(width, height, columns, rows);
  const std::vector<double> field = sampleField(grid, [](const Vector3& p) { return p.x(); });
  for (double value : { 0.37, 0.05, 0.9321 })
  {
    const std::string what = "value " + std::to_string(value);
    const std::vector<Isoline> lines = extractIsolines(grid, field, value);
    ASSERT_EQ(lines.size(), 1u) << what;
    const Isoline& line = lines[0];
    EXPECT_FALSE(line.closed) << what;
    expectWellFormed(grid, line, what);
    // Two crossings per column of cells: on the horizontal edges and on the diagonals.
    EXPECT_EQ(line.points.size(), static_cast<std::size_t>(2 * rows + 1)) << what;
    for (const Vector3& p : line.points)
    {
      EXPECT_NEAR(p.x(), value, 1e-12) << what;
      EXPECT_EQ(p.z(), 0.0);
    }
    EXPECT_NEAR(line.length, height, 1e-12) << what;
    // From one boundary to the other, monotonically.
    const double direction = line.points.back().y() - line.points.front().y();
    EXPECT_NEAR(std::abs(direction), height, 1e-12) << what;
    for (std::size_t i = 0; i + 1 < line.points.size(); ++i)
    {
      EXPECT_GT((line.points[i + 1].y() - line.points[i].y()) * direction, 0.0) << what;
    }
    consistentSide(grid, field, lines, what);
  }
}

TEST(Isolines, GridValueThroughVerticesHasNoRepeatedPoints)
{
  const double width = 1.0, height = 1.5;
  const int columns = 10, rows = 12;
  const TriangleMesh grid = makeGrid(width, height, columns, rows);
  const std::vector<double> field = sampleField(grid, [](const Vector3& p) { return p.x(); });
  // Every column of vertices, the right boundary included.
  for (int column = 1; column <= columns; ++column)
  {
    const double value = grid.point(column).x();
    const std::string what = "column " + std::to_string(column);
    const std::vector<Isoline> lines = extractIsolines(grid, field, value);
    ASSERT_EQ(lines.size(), 1u) << what;
    const Isoline& line = lines[0];
    EXPECT_FALSE(line.closed) << what;
    expectWellFormed(grid, line, what);
    // Exactly the column's vertices, in order: no repeated point and no gap.
    ASSERT_EQ(line.points.size(), static_cast<std::size_t>(rows + 1)) << what;
    for (const Vector3& p : line.points)
    {
      EXPECT_NEAR(p.x(), value, 1e-12) << what;
    }
    const bool upwards = line.points.back().y() > line.points.front().y();
    for (int j = 0; j <= rows; ++j)
    {
      const int row = upwards ? j : rows - j;
      EXPECT_LE((line.points[j] - grid.point(row * (columns + 1) + column)).norm(), 1e-12) << what << " row " << row;
    }
    EXPECT_NEAR(line.length, height, 1e-12) << what;
    consistentSide(grid, field, lines, what);
  }
  // The minimum: every vertex counts as above, nothing is crossed.
  EXPECT_TRUE(extractIsolines(grid, field, 0.0).empty());
  EXPECT_TRUE(extractIsolines(grid, field, -1.0).empty());
  EXPECT_TRUE(extractIsolines(grid, field, 1.5).empty());
}

TEST(Isolines, FlatRegionAtTheValueIsBoundedNotFilled)
{
  const double height = 1.5;
  const int columns = 10, rows = 12;
  const TriangleMesh grid = makeGrid(1.0, height, columns, rows);
  const std::vector<double> field = sampleField(grid, [](const Vector3& p) { return std::min(0.0, p.x() - 0.5); });
  ASSERT_EQ(grid.point(5).x(), 0.5);
  const std::vector<Isoline> lines = extractIsolines(grid, field, 0.0);
  ASSERT_EQ(lines.size(), 1u);
  const Isoline& line = lines[0];
  EXPECT_FALSE(line.closed);
  expectWellFormed(grid, line, "flat");
  ASSERT_EQ(line.points.size(), static_cast<std::size_t>(rows + 1));
  for (const Vector3& p : line.points)
  {
    EXPECT_NEAR(p.x(), 0.5, 1e-12);
  }
  EXPECT_NEAR(line.length, height, 1e-12);
}

TEST(Isolines, SphereLatitudeIsOneClosedLoop)
{
  const double radius = 2.0;
  const TriangleMesh sphere = makeIcosphere(radius, 4);
  const std::vector<double> field = sampleField(sphere, [&](const Vector3& p) { return p.z() / radius; });
  int orientation = 0, side = 0;
  // z = 0 passes through vertices of the icosphere's equator.
  for (double value : { -0.7, -0.3, 0.0, 0.3, 0.55, 0.9 })
  {
    const std::string what = "value " + std::to_string(value);
    const std::vector<Isoline> lines = extractIsolines(sphere, field, value);
    ASSERT_EQ(lines.size(), 1u) << what;
    const Isoline& loop = lines[0];
    EXPECT_TRUE(loop.closed) << what;
    expectWellFormed(sphere, loop, what);
    for (const Vector3& p : loop.points)
    {
      EXPECT_NEAR(p.z(), value * radius, 1e-12) << what;
    }
    const double circle = radius * std::sqrt(1.0 - value * value);
    EXPECT_NEAR(loop.length, 2.0 * Pi * circle, 0.01 * 2.0 * Pi * circle) << what;
    const double area = signedAreaSeenFromZ(loop);
    EXPECT_NEAR(std::abs(area), Pi * circle * circle, 0.02 * Pi * circle * circle) << what;
    const int sign = area > 0.0 ? 1 : -1;
    if (orientation == 0)
    {
      orientation = sign;
    }
    EXPECT_EQ(sign, orientation) << what << ": the loop turns the other way";
    const int s = consistentSide(sphere, field, lines, what);
    if (side == 0)
    {
      side = s;
    }
    EXPECT_EQ(s, side) << what;
  }
  // The value of the brief: 1% of the circle's length.
  const std::vector<Isoline> lines = extractIsolines(sphere, field, 0.3);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NEAR(lines[0].length / (2.0 * Pi * std::sqrt(1.0 - 0.09) * radius), 1.0, 0.01);
}

TEST(Isolines, SphereValueThroughVerticesHasNoRepeatedPoints)
{
  // f = z at the height of a vertex: the loop passes through that vertex (and its mirror images).
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  const std::vector<double> field = sampleField(sphere, [](const Vector3& p) { return p.z(); });
  int checked = 0;
  for (int v = 0; v < sphere.vertexCount() && checked < 12; v += 37)
  {
    const double value = field[v];
    if (std::abs(value) > 0.9)
    {
      continue;
    }
    ++checked;
    const std::string what = "value " + std::to_string(value) + " of vertex " + std::to_string(v);
    const std::vector<Isoline> lines = extractIsolines(sphere, field, value);
    ASSERT_EQ(lines.size(), 1u) << what;
    EXPECT_TRUE(lines[0].closed) << what;
    expectWellFormed(sphere, lines[0], what);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vector3& p : lines[0].points)
    {
      EXPECT_NEAR(p.z(), value, 1e-12) << what;
      nearest = std::min(nearest, (p - sphere.point(v)).norm());
    }
    EXPECT_LE(nearest, 1e-12) << what;
  }
  EXPECT_EQ(checked, 12);
}

TEST(Isolines, TwoLoopsOnTorusAndSphere)
{
  // f = x on a torus around z: the plane x = 0.5 cuts the tube twice.
  const TriangleMesh torus = makeTorus(2.0, 0.6, 64, 24);
  const std::vector<double> fx = sampleField(torus, [](const Vector3& p) { return p.x(); });
  const std::vector<Isoline> torusLines = extractIsolines(torus, fx, 0.5);
  ASSERT_EQ(torusLines.size(), 2u);
  for (const Isoline& loop : torusLines)
  {
    EXPECT_TRUE(loop.closed);
    expectWellFormed(torus, loop, "torus");
    for (const Vector3& p : loop.points)
    {
      EXPECT_NEAR(p.x(), 0.5, 1e-12);
    }
  }
  consistentSide(torus, fx, torusLines, "torus");

  // f = z^2 on a sphere: z = +/- 0.5.
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  const std::vector<double> fzz = sampleField(sphere, [](const Vector3& p) { return p.z() * p.z(); });
  const std::vector<Isoline> loops = extractIsolines(sphere, fzz, 0.25);
  ASSERT_EQ(loops.size(), 2u);
  for (const Isoline& loop : loops)
  {
    EXPECT_TRUE(loop.closed);
    expectWellFormed(sphere, loop, "sphere");
    EXPECT_NEAR(std::abs(loop.points[0].z()), 0.5, 0.01);
    EXPECT_NEAR(loop.length, 2.0 * Pi * std::sqrt(0.75), 0.02 * 2.0 * Pi * std::sqrt(0.75));
  }
  consistentSide(sphere, fzz, loops, "sphere");
}

TEST(Isolines, RefusesFieldOfWrongSize)
{
  const TriangleMesh grid = makeGrid(1.0, 1.0, 3, 3);
  EXPECT_THROW(extractIsolines(grid, std::vector<double>(5, 0.0), 0.5), Error);
}

// ---------------------------------------------------------------------------------------------
// Scores (ROI Scissor, section 4.2).

TEST(Isolines, ScoreOfLinearFieldIsItsSlope)
{
  const double height = 1.5;
  const TriangleMesh grid = makeGrid(2.0, height, 14, 9);
  const std::vector<double> field = sampleField(grid, [](const Vector3& p) { return 2.5 * p.x() - 1.0; });
  const std::vector<double> magnitudes = gradientMagnitudes(grid, field);
  const std::vector<IsovalueScore> scores = scoreIsovalues(grid, field, magnitudes, 9);
  ASSERT_EQ(scores.size(), 9u);
  for (std::size_t i = 0; i < scores.size(); ++i)
  {
    EXPECT_NEAR(scores[i].value, -1.0 + (i + 1) * 5.0 / 10.0, 1e-12);
    EXPECT_NEAR(scores[i].score, 2.5, 1e-12);
    EXPECT_NEAR(scores[i].length, height, 1e-12);
    EXPECT_NEAR(isolineScore(extractIsolines(grid, field, scores[i].value), magnitudes), 2.5, 1e-12);
  }
  EXPECT_EQ(isolineScore({}, magnitudes), 0.0);
}

TEST(Isolines, ScoresAgreeWithExtractedIsolines)
{
  // A harmonic field on a torus between two vertices: several loops per value, varying scores.
  const TriangleMesh torus = makeTorus(2.0, 0.7, 48, 20);
  LaplacianWeightOptions options;
  options.weighting = LaplacianWeighting::SmoothConcavity;
  const std::vector<double> weights = computeLaplacianWeights(torus, options);
  FieldConstraints constraints;
  constraints.dirichletVertices = { 0, 24 * 20 + 10, 12 * 20 + 5 };
  constraints.dirichletValues = { -1.0, 3.0, 0.5 };
  HarmonicFieldSolver solver;
  const std::vector<double> field = solver.solve(torus, weights, constraints).field;
  const std::vector<double> magnitudes = gradientMagnitudes(torus, field);
  const double lo = *std::min_element(field.begin(), field.end());
  const double hi = *std::max_element(field.begin(), field.end());
  ASSERT_EQ(lo, -1.0);
  ASSERT_EQ(hi, 3.0);

  const int count = 37;
  const std::vector<IsovalueScore> scores = scoreIsovalues(torus, field, magnitudes, count);
  ASSERT_EQ(static_cast<int>(scores.size()), count);
  double lowest = std::numeric_limits<double>::infinity(), highest = 0.0;
  std::size_t mostComponents = 0;
  for (int i = 1; i <= count; ++i)
  {
    const IsovalueScore& s = scores[i - 1];
    EXPECT_NEAR(s.value, lo + i * (hi - lo) / (count + 1), 1e-12) << "i " << i;
    const std::vector<Isoline> lines = extractIsolines(torus, field, s.value);
    double length = 0.0;
    for (const Isoline& line : lines)
    {
      length += line.length;
    }
    EXPECT_NEAR(s.score, isolineScore(lines, magnitudes), 1e-12) << "value " << s.value;
    EXPECT_NEAR(s.length, length, 1e-12 * std::max(1.0, length)) << "value " << s.value;
    EXPECT_GT(s.score, 0.0);
    lowest = std::min(lowest, s.score);
    highest = std::max(highest, s.score);
    mostComponents = std::max(mostComponents, lines.size());
  }
  EXPECT_GE(mostComponents, 2u);
  EXPECT_GT(highest, 1.5 * lowest);
}

TEST(Isolines, ScoresAgreeOnSphereWithVertexValues)
{
  // A polynomial field on a sphere, and isovalues that hit vertex values exactly.
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  std::vector<double> field =
    sampleField(sphere, [](const Vector3& p) { return p.x() + 0.3 * p.y() * p.y() - p.z() * p.z() * p.z(); });
  // Quantize the field to half steps, so that many vertices (and flat faces) sit exactly on the
  // sampled values.
  const double lo0 = *std::min_element(field.begin(), field.end());
  const double hi0 = *std::max_element(field.begin(), field.end());
  const int count = 19;
  const std::vector<IsovalueScore> probe = scoreIsovalues(sphere, field, gradientMagnitudes(sphere, field), count);
  ASSERT_EQ(static_cast<int>(probe.size()), count);
  EXPECT_NEAR(probe[0].value, lo0 + (hi0 - lo0) / (count + 1), 1e-12);
  const double step = (hi0 - lo0) / (count + 1);
  auto sampled = [&](int k) { return k == 0 ? lo0 : (k == count + 1 ? hi0 : probe[k - 1].value); };
  for (double& f : field)
  {
    const int halfSteps = static_cast<int>(std::lround((f - lo0) / step * 2.0));
    f = halfSteps % 2 == 0 ? sampled(halfSteps / 2) : 0.5 * (sampled(halfSteps / 2) + sampled(halfSteps / 2 + 1));
  }
  const std::vector<double> magnitudes = gradientMagnitudes(sphere, field);
  const std::vector<IsovalueScore> scores = scoreIsovalues(sphere, field, magnitudes, count);
  ASSERT_EQ(static_cast<int>(scores.size()), count);
  const double lo = *std::min_element(field.begin(), field.end());
  const double hi = *std::max_element(field.begin(), field.end());
  int exactHits = 0;
  for (int i = 1; i <= count; ++i)
  {
    const IsovalueScore& s = scores[i - 1];
    EXPECT_NEAR(s.value, lo + i * (hi - lo) / (count + 1), 1e-12);
    exactHits += std::count(field.begin(), field.end(), s.value) > 0 ? 1 : 0;
    const std::vector<Isoline> lines = extractIsolines(sphere, field, s.value);
    double length = 0.0;
    for (const Isoline& line : lines)
    {
      length += line.length;
    }
    EXPECT_NEAR(s.score, isolineScore(lines, magnitudes), 1e-12) << "value " << s.value;
    EXPECT_NEAR(s.length, length, 1e-12 * std::max(1.0, length)) << "value " << s.value;
  }
  EXPECT_GT(exactHits, 0);
}

TEST(Isolines, NoScoresForConstantFieldOrNoCount)
{
  const TriangleMesh grid = makeGrid(1.0, 1.0, 4, 4);
  const std::vector<double> constant(grid.vertexCount(), 2.0);
  EXPECT_TRUE(scoreIsovalues(grid, constant, gradientMagnitudes(grid, constant), 10).empty());
  const std::vector<double> field = sampleField(grid, [](const Vector3& p) { return p.y(); });
  EXPECT_TRUE(scoreIsovalues(grid, field, gradientMagnitudes(grid, field), 0).empty());
}

// ---------------------------------------------------------------------------------------------
// Choosing a component and labelling the two sides of a cut.

TEST(Isolines, GridCutGivesTwoSides)
{
  const int columns = 10, rows = 8;
  const TriangleMesh grid = makeGrid(1.0, 1.0, columns, rows);
  const std::vector<double> field = sampleField(grid, [](const Vector3& p) { return p.x(); });
  for (double value : { 0.45, 0.5, 0.83 })
  {
    const std::string what = "value " + std::to_string(value);
    const std::vector<Isoline> lines = extractIsolines(grid, field, value);
    ASSERT_EQ(lines.size(), 1u) << what;
    const std::vector<int> labels = labelCutSides(grid, field, value, { &lines[0] });
    ASSERT_EQ(static_cast<int>(labels.size()), grid.faceCount());
    EXPECT_EQ(labelCount(labels), 2) << what;
    expectLabelsInFaceOrder(labels);
    for (int f = 0; f < grid.faceCount(); ++f)
    {
      // Crossed faces go with the side of their mean value.
      const Triangle& t = grid.triangle(f);
      const double mean = (field[t[0]] + field[t[1]] + field[t[2]]) / 3.0;
      EXPECT_EQ(labels[f], mean >= value ? 1 : 0) << what << ", face " << f;
    }
    // Without a cut, everything is one piece.
    EXPECT_EQ(labelCount(labelCutSides(grid, field, value, {})), 1) << what;
  }
}

TEST(Isolines, SphereCutAlongOneOrBothLoops)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  const std::vector<double> field = sampleField(sphere, [](const Vector3& p) { return p.z() * p.z(); });
  const std::vector<Isoline> loops = extractIsolines(sphere, field, 0.25);
  ASSERT_EQ(loops.size(), 2u);

  // The loop nearest to points by the northern circle, and the one by the southern circle.
  std::vector<Vector3> north, south;
  for (int i = 0; i < 5; ++i)
  {
    const double angle = 0.4 * i;
    north.emplace_back(0.9 * std::cos(angle), 0.9 * std::sin(angle), 0.55);
    south.emplace_back(0.8 * std::cos(angle), 0.8 * std::sin(angle), -0.4);
  }
  const int northIndex = nearestIsoline(loops, north);
  const int southIndex = nearestIsoline(loops, south);
  ASSERT_GE(northIndex, 0);
  ASSERT_GE(southIndex, 0);
  EXPECT_NE(northIndex, southIndex);
  EXPECT_GT(zRange(loops[northIndex]).first, 0.45);
  EXPECT_LT(zRange(loops[southIndex]).second, -0.45);
  EXPECT_EQ(nearestIsoline({}, north), -1);
  // A single point just outside one loop.
  EXPECT_EQ(nearestIsoline(loops, { Vector3(0.0, 0.87, -0.52) }), southIndex);

  // Faces well inside the caps and the band.
  auto region = [&](int f) {
    const double z = centroid(sphere, f).z();
    return z > 0.6 ? 0 : (z < -0.6 ? 1 : (std::abs(z) < 0.4 ? 2 : -1));
  };
  const std::vector<int> one = labelCutSides(sphere, field, 0.25, { &loops[northIndex] });
  EXPECT_EQ(labelCount(one), 2);
  expectLabelsInFaceOrder(one);
  const std::vector<int> both = labelCutSides(sphere, field, 0.25, { &loops[0], &loops[1] });
  EXPECT_EQ(labelCount(both), 3);
  expectLabelsInFaceOrder(both);
  int regionLabelOne[3] = { -1, -1, -1 }, regionLabelBoth[3] = { -1, -1, -1 };
  for (int f = 0; f < sphere.faceCount(); ++f)
  {
    const int r = region(f);
    if (r < 0)
    {
      continue;
    }
    if (regionLabelOne[r] < 0)
    {
      regionLabelOne[r] = one[f];
      regionLabelBoth[r] = both[f];
    }
    EXPECT_EQ(one[f], regionLabelOne[r]) << "face " << f;
    EXPECT_EQ(both[f], regionLabelBoth[r]) << "face " << f;
  }
  // Cutting the northern loop only: the northern cap alone, the band joined to the southern cap.
  EXPECT_NE(regionLabelOne[0], regionLabelOne[2]);
  EXPECT_EQ(regionLabelOne[1], regionLabelOne[2]);
  EXPECT_NE(regionLabelBoth[0], regionLabelBoth[1]);
  EXPECT_NE(regionLabelBoth[0], regionLabelBoth[2]);
  EXPECT_NE(regionLabelBoth[1], regionLabelBoth[2]);
}

// Cuts from several strokes (labelStrokeCuts): the segments the strokes intend, with
// T-junctions. A sphere in three sectors (orange slices): three boundaries from pole to pole,
// meeting three at a time at both poles. One stroke along each boundary.
namespace kerf
{
namespace
{
struct StrokedSectors
{
  TriangleMesh mesh;
  std::vector<int> truth;
  std::vector<std::vector<double>> fields;
  std::vector<std::vector<Isoline>> isolines;
  std::vector<CutWithStroke> cuts;
};

// The mesh labelled by `label` of each face's centre, one stroke along each boundary chain (as the
// benchmark's simulated user draws them), and each stroke's cut.
StrokedSectors strokedSegments(TriangleMesh mesh, const std::function<int(const Vector3&)>& label)
{
  StrokedSectors s;
  s.mesh = std::move(mesh);
  for (int f = 0; f < s.mesh.faceCount(); ++f)
  {
    const Triangle& t = s.mesh.triangle(f);
    s.truth.push_back(label((s.mesh.point(t[0]) + s.mesh.point(t[1]) + s.mesh.point(t[2])) / 3.0));
  }
  auto surface = std::make_shared<const Surface>(s.mesh);
  HarmonicCutSession session(surface);
  StrokeOptions strokeOptions;
  strokeOptions.offset = 0.01 * s.mesh.boundingBoxDiagonal();
  const std::vector<BoundaryStroke> strokes = boundaryStrokes(s.mesh, s.truth, 0.03 * s.mesh.boundingBoxDiagonal());
  s.fields.reserve(strokes.size());
  s.isolines.reserve(strokes.size());
  for (const BoundaryStroke& stroke : strokes)
  {
    HarmonicCutSession::StrokeCut cut = session.cutFromStroke({ stroke.points }, strokeOptions, HarmonicFieldOptions());
    EXPECT_GE(cut.chosen, 0);
    s.fields.push_back(std::move(cut.field));
    s.isolines.push_back(std::move(cut.isolines));
    CutWithStroke withStroke;
    withStroke.cut = { &s.fields.back(), 0.0, { &s.isolines.back()[static_cast<std::size_t>(cut.chosen)] } };
    withStroke.stroke = stroke.points;
    withStroke.sideFaces = cut.sideFaces;
    s.cuts.push_back(std::move(withStroke));
  }
  return s;
}

const double Pi = 3.14159265358979323846;

// A sphere in `sectors` orange slices around z.
StrokedSectors strokedSectors(int sectors)
{
  return strokedSegments(makeIcosphere(1.0, 4), [sectors](const Vector3& c) {
    return std::min(sectors - 1, static_cast<int>((std::atan2(c.y(), c.x()) + Pi) / (2.0 * Pi / sectors)));
  });
}

int segmentCount(const std::vector<int>& labels)
{
  return *std::max_element(labels.begin(), labels.end()) + 1;
}

TEST(StrokeCuts, TJunctionsGiveTheIntendedSegments)
{
  for (int sectors : { 3, 4 })
  {
    const StrokedSectors s = strokedSectors(sectors);
    ASSERT_EQ(static_cast<int>(s.cuts.size()), sectors); // one stroke per boundary
    std::vector<FieldCut> whole;
    for (const CutWithStroke& cut : s.cuts)
    {
      whole.push_back(cut.cut);
    }
    // Every isoline is a closed loop round the sphere: cutting along all of them splits each
    // sector into pieces no stroke separates.
    EXPECT_GT(segmentCount(labelCuts(s.mesh, whole)), sectors);
    const std::vector<int> labels = labelStrokeCuts(s.mesh, s.cuts, 0.03 * s.mesh.boundingBoxDiagonal());
    EXPECT_EQ(segmentCount(labels), sectors);
    const SegmentationScores scores = compareSegmentations(s.mesh, labels, s.truth);
    EXPECT_LT(scores.randIndexError, 0.01) << sectors << " sectors";
  }
}

TEST(StrokeCuts, AThreePartStarGivesItsThreeParts)
{
  // Three fingers on a sphere (at 0, 120 and 240 degrees around z), each with its third of the
  // body: three boundaries from pole to pole between the fingers, meeting three at a time at the
  // poles (T-junctions), each drawn as one open stroke.
  const StrokedSectors s = strokedSegments(makeProtrusions(3, 1.0, 0.35, 4), [](const Vector3& c) {
    const double angle = std::atan2(c.y(), c.x()) + 2.0 * Pi + Pi / 3.0;
    return static_cast<int>(angle / (2.0 * Pi / 3.0)) % 3;
  });
  ASSERT_EQ(s.cuts.size(), 3u);
  const std::vector<int> labels = labelStrokeCuts(s.mesh, s.cuts, 0.03 * s.mesh.boundingBoxDiagonal());
  EXPECT_EQ(segmentCount(labels), 3);
  const SegmentationScores scores = compareSegmentations(s.mesh, labels, s.truth);
  std::cout << "three-part star: 1 - Rand index " << scores.randIndexError << std::endl;
  EXPECT_LT(scores.randIndexError, 0.01);
}

TEST(StrokeCuts, AHandleIsCutAtBothEnds)
{
  // A handle: a quarter of a torus's ring, attached to the rest at two meridian loops. One stroke
  // along each loop; neither cut alone separates anything (the ring stays connected), the two
  // together give the handle and the rest.
  const StrokedSectors s = strokedSegments(makeTorus(1.0, 0.3, 96, 32), [](const Vector3& c) {
    const double angle = std::atan2(c.y(), c.x());
    return angle > 0.0 && angle < Pi / 2.0 ? 1 : 0;
  });
  ASSERT_EQ(s.cuts.size(), 2u);
  for (const CutWithStroke& cut : s.cuts)
  {
    EXPECT_EQ(segmentCount(labelCuts(s.mesh, { cut.cut })), 1);
  }
  const std::vector<int> labels = labelStrokeCuts(s.mesh, s.cuts, 0.03 * s.mesh.boundingBoxDiagonal());
  EXPECT_EQ(segmentCount(labels), 2);
  const SegmentationScores scores = compareSegmentations(s.mesh, labels, s.truth);
  std::cout << "handle: 1 - Rand index " << scores.randIndexError << std::endl;
  EXPECT_LT(scores.randIndexError, 0.01);
}

TEST(StrokeCuts, TheTwoSidesOfAStrokeStayApart)
{
  // Two sectors: one boundary loop in two strokes (each pole is an end of both).
  const StrokedSectors s = strokedSectors(2);
  const std::vector<int> labels = labelStrokeCuts(s.mesh, s.cuts, 0.03 * s.mesh.boundingBoxDiagonal());
  for (const CutWithStroke& cut : s.cuts)
  {
    for (std::size_t i = 0; i + 1 < cut.sideFaces.size(); i += 2)
    {
      EXPECT_NE(labels[cut.sideFaces[i]], labels[cut.sideFaces[i + 1]]);
    }
  }
  EXPECT_EQ(segmentCount(labels), 2);
}

} // namespace
} // namespace kerf
