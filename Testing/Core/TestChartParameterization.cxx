// parameterizeCharts: developable charts unroll without distortion, hemispheres without flips, packing, charts cut into
// disks (cutToDisk), LinABF against LSCM, and the errors.
#include "Error.h"
#include "Mesh/MeshGenerators.h"
#include "Parameterization/ChartParameterization.h"
#include "Parameterization/CutToDisk.h"
#include "Parameterization/LinearABF.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace kerf
{
namespace
{

std::vector<int> oneLabel(const TriangleMesh& mesh, int label = 0)
{
  return std::vector<int>(static_cast<std::size_t>(mesh.faceCount()), label);
}

void expectInsideSquare(const ChartParameterizationResult& result, double margin)
{
  for (const Vector2& p : result.uv)
  {
    EXPECT_GE(p.minCoeff(), margin - 1e-12);
    EXPECT_LE(p.maxCoeff(), 1.0 - margin + 1e-12);
  }
}

void expectIsometric(const ChartParameterizationResult& result)
{
  EXPECT_EQ(result.distortion.flippedFaces, 0);
  for (const FaceDistortion& face : result.faces)
  {
    EXPECT_NEAR(face.stretch, 1.0, 1e-6);
    EXPECT_NEAR(face.shear, 1.0, 1e-6);
    EXPECT_FALSE(face.flipped);
  }
  EXPECT_NEAR(result.distortion.meanStretch, 1.0, 1e-6);
  EXPECT_NEAR(result.distortion.surfaceStretch, 1.0, 1e-6);
  EXPECT_NEAR(result.distortion.maxShear, 1.0, 1e-6);
}

TEST(ChartParameterization, SlitCylinderUnrollsWithoutDistortion)
{
  const TriangleMesh cylinder = makeSlitCylinder(1.0, 2.0, 48, 12);
  ASSERT_EQ(cylinder.boundaryLoops().size(), 1u);
  const ChartParameterizationResult result = parameterizeCharts(cylinder, oneLabel(cylinder));
  expectIsometric(result);
  expectInsideSquare(result, 0.01);
  // The unrolled rectangle (2 pi x 2) turned to lie flat, scaled to fit the square with its margins.
  EXPECT_NEAR(result.texelScale, (1.0 - 2 * 0.01) / (2.0 * M_PI), 0.01 * result.texelScale);
}

TEST(ChartParameterization, ConeSectorUnrollsWithoutDistortion)
{
  const TriangleMesh cone = makeConeSector(0.5, 0.4, 1.6, 1.5 * M_PI, 10, 40);
  const ChartParameterizationResult result = parameterizeCharts(cone, oneLabel(cone, 3));
  expectIsometric(result);
  ASSERT_EQ(result.charts.size(), 1u);
  EXPECT_EQ(result.charts[0].label, 3);
  EXPECT_EQ(result.overlappingChartPairs, 0);
}

TEST(ChartParameterization, HemispheresHaveNoFlipsAndBoundedStretch)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  std::vector<int> labels;
  for (const Triangle& t : sphere.triangles())
  {
    labels.push_back((sphere.point(t[0]) + sphere.point(t[1]) + sphere.point(t[2])).z() > 0.0 ? 1 : 0);
  }
  const ChartParameterizationResult result = parameterizeCharts(sphere, labels);
  ASSERT_EQ(result.charts.size(), 2u);
  EXPECT_EQ(result.distortion.flippedFaces, 0);
  // Measured (icosphere of 5120 triangles): mean stretch 0.980, L2 stretch 1.081, maximum
  // stretch 1.546, mean shear 1.025, maximum shear 1.072. A conformal map keeps shear near 1 and
  // puts a hemisphere's distortion into scale, which the L2 stretch sees and the mean hides.
  EXPECT_GT(result.distortion.meanStretch, 0.95);
  EXPECT_LT(result.distortion.meanStretch, 1.0);
  EXPECT_GT(result.distortion.surfaceStretch, 1.05);
  EXPECT_LT(result.distortion.surfaceStretch, 1.10);
  EXPECT_LT(result.distortion.maxStretch, 1.60);
  EXPECT_LT(result.distortion.meanShear, 1.03);
  EXPECT_LT(result.distortion.maxShear, 1.10);
  EXPECT_EQ(result.overlappingChartPairs, 0);
}

TEST(ChartParameterization, OctantsArePackedInsideTheSquareWithoutOverlap)
{
  const TriangleMesh sphere = makeIcosphere(2.0, 3);
  for (double margin : { 0.0, 0.01, 0.05 })
  {
    ChartParameterizationOptions options;
    options.margin = margin;
    const ChartParameterizationResult result = parameterizeCharts(sphere, octantLabels(sphere), options);
    ASSERT_EQ(result.charts.size(), 8u);
    expectInsideSquare(result, margin);
    EXPECT_EQ(result.overlappingChartPairs, 0);
    EXPECT_EQ(result.distortion.flippedFaces, 0);
    // Equal texel density: every chart's texture area is its 3D area times texelScale^2.
    for (std::size_t c = 0; c < result.charts.size(); ++c)
    {
      double area3D = 0.0, areaUV = 0.0;
      for (int f = 0; f < result.split.mesh.faceCount(); ++f)
      {
        if (result.split.faceLabel[static_cast<std::size_t>(f)] != result.charts[c].label)
        {
          continue;
        }
        const Triangle& t = result.split.mesh.triangle(f);
        const TriangleMesh& m = result.split.mesh;
        area3D += 0.5 * (m.point(t[1]) - m.point(t[0])).cross(m.point(t[2]) - m.point(t[0])).norm();
        const Vector2 a = result.uv[static_cast<std::size_t>(t[1])] - result.uv[static_cast<std::size_t>(t[0])];
        const Vector2 b = result.uv[static_cast<std::size_t>(t[2])] - result.uv[static_cast<std::size_t>(t[0])];
        areaUV += 0.5 * (a.x() * b.y() - a.y() * b.x());
      }
      EXPECT_NEAR(areaUV, area3D * result.texelScale * result.texelScale, 1e-9 * area3D);
    }
  }
}

TEST(ChartParameterization, IsDeterministicAndSolversAgree)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  const std::vector<int> labels = octantLabels(sphere);
  const ChartParameterizationResult first = parameterizeCharts(sphere, labels);
  const ChartParameterizationResult second = parameterizeCharts(sphere, labels);
  for (ChartSolver solver : { ChartSolver::ComplexLDLT, ChartSolver::RealCHOLMOD, ChartSolver::RealLDLT })
  {
    ChartParameterizationOptions other;
    other.solver = solver;
    const ChartParameterizationResult third = parameterizeCharts(sphere, labels, other);
    ASSERT_EQ(first.uv.size(), second.uv.size());
    for (std::size_t v = 0; v < first.uv.size(); ++v)
    {
      EXPECT_EQ(first.uv[v], second.uv[v]);
    }
    // The other solver's rounding may turn a chart to another of its near-equal minimal boxes, so
    // the maps are compared by their distortion.
    for (std::size_t f = 0; f < first.faces.size(); ++f)
    {
      EXPECT_NEAR(first.faces[f].stretch, third.faces[f].stretch, 1e-9);
      EXPECT_NEAR(first.faces[f].shear, third.faces[f].shear, 1e-9);
    }
  }
}

// A unit grid of cells x cells squares, bent (z = 0.3 sin 3x cos 2y) and moved by `offset` along x.
std::pair<std::vector<Vector3>, std::vector<Triangle>> bentGrid(int cells, double offset)
{
  const TriangleMesh grid = makeGrid(1.0, 1.0, cells, cells);
  std::vector<Vector3> points = grid.points();
  for (Vector3& p : points)
  {
    p = Vector3(p.x() + offset, p.y(), 0.3 * std::sin(3.0 * p.x()) * std::cos(2.0 * p.y()));
  }
  return { points, grid.triangles() };
}

// The charts of one call are factored one after another into one kept buffer when CHOLMOD makes
// supernodal factors, as it does for both charts here (81 x 81 and 71 x 71 vertices; at 61 x 61
// it chooses a simplicial factor): the larger chart first leaves its values in the buffer the
// smaller one is factored into. With the labels swapped the smaller chart is factored first, into
// fresh memory; the atlas must be the same bit for bit.
TEST(ChartParameterization, ChartsFactoredIntoKeptMemoryMatchChartsFactoredIntoFreshMemory)
{
  auto [points, triangles] = bentGrid(80, 0.0);
  const auto [smallPoints, smallTriangles] = bentGrid(70, 2.0);
  const int offset = static_cast<int>(points.size());
  const int largeFaces = static_cast<int>(triangles.size());
  points.insert(points.end(), smallPoints.begin(), smallPoints.end());
  for (Triangle t : smallTriangles)
  {
    triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  const TriangleMesh mesh(points, triangles);
  std::vector<int> largeFirst(triangles.size(), 0);
  std::fill(largeFirst.begin() + largeFaces, largeFirst.end(), 1);
  std::vector<int> smallFirst(triangles.size(), 1);
  std::fill(smallFirst.begin() + largeFaces, smallFirst.end(), 0);
  const ChartParameterizationResult kept = parameterizeCharts(mesh, largeFirst);
  const ChartParameterizationResult fresh = parameterizeCharts(mesh, smallFirst);
  ASSERT_EQ(kept.charts.size(), 2u);
  EXPECT_EQ(kept.charts[0].vertexCount, 81 * 81);
  EXPECT_EQ(fresh.charts[0].vertexCount, 71 * 71);
  EXPECT_EQ(kept.distortion.flippedFaces, 0);
  ASSERT_EQ(kept.uv.size(), fresh.uv.size());
  for (std::size_t v = 0; v < kept.uv.size(); ++v)
  {
    ASSERT_EQ(kept.split.originalPoint[v], fresh.split.originalPoint[v]);
    EXPECT_EQ(kept.uv[v], fresh.uv[v]) << "vertex " << v;
  }
}

// On a chart whose factor CHOLMOD makes supernodal (81 x 81 vertices, see above), the solve runs
// Kerf's complex one-column kernels: the map matches Eigen's SimplicialLDLT's to rounding, as
// amplified by the system's condition, and is the same bit for bit on every call.
TEST(ChartParameterization, SupernodalSolvesMatchTheSimplicialSolver)
{
  const auto [points, triangles] = bentGrid(80, 0.0);
  const TriangleMesh chart(points, triangles);
  const std::vector<Vector2> kerf = leastSquaresConformalMap(chart, ChartSolver::ComplexCHOLMOD);
  const std::vector<Vector2> eigen = leastSquaresConformalMap(chart, ChartSolver::ComplexLDLT);
  const std::vector<Vector2> again = leastSquaresConformalMap(chart, ChartSolver::ComplexCHOLMOD);
  ASSERT_EQ(kerf.size(), eigen.size());
  double largest = 0.0;
  double difference = 0.0;
  for (std::size_t v = 0; v < kerf.size(); ++v)
  {
    largest = std::max(largest, eigen[v].norm());
    difference = std::max(difference, (kerf[v] - eigen[v]).norm());
    EXPECT_EQ(kerf[v], again[v]) << "vertex " << v;
  }
  EXPECT_GT(largest, 0.5);
  EXPECT_LT(difference, 1e-10 * largest);
}

TEST(ChartParameterization, FaceDistortionOfKnownMaps)
{
  const Vector3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  // (x, y) -> (2x, y): s1 = 2, s2 = 1.
  FaceDistortion d = faceDistortion(p0, p1, p2, Vector2(0, 0), Vector2(2, 0), Vector2(0, 1));
  EXPECT_NEAR(d.stretch, std::sqrt(2.5), 1e-12);
  EXPECT_NEAR(d.shear, 2.0, 1e-12);
  EXPECT_FALSE(d.flipped);
  // A mirror is flipped and otherwise undistorted.
  d = faceDistortion(p0, p1, p2, Vector2(0, 0), Vector2(0, 1), Vector2(1, 0));
  EXPECT_TRUE(d.flipped);
  EXPECT_NEAR(d.stretch, 1.0, 1e-12);
  // A triangle tilted in 3D and rotated in the plane: an isometry.
  const Vector3 q1(0.6, 0.0, 0.8), q2(0.0, 1.0, 0.0);
  const double c = std::cos(0.3), s = std::sin(0.3);
  d = faceDistortion(p0, q1, q2, Vector2(0, 0), Vector2(c, s), Vector2(-s, c));
  EXPECT_NEAR(d.stretch, 1.0, 1e-12);
  EXPECT_NEAR(d.shear, 1.0, 1e-12);
}

TEST(ChartParameterization, MinimalBoxOfATurnedRectangle)
{
  const double angle = 0.4;
  const Eigen::Rotation2Dd turn(angle);
  std::vector<Vector2> points;
  for (int i = 0; i <= 10; ++i)
  {
    for (int j = 0; j <= 3; ++j)
    {
      points.push_back(turn * Vector2(0.3 * i, 0.3 * j));
    }
  }
  EXPECT_EQ(convexHull({ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 0, 1 }, { 1, 0.5 } }).size(), 4u);
  const Eigen::Rotation2Dd back(minimalBoundingBoxRotation(points));
  Vector2 low = Vector2::Constant(1e9), high = -low;
  for (const Vector2& p : points)
  {
    low = low.cwiseMin(back * p);
    high = high.cwiseMax(back * p);
  }
  EXPECT_NEAR(high.x() - low.x(), 3.0, 1e-12);
  EXPECT_NEAR(high.y() - low.y(), 0.9, 1e-12);
}

TEST(ChartParameterization, PackedBoxesDoNotOverlap)
{
  const std::vector<Vector2> sizes = { { 3, 1 }, { 1, 1 }, { 2, 2 }, { 0.5, 0.2 }, { 1, 0.7 } };
  double scale = 0.0;
  const std::vector<Vector2> corners = packBoxes(sizes, 0.02, scale);
  for (std::size_t i = 0; i < sizes.size(); ++i)
  {
    const Vector2 high = corners[i] + sizes[i] * scale;
    EXPECT_GE(corners[i].minCoeff(), 0.02 - 1e-12);
    EXPECT_LE(high.maxCoeff(), 0.98 + 1e-12);
    for (std::size_t j = 0; j < i; ++j)
    {
      const Vector2 otherHigh = corners[j] + sizes[j] * scale;
      const bool apart = high.x() + 0.02 <= corners[j].x() + 1e-12 || otherHigh.x() + 0.02 <= corners[i].x() + 1e-12 ||
        high.y() + 0.02 <= corners[j].y() + 1e-12 || otherHigh.y() + 0.02 <= corners[i].y() + 1e-12;
      EXPECT_TRUE(apart) << i << " " << j;
    }
  }
  EXPECT_THROW(packBoxes(sizes, 0.3, scale), Error);
  EXPECT_THROW(packBoxes(sizes, std::nan(""), scale), Error);
}

std::string errorOf(const TriangleMesh& mesh, const std::vector<int>& labels, bool cutToDisks = false)
{
  try
  {
    ChartParameterizationOptions options;
    options.cutToDisks = cutToDisks;
    parameterizeCharts(mesh, labels, options);
  }
  catch (const Error& error)
  {
    return error.what();
  }
  return {};
}

TEST(ChartParameterization, RefusesChartsThatAreNotDisks)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 2);
  EXPECT_NE(
    errorOf(sphere, oneLabel(sphere, 5)).find("chart 5: it has 0 boundary loops and genus 0"), std::string::npos)
    << errorOf(sphere, oneLabel(sphere, 5));
  const TriangleMesh torus = makeTorus(1.0, 0.3, 24, 12);
  EXPECT_NE(errorOf(torus, oneLabel(torus)).find("genus 1"), std::string::npos);
  // A cylinder has two boundary loops; with a slit it is a disk.
  const TriangleMesh tube = makeCylinder(1.0, 1.0, 16, 4);
  EXPECT_NE(errorOf(tube, oneLabel(tube, 2)).find("chart 2: it has 2 boundary loops"), std::string::npos);
  // With cutToDisks (the default) the same charts are cut into disks instead.
  EXPECT_EQ(errorOf(sphere, oneLabel(sphere, 5), true), "");
  EXPECT_EQ(errorOf(torus, oneLabel(torus), true), "");
  EXPECT_EQ(errorOf(tube, oneLabel(tube, 2), true), "");
  // Every offending chart is named: the octants are fine, a closed sphere beside them is not.
  std::vector<Vector3> points = sphere.points();
  std::vector<Triangle> triangles = sphere.triangles();
  std::vector<int> labels = octantLabels(sphere);
  for (const Triangle& t : sphere.triangles())
  {
    triangles.push_back({ { t[0] + sphere.vertexCount(), t[1] + sphere.vertexCount(), t[2] + sphere.vertexCount() } });
    labels.push_back(9);
  }
  for (const Vector3& p : sphere.points())
  {
    points.push_back(p + Vector3(3, 0, 0));
  }
  const std::string message = errorOf(TriangleMesh(points, triangles), labels);
  EXPECT_NE(message.find("chart 9:"), std::string::npos) << message;
  EXPECT_EQ(message.find("chart 1:"), std::string::npos) << message;
}

// A chart cut into a disk: the cut mesh is a disk whose vertices copy the chart's, with the
// chart's triangles in order; its area is unchanged.
void expectDiskOf(const EdgeCut& cut, const TriangleMesh& chart)
{
  EXPECT_EQ(chartTopologyProblem(cut.mesh), "");
  ASSERT_EQ(cut.mesh.faceCount(), chart.faceCount());
  ASSERT_EQ(cut.originalVertex.size(), static_cast<std::size_t>(cut.mesh.vertexCount()));
  for (int f = 0; f < chart.faceCount(); ++f)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      EXPECT_EQ(cut.originalVertex[static_cast<std::size_t>(cut.mesh.triangle(f)[k])], chart.triangle(f)[k]);
    }
  }
  for (int v = 0; v < cut.mesh.vertexCount(); ++v)
  {
    EXPECT_EQ(cut.mesh.point(v), chart.point(cut.originalVertex[static_cast<std::size_t>(v)]));
  }
}

TEST(CutToDisk, ADiskIsNotCut)
{
  const TriangleMesh grid = makeGrid(1.0, 1.0, 4, 4);
  const EdgeCut cut = cutToDisk(grid);
  EXPECT_TRUE(cut.cutEdges.empty());
  EXPECT_EQ(cut.mesh.points(), grid.points());
  EXPECT_EQ(cut.mesh.triangles(), grid.triangles());
}

TEST(CutToDisk, ACylinderIsCutAlongOneShortestLine)
{
  // Radius 1, height 2, 32 around, 9 rings: the boundary circles are joined by one path of 8
  // edges; the shortest paths between the rings are the cylinder's vertical lines (length 2).
  const TriangleMesh tube = makeCylinder(1.0, 2.0, 32, 9);
  const EdgeCut cut = cutToDisk(tube);
  expectDiskOf(cut, tube);
  EXPECT_EQ(cut.cutEdges.size(), 8u);
  EXPECT_NEAR(cut.cutLength, 2.0, 1e-12);
  EXPECT_EQ(cut.mesh.vertexCount(), tube.vertexCount() + 9);
  // Unrolled, the cylinder is a rectangle: no distortion at all.
  const ChartParameterizationResult result = parameterizeCharts(tube, oneLabel(tube, 4));
  ASSERT_EQ(result.charts.size(), 1u);
  EXPECT_EQ(result.cutCharts, 1);
  EXPECT_EQ(result.charts[0].cutFrom, "2 boundary loops and genus 0");
  EXPECT_EQ(result.charts[0].cutEdgeCount, 8);
  EXPECT_NEAR(result.charts[0].cutLength, 2.0, 1e-12);
  expectIsometric(result);
  expectInsideSquare(result, 0.01);
  EXPECT_EQ(result.split.mesh.vertexCount(), tube.vertexCount() + 9);
  for (int v = 0; v < result.split.mesh.vertexCount(); ++v)
  {
    EXPECT_EQ(result.split.mesh.point(v), tube.point(result.split.originalPoint[static_cast<std::size_t>(v)]));
  }
}

TEST(CutToDisk, ATorusIsCutAlongTwoLoops)
{
  // The torus of radii 1 and 0.3: its shortest handle loops are a tube circle (2 pi 0.3 = 1.88
  // as a polygon of 12 edges: 1.86) and an inner equator (2 pi 0.7 = 4.40; 4.39 with 24 edges).
  const TriangleMesh torus = makeTorus(1.0, 0.3, 24, 12);
  const EdgeCut cut = cutToDisk(torus);
  expectDiskOf(cut, torus);
  const double tube = 12 * 2.0 * 0.3 * std::sin(M_PI / 12);
  const double inner = 24 * 2.0 * 0.7 * std::sin(M_PI / 24);
  EXPECT_GE(cut.cutLength, tube + inner - 1e-9);
  EXPECT_LE(cut.cutLength, 1.5 * (tube + inner));
  const ChartParameterizationResult result = parameterizeCharts(torus, oneLabel(torus));
  EXPECT_EQ(result.charts[0].cutFrom, "0 boundary loops and genus 1");
  EXPECT_EQ(result.overlappingChartPairs, 0);
  EXPECT_EQ(result.distortion.flippedFaces, 0);
  expectInsideSquare(result, 0.01);
}

TEST(CutToDisk, ASphereIsPeeledAlongAHalfCircle)
{
  // Vertices far apart on the unit sphere are nearly antipodal: the cut between them is about
  // half a great circle (pi), a little longer along the edges.
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  const EdgeCut cut = cutToDisk(sphere);
  expectDiskOf(cut, sphere);
  EXPECT_GE(cut.cutLength, 0.99 * M_PI);
  EXPECT_LE(cut.cutLength, 1.15 * M_PI);
  const ChartParameterizationResult result = parameterizeCharts(sphere, oneLabel(sphere, 7));
  EXPECT_EQ(result.charts[0].label, 7);
  EXPECT_EQ(result.charts[0].cutFrom, "0 boundary loops and genus 0");
  EXPECT_EQ(result.overlappingChartPairs, 0);
  expectInsideSquare(result, 0.01);
}

TEST(CutToDisk, ATorusWithTwoHolesBecomesOneDisk)
{
  // The torus without two of its quads far apart: genus 1 and 2 boundary loops.
  const TriangleMesh torus = makeTorus(1.0, 0.3, 24, 12);
  std::vector<Triangle> triangles;
  for (int f = 0; f < torus.faceCount(); ++f)
  {
    if (f / 2 != 0 && f / 2 != 12 * 12 + 6)
    {
      triangles.push_back(torus.triangle(f));
    }
  }
  const TriangleMesh holed(torus.points(), triangles);
  ASSERT_EQ(holed.boundaryLoops().size(), 2u);
  const EdgeCut cut = cutToDisk(holed);
  expectDiskOf(cut, holed);
  EXPECT_EQ(cutToDisk(holed).mesh.triangles(), cut.mesh.triangles()); // deterministic
}

TEST(CutToDisk, RefusesWhatCannotBeCut)
{
  EXPECT_THROW(cutToDisk(TriangleMesh()), Error);
  // Two separate triangles.
  const TriangleMesh two(
    { Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(5, 0, 0), Vector3(6, 0, 0), Vector3(5, 1, 0) },
    { { { 0, 1, 2 } }, { { 3, 4, 5 } } });
  EXPECT_THROW(cutToDisk(two), Error);
  // One flag per edge, or the cut is refused.
  EXPECT_THROW(splitAlongEdges(two, std::vector<char>(2, 0)), Error);
}

TEST(ChartParameterization, RefusesDegenerateAndEmptyInput)
{
  std::vector<Vector3> points = makeGrid(1.0, 1.0, 2, 2).points();
  std::vector<Triangle> triangles = makeGrid(1.0, 1.0, 2, 2).triangles();
  points[4] = 0.5 * (points[1] + points[5]); // the centre on edge 1-5: triangle (1, 5, 4) has zero area
  const TriangleMesh flat(points, triangles);
  EXPECT_NE(errorOf(flat, oneLabel(flat)).find("zero-area"), std::string::npos) << errorOf(flat, oneLabel(flat));
  EXPECT_THROW(parameterizeCharts(TriangleMesh(), {}), Error);
  const TriangleMesh grid = makeGrid(1.0, 1.0, 2, 2);
  EXPECT_THROW(parameterizeCharts(grid, { 0, 0 }), Error);
  ChartParameterizationOptions options;
  options.margin = -0.1;
  EXPECT_THROW(parameterizeCharts(grid, oneLabel(grid), options), Error);
}

ChartParameterizationOptions linearABF()
{
  ChartParameterizationOptions options;
  options.method = ChartMethod::LinABF;
  return options;
}

// The largest |alpha - beta| of LinABF's angles, and the largest gap between beta and the 3D angle.
double largestCorrection(const TriangleMesh& chart)
{
  const LinearABFAngles angles = linearAngleBasedAngles(chart);
  double largest = 0.0;
  for (std::size_t c = 0; c < angles.angles.size(); ++c)
  {
    largest = std::max(largest, std::abs(angles.angles[c] - angles.targets[c]));
  }
  return largest;
}

TEST(LinearABFCharts, DevelopableChartsNeedNoCorrectionAndUnrollWithoutDistortion)
{
  const TriangleMesh cylinder = makeSlitCylinder(1.0, 2.0, 48, 12);
  const TriangleMesh cone = makeConeSector(0.5, 0.4, 1.6, 1.5 * M_PI, 10, 40);
  for (const TriangleMesh* chart : { &cylinder, &cone })
  {
    EXPECT_LT(largestCorrection(*chart), 1e-12);
    const ChartParameterizationResult result = parameterizeCharts(*chart, oneLabel(*chart), linearABF());
    expectIsometric(result);
    expectInsideSquare(result, 0.01);
    EXPECT_EQ(result.overlappingChartPairs, 0);
  }
}

// The triangles of an icosphere of 5,120 whose centroids have z > 0 (2,528), as a chart of its own.
TriangleMesh hemisphere()
{
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  std::vector<int> index(static_cast<std::size_t>(sphere.vertexCount()), -1);
  std::vector<Vector3> points;
  std::vector<Triangle> triangles;
  for (const Triangle& t : sphere.triangles())
  {
    if ((sphere.point(t[0]) + sphere.point(t[1]) + sphere.point(t[2])).z() > 0.0)
    {
      Triangle kept;
      for (std::size_t k = 0; k < 3; ++k)
      {
        int& i = index[static_cast<std::size_t>(t[k])];
        if (i < 0)
        {
          i = static_cast<int>(points.size());
          points.push_back(sphere.point(t[k]));
        }
        kept[k] = i;
      }
      triangles.push_back(kept);
    }
  }
  return TriangleMesh(points, triangles);
}

// The angle of triangle corner k in 3D and in UV (after parameterizeCharts).
double corner3D(const TriangleMesh& mesh, const Triangle& t, int k)
{
  const Vector3 a = mesh.point(t[static_cast<std::size_t>((k + 1) % 3)]) - mesh.point(t[static_cast<std::size_t>(k)]);
  const Vector3 b = mesh.point(t[static_cast<std::size_t>((k + 2) % 3)]) - mesh.point(t[static_cast<std::size_t>(k)]);
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double cornerUV(const std::vector<Vector2>& uv, const Triangle& t, int k)
{
  const Vector2 a = uv[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])] -
    uv[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
  const Vector2 b = uv[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 2) % 3)])] -
    uv[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
  return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b));
}

// Mean |alpha_UV - alpha_3D| over the corners, and checks that the UV angles around each interior
// vertex sum to 2 pi (the map is flat and not folded there).
double meanAngleError(const ChartParameterizationResult& result)
{
  const TriangleMesh& mesh = result.split.mesh;
  std::vector<double> sum(static_cast<std::size_t>(mesh.vertexCount()), 0.0);
  double total = 0.0;
  for (const Triangle& t : mesh.triangles())
  {
    for (int k = 0; k < 3; ++k)
    {
      const double angle = cornerUV(result.uv, t, k);
      total += std::abs(angle - corner3D(mesh, t, k));
      sum[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])] += angle;
    }
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (!mesh.isBoundaryVertex(v))
    {
      EXPECT_NEAR(sum[static_cast<std::size_t>(v)], 2.0 * M_PI, 1e-9) << v;
    }
  }
  return total / (3.0 * mesh.faceCount());
}

TEST(LinearABFCharts, AnglesMeetTheTriangleAndVertexSums)
{
  const TriangleMesh chart = hemisphere();
  const LinearABFAngles angles = linearAngleBasedAngles(chart);
  ASSERT_EQ(angles.angles.size(), 3u * static_cast<std::size_t>(chart.faceCount()));
  std::vector<double> vertexSum(static_cast<std::size_t>(chart.vertexCount()), 0.0), targetSum = vertexSum;
  double wheel = 0.0;
  std::vector<double> logRatio(static_cast<std::size_t>(chart.vertexCount()), 0.0);
  for (int f = 0; f < chart.faceCount(); ++f)
  {
    const std::size_t c = 3 * static_cast<std::size_t>(f);
    EXPECT_NEAR(angles.angles[c] + angles.angles[c + 1] + angles.angles[c + 2], M_PI, 1e-12);
    for (std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t v = static_cast<std::size_t>(chart.triangle(f)[k]);
      EXPECT_GT(angles.angles[c + k], 0.0);
      vertexSum[v] += angles.angles[c + k];
      targetSum[v] += angles.targets[c + k];
      logRatio[v] +=
        std::log(std::sin(angles.angles[c + (k + 1) % 3])) - std::log(std::sin(angles.angles[c + (k + 2) % 3]));
    }
  }
  int interior = 0;
  for (int v = 0; v < chart.vertexCount(); ++v)
  {
    if (!chart.isBoundaryVertex(v))
    {
      ++interior;
      EXPECT_NEAR(vertexSum[static_cast<std::size_t>(v)], 2.0 * M_PI, 1e-12);
      EXPECT_NEAR(targetSum[static_cast<std::size_t>(v)], 2.0 * M_PI, 1e-12);
      wheel = std::max(wheel, std::abs(logRatio[static_cast<std::size_t>(v)]));
    }
  }
  EXPECT_EQ(angles.interiorVertices, interior);
  // The wheel condition holds to first order only: measured largest |sum log sin(alpha_next) -
  // sum log sin(alpha_previous)| 1.6e-4 on this hemisphere.
  EXPECT_GT(wheel, 0.0);
  EXPECT_LT(wheel, 5e-4);
}

TEST(LinearABFCharts, HemisphereHasLessAngleDistortionThanLSCM)
{
  const TriangleMesh chart = hemisphere();
  const ChartParameterizationResult conformal = parameterizeCharts(chart, oneLabel(chart));
  const ChartParameterizationResult angular = parameterizeCharts(chart, oneLabel(chart), linearABF());
  EXPECT_EQ(conformal.distortion.flippedFaces, 0);
  EXPECT_EQ(angular.distortion.flippedFaces, 0);
  const double conformalError = meanAngleError(conformal);
  const double angularError = meanAngleError(angular);
  // Measured (2,528 triangles): mean |alpha_UV - alpha_3D| LSCM 0.013449 rad, LinABF 0.013279;
  // mean shear 1.024999 and 1.024930; maximum shear 1.0698 and 1.0506; maximum stretch 1.533 and
  // 1.376; L2 stretch 1.0778 and 1.0769. LinABF spreads the curvature more evenly: its worst
  // triangles gain most, the means little.
  EXPECT_GT(conformalError, 0.0130);
  EXPECT_LT(conformalError, 0.0140);
  EXPECT_GT(angularError, 0.0128);
  EXPECT_LT(angularError, conformalError);
  EXPECT_LT(angular.distortion.meanShear, conformal.distortion.meanShear);
  EXPECT_LT(conformal.distortion.meanShear, 1.03);
  EXPECT_LT(angular.distortion.maxShear, 1.06);
  EXPECT_GT(conformal.distortion.maxShear, 1.06);
  EXPECT_LT(angular.distortion.maxStretch, 1.40);
  EXPECT_GT(conformal.distortion.maxStretch, 1.50);
  EXPECT_LT(angular.distortion.surfaceStretch, conformal.distortion.surfaceStretch);
}

TEST(LinearABFCharts, IsDeterministic)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  const std::vector<int> labels = octantLabels(sphere);
  const ChartParameterizationResult first = parameterizeCharts(sphere, labels, linearABF());
  const ChartParameterizationResult second = parameterizeCharts(sphere, labels, linearABF());
  ASSERT_EQ(first.uv.size(), second.uv.size());
  for (std::size_t v = 0; v < first.uv.size(); ++v)
  {
    EXPECT_EQ(first.uv[v], second.uv[v]);
  }
  EXPECT_EQ(first.distortion.flippedFaces, 0);
  EXPECT_EQ(first.overlappingChartPairs, 0);
}

TEST(LinearABFCharts, SeamsAndCutsWorkWithEitherMethod)
{
  // One closed chart with five fingers: cut into a disk, then seams where the map is worst.
  // Measured (5,120 triangles): LSCM L2 stretch 533 without seams, 3.83 after 3 seams (2
  // flipped triangles); LinABF 48.3 without, 1.180 after 4 seams (none flipped). LSCM shrinks the
  // fingers towards points, LinABF far less.
  const TriangleMesh fingers = makeProtrusions(5, 1.5, 0.25, 4);
  std::vector<double> plainStretch, seamedStretch;
  for (ChartMethod method : { ChartMethod::LSCM, ChartMethod::LinABF })
  {
    ChartParameterizationOptions options;
    options.method = method;
    const ChartParameterizationResult plain = parameterizeCharts(fingers, oneLabel(fingers), options);
    options.maximumSeams = 10;
    const ChartParameterizationResult seamed = parameterizeCharts(fingers, oneLabel(fingers), options);
    ASSERT_EQ(seamed.charts.size(), 1u);
    EXPECT_EQ(seamed.cutCharts, 1);
    EXPECT_GE(seamed.charts[0].seams, 1);
    EXPECT_LT(seamed.distortion.surfaceStretch, plain.distortion.surfaceStretch);
    EXPECT_EQ(seamed.overlappingChartPairs, 0);
    plainStretch.push_back(plain.distortion.surfaceStretch);
    seamedStretch.push_back(seamed.distortion.surfaceStretch);
    if (method == ChartMethod::LinABF)
    {
      EXPECT_EQ(seamed.distortion.flippedFaces, 0);
      EXPECT_LT(seamed.distortion.surfaceStretch, 1.2);
    }
  }
  EXPECT_LT(plainStretch[1], 0.2 * plainStretch[0]);
  EXPECT_LT(seamedStretch[1], seamedStretch[0]);
}

TEST(LinearABFCharts, RefusesWhatIsNotADisk)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 2);
  EXPECT_THROW(linearAngleBasedFlattening(sphere), Error);
  // Closed: the vertex sums contradict the triangle sums (2 pi V != pi F), the system is singular.
  EXPECT_THROW(linearAngleBasedAngles(sphere), Error);
  EXPECT_THROW(linearAngleBasedAngles(TriangleMesh()), Error);
  ChartParameterizationOptions options = linearABF();
  options.cutToDisks = false;
  EXPECT_THROW(parameterizeCharts(sphere, oneLabel(sphere), options), Error);
  // A zero-area triangle: the centre of a 2 x 2 grid moved onto an edge.
  std::vector<Vector3> points = makeGrid(1.0, 1.0, 2, 2).points();
  points[4] = 0.5 * (points[1] + points[5]);
  const TriangleMesh flat(points, makeGrid(1.0, 1.0, 2, 2).triangles());
  EXPECT_THROW(linearAngleBasedAngles(flat), Error);
  EXPECT_THROW(linearAngleBasedFlattening(flat), Error);
  EXPECT_THROW(parameterizeCharts(flat, oneLabel(flat), linearABF()), Error);
}

} // namespace
} // namespace kerf
