// Multi-label random walks: linear probabilities across a grid, unseeded components, ties, the neck of a two-lobe
// shape, errors, repeatability, and walks from segment spines (never removing a segment).
#include "Error.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Mesh/MeshGenerators.h"
#include "Numerics/LaplacianWeights.h"
#include "Segmentation/RandomWalk.h"
#include "Segmentation/RegionGrowing.h"
#include "StrokeShapes.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

using namespace kerf;
using kerf::test::DumbbellWithStrokes;

namespace
{
std::vector<double> cotangentWeights(const TriangleMesh& mesh)
{
  return computeLaplacianWeights(mesh, LaplacianWeightOptions{ LaplacianWeighting::Cotangent });
}

// The grid's left column seeded with label 3 and its right column with label 7.
void seedColumns(int columns, int rows, std::vector<int>& vertices, std::vector<int>& labels)
{
  for (int j = 0; j <= rows; ++j)
  {
    vertices.push_back(j * (columns + 1));
    labels.push_back(3);
    vertices.push_back(j * (columns + 1) + columns);
    labels.push_back(7);
  }
}

// A planar strip of unit width walked from its two short sides (seedColumns), cotangent weights.
struct StripWalk
{
  TriangleMesh mesh;
  RandomWalkLabelling walks;
  StripWalk(double height, int columns, int rows)
    : mesh(makeGrid(1.0, height, columns, rows))
  {
    std::vector<int> vertices, labels;
    seedColumns(columns, rows, vertices, labels);
    this->walks = randomWalkLabels(this->mesh, cotangentWeights(this->mesh), vertices, labels);
  }
};
} // namespace

TEST(RandomWalk, ProbabilitiesAreLinearAcrossAGrid)
{
  // Seeds on the two short sides of a planar strip: the harmonic field of each label is linear in
  // x (the cotangent Laplacian is linearly precise on this grid), so a vertex's probability is
  // max(x, 1 - x) and its other label's min(x, 1 - x), the left half is 3 and the right half 7.
  const StripWalk strip(0.3, 20, 6);
  const TriangleMesh& mesh = strip.mesh;
  const RandomWalkLabelling& walks = strip.walks;
  EXPECT_EQ(walks.labels, (std::vector<int>{ 3, 7 }));
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const double x = mesh.point(v).x();
    EXPECT_NEAR(walks.vertexProbabilities[v], std::max(x, 1.0 - x), 1e-9) << "vertex " << v;
    EXPECT_NEAR(walks.secondProbabilities[v], std::min(x, 1.0 - x), 1e-9) << "vertex " << v;
    if (std::abs(x - 0.5) > 1e-9)
    {
      EXPECT_EQ(walks.vertexLabels[v], x < 0.5 ? 3 : 7) << "vertex " << v;
      EXPECT_EQ(walks.secondLabels[v], x < 0.5 ? 7 : 3) << "vertex " << v;
    }
    else
    {
      EXPECT_EQ(walks.vertexLabels[v] + walks.secondLabels[v], 10) << "vertex " << v; // 3 and 7
    }
  }
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const double x = (mesh.point(t[0]).x() + mesh.point(t[1]).x() + mesh.point(t[2]).x()) / 3.0;
    EXPECT_EQ(walks.faceLabels[f], x < 0.5 ? 3 : 7) << "face " << f;
  }
}

TEST(RandomWalk, TiesGoToTheSmallerLabel)
{
  // Two columns of cells: the middle vertex column is as far from either seed column, so each of
  // its vertices has probability 1/2 for both labels, and takes the smaller. The two labels'
  // fields, solved here as randomWalkLabels solves them, are checked equal to the last bit there,
  // so that the rule, not rounding, decides.
  const int columns = 2, rows = 1;
  const StripWalk strip(1.0, columns, rows);
  std::vector<int> vertices, labels;
  seedColumns(columns, rows, vertices, labels);
  FieldConstraints constraints;
  constraints.dirichletVertices = vertices;
  HarmonicFieldSolver solver;
  std::array<std::vector<double>, 2> fields;
  for (int side = 0; side < 2; ++side)
  {
    constraints.dirichletValues.clear();
    for (int label : labels)
    {
      constraints.dirichletValues.push_back(label == (side == 0 ? 3 : 7) ? 1.0 : 0.0);
    }
    fields[side] = solver.solve(strip.mesh, cotangentWeights(strip.mesh), constraints).field;
  }
  for (int j = 0; j <= rows; ++j)
  {
    const int middle = j * (columns + 1) + 1;
    ASSERT_EQ(fields[0][middle], fields[1][middle]) << "no exact tie at vertex " << middle;
    EXPECT_NEAR(strip.walks.vertexProbabilities[middle], 0.5, 1e-12);
    EXPECT_EQ(strip.walks.vertexLabels[middle], 3);
  }
}

TEST(RandomWalk, ComponentsWithoutSeedsAreLeftOut)
{
  // Two strips side by side, only the first seeded: the second is labelled -1 with probability 0
  // and changes nothing in the first (the same numbers as the first strip alone).
  const int columns = 10, rows = 4;
  const TriangleMesh strip = makeGrid(1.0, 0.4, columns, rows);
  std::vector<Vector3> points;
  std::vector<Triangle> triangles;
  for (int copy = 0; copy < 2; ++copy)
  {
    const int offset = static_cast<int>(points.size());
    for (int v = 0; v < strip.vertexCount(); ++v)
    {
      points.push_back(strip.point(v) + Vector3(0.0, copy * 1.0, 0.0));
    }
    for (int f = 0; f < strip.faceCount(); ++f)
    {
      const Triangle& t = strip.triangle(f);
      triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
    }
  }
  const TriangleMesh mesh(points, triangles);
  std::vector<int> vertices, labels;
  seedColumns(columns, rows, vertices, labels);
  const RandomWalkLabelling both = randomWalkLabels(mesh, cotangentWeights(mesh), vertices, labels);
  const RandomWalkLabelling alone = randomWalkLabels(strip, cotangentWeights(strip), vertices, labels);
  for (int v = 0; v < strip.vertexCount(); ++v)
  {
    EXPECT_EQ(both.vertexLabels[v], alone.vertexLabels[v]);
    EXPECT_NEAR(both.vertexProbabilities[v], alone.vertexProbabilities[v], 1e-12);
    EXPECT_EQ(both.vertexLabels[v + strip.vertexCount()], -1);
    EXPECT_EQ(both.vertexProbabilities[v + strip.vertexCount()], 0.0);
  }
  for (int f = 0; f < strip.faceCount(); ++f)
  {
    EXPECT_EQ(both.faceLabels[f], alone.faceLabels[f]);
    EXPECT_EQ(both.faceLabels[f + strip.faceCount()], -1);
  }
}

TEST(RandomWalk, ConcavityAwareWalksStopAtTheNeckWhateverTheStrokes)
{
  // One stroke on the larger lobe's far end, the other moved towards the neck: halfway between
  // them under plain lengths lies 0.3 or more inside the larger lobe, but walks rarely cross the
  // concave neck, so the boundary stays on the rings round it (with cotangent weights it lands
  // 1.6 to 2.4 from the neck). The isophotic metric's fronts pass this too; the walks' gain is
  // where no crease stops the fronts (Documentation/filters/EasyMeshCutting.md, psb-dev).
  const DumbbellWithStrokes shape(5);
  const Surface surface(shape.mesh);
  for (double above : { 0.4, 0.8 })
  {
    std::vector<LabelledStroke> strokes = shape.strokes;
    for (Vector3& p : strokes[1].points)
    {
      const double z = p.z() - 1.5 + shape.neckZ + above;
      p = Vector3(dumbbellRadius(z, DumbbellWithStrokes::HalfLength, DumbbellWithStrokes::Radii,
                    DumbbellWithStrokes::NeckHeight, DumbbellWithStrokes::Depth),
        0.0, z);
    }
    const RegionGrowingResult result = growRegions(surface, strokes, RegionGrowingOptions());
    ASSERT_EQ(result.probabilities.size(), static_cast<std::size_t>(shape.mesh.vertexCount()));
    const std::vector<LabelBoundary> boundaries = labelBoundaries(shape.mesh, result.faceLabels);
    ASSERT_EQ(boundaries.size(), 1u) << "stroke " << above << " above the neck";
    EXPECT_TRUE(boundaries[0].closed);
    double farthest = 0.0;
    for (int v : boundaries[0].vertices)
    {
      farthest = std::max(farthest, std::abs(shape.mesh.point(v).z() - shape.neckZ));
    }
    EXPECT_LT(farthest, 0.1 * DumbbellWithStrokes::Radii[0]) << "stroke " << above << " above the neck";
    // The seeds are certain; every other vertex's label has probability at least 1/2 (two labels,
    // up to rounding).
    for (int v : result.seeds.vertices)
    {
      EXPECT_EQ(result.probabilities[v], 1.0);
    }
    EXPECT_GE(*std::min_element(result.probabilities.begin(), result.probabilities.end()), 0.5 - 1e-12);
  }
}

TEST(RandomWalk, SameLabelsRunAfterRun)
{
  const DumbbellWithStrokes shape(4);
  const Surface first(shape.mesh), second(shape.mesh);
  const RegionGrowingResult a = growRegions(first, shape.strokes, RegionGrowingOptions());
  const RegionGrowingResult b = growRegions(second, shape.strokes, RegionGrowingOptions());
  EXPECT_EQ(a.faceLabels, b.faceLabels);
  EXPECT_EQ(a.vertexLabels, b.vertexLabels);
  EXPECT_EQ(a.probabilities, b.probabilities); // bit for bit
}

TEST(RandomWalk, BadSeedsAndWeightsAreRefused)
{
  const TriangleMesh mesh = makeGrid(1.0, 1.0, 3, 3);
  const std::vector<double> weights = cotangentWeights(mesh);
  EXPECT_THROW(randomWalkLabels(mesh, weights, {}, {}), Error);
  EXPECT_THROW(randomWalkLabels(mesh, weights, { 0, 1 }, { 0 }), Error);
  EXPECT_THROW(randomWalkLabels(mesh, weights, { 0, 99 }, { 0, 1 }), Error);
  EXPECT_THROW(randomWalkLabels(mesh, weights, { 0, -1 }, { 0, 1 }), Error);
  EXPECT_THROW(randomWalkLabels(mesh, weights, { 0, 3 }, { 0, -2 }), Error);
  EXPECT_THROW(randomWalkLabels(mesh, weights, { 0, 0 }, { 0, 1 }), Error);
  EXPECT_THROW(randomWalkLabels(mesh, std::vector<double>(3, 1.0), { 0, 3 }, { 0, 1 }), Error);
  for (double bad : { -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    std::vector<double> badWeights = weights;
    badWeights[5] = bad;
    EXPECT_THROW(randomWalkLabels(mesh, badWeights, { 0, 3 }, { 0, 1 }), Error) << bad;
  }
  // A seed repeated with its own label is accepted; one label labels its whole component.
  const RandomWalkLabelling one = randomWalkLabels(mesh, weights, { 0, 0 }, { 4, 4 });
  EXPECT_EQ(one.vertexLabels, std::vector<int>(mesh.vertexCount(), 4));
}

TEST(RandomWalk, PlacementNamesRoundTrip)
{
  for (BoundaryPlacement placement :
    { BoundaryPlacement::Fronts, BoundaryPlacement::MinimumCut, BoundaryPlacement::RandomWalks })
  {
    EXPECT_EQ(parseBoundaryPlacement(boundaryPlacementName(placement)), placement);
  }
  EXPECT_THROW(parseBoundaryPlacement("halfway"), Error);
  EXPECT_EQ(RegionGrowingOptions().placement, BoundaryPlacement::RandomWalks);
  const DumbbellWithStrokes shape(3);
  const Surface surface(shape.mesh);
  RegionGrowingOptions unknown;
  unknown.placement = static_cast<BoundaryPlacement>(7);
  EXPECT_THROW(growRegions(surface, shape.strokes, unknown), Error);
  EXPECT_THROW(boundaryPlacementName(unknown.placement), Error);
}

namespace
{
double centroidX(const TriangleMesh& mesh, int f)
{
  const Triangle& t = mesh.triangle(f);
  return (mesh.point(t[0]).x() + mesh.point(t[1]).x() + mesh.point(t[2]).x()) / 3.0;
}

// The faces of `mesh` that pass the test.
template <typename Test>
std::vector<int> facesWhere(const TriangleMesh& mesh, Test test)
{
  std::vector<int> faces;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    if (test(f))
    {
      faces.push_back(f);
    }
  }
  return faces;
}
} // namespace

TEST(RandomWalk, SpinesOnAStripsSidesCutItHalfway)
{
  // A unit strip of 20 x 10 cells cut at x = 0.3; each segment's spine is its outer column of
  // faces, so its seeds are the vertex columns x = 0 and 0.05 (label 0) and 0.95 and 1 (label 1).
  // The fields are linear between them: p_0 = 1/2 on x = 1/2, every face left of it goes to 0 and
  // every face right of it to 1, and the 4 columns of 20 faces between 0.3 and 0.5 change.
  const TriangleMesh mesh = makeGrid(1.0, 0.5, 20, 10);
  const std::vector<double> weights = cotangentWeights(mesh);
  std::vector<int> labels(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    labels[f] = centroidX(mesh, f) < 0.3 ? 0 : 1;
  }
  const std::vector<SegmentSpine> spines = {
    { 0, facesWhere(mesh, [&](int f) { return centroidX(mesh, f) < 0.05; }) },
    { 1, facesWhere(mesh, [&](int f) { return centroidX(mesh, f) > 0.95; }) },
  };
  ASSERT_EQ(spines[0].faces.size(), 20u);
  const SpineWalk walk = walkFromSpines(mesh, weights, spines, labels);
  EXPECT_TRUE(walk.applied);
  EXPECT_EQ(walk.changedFaces, 80);
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    EXPECT_EQ(walk.faceLabels[f], centroidX(mesh, f) < 0.5 ? 0 : 1) << "face " << f;
  }
  // The input is left as it was, and the same call gives the same labels.
  EXPECT_EQ(walkFromSpines(mesh, weights, spines, labels).faceLabels, walk.faceLabels);
}

TEST(RandomWalk, SpinesNeverRemoveASegment)
{
  // Segment 1 is one face F of a 20 x 10 grid, its spine F itself; segment 0 is every other face.
  const TriangleMesh mesh = makeGrid(1.0, 0.5, 20, 10);
  const std::vector<double> weights = cotangentWeights(mesh);
  const int F = facesWhere(mesh, [&](int f) {
    const Triangle& t = mesh.triangle(f);
    const Vector3 c = (mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0;
    return std::abs(c.x() - 0.5) < 0.025 && std::abs(c.y() - 0.25) < 0.025;
  }).front();
  std::vector<int> labels(mesh.faceCount(), 0);
  labels[F] = 1;
  const int c = mesh.triangle(F)[0]; // the corner left to segment 1
  auto contains = [&](int f, int v) {
    const Triangle& t = mesh.triangle(f);
    return t[0] == v || t[1] == v || t[2] == v;
  };

  // Segment 0's spine through every other face but those around c: F's two other corners are
  // shared and seed neither, c is segment 1's only seed, and every vertex else seeds 0. A walk
  // from c reaches a seed of 0 at its first step, so c's faces sum more for 0 (each free corner
  // is 0's with probability 1 - w_ac / sum_a w): segment 1 would win no face, and the input stands.
  const std::vector<int> notAroundC = facesWhere(mesh, [&](int f) { return f != F && !contains(f, c); });
  const std::vector<SegmentSpine> starved = { { 0, notAroundC }, { 1, { F } } };
  const SpineWalk kept = walkFromSpines(mesh, weights, starved, labels);
  EXPECT_FALSE(kept.applied);
  EXPECT_EQ(kept.changedFaces, 0);
  EXPECT_EQ(kept.faceLabels, labels);
  // The walk the fallback refused: the same seeds, drawn by hand, give segment 1 no face.
  std::vector<int> seedVertices, seedLabels;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const Triangle& t = mesh.triangle(F);
    if (v == c || (v != t[1] && v != t[2]))
    {
      seedVertices.push_back(v);
      seedLabels.push_back(v == c ? 1 : 0);
    }
  }
  const std::vector<int> refused = randomWalkLabels(mesh, weights, seedVertices, seedLabels).faceLabels;
  EXPECT_EQ(std::count(refused.begin(), refused.end(), 1), 0);

  // Segment 0's spine through every other face: all three corners of F are shared, segment 1 has
  // no seed, and the input stands.
  const std::vector<SegmentSpine> unseeded = { { 0, facesWhere(mesh, [&](int f) { return f != F; }) }, { 1, { F } } };
  const SpineWalk unchanged = walkFromSpines(mesh, weights, unseeded, labels);
  EXPECT_FALSE(unchanged.applied);
  EXPECT_EQ(unchanged.faceLabels, labels);

  // Segment 0's spine along the grid's left column: F's corners seed 1 and F keeps its label.
  const std::vector<SegmentSpine> apart = { { 0, facesWhere(mesh, [&](int f) { return centroidX(mesh, f) < 0.05; }) },
    { 1, { F } } };
  const SpineWalk walked = walkFromSpines(mesh, weights, apart, labels);
  EXPECT_TRUE(walked.applied);
  EXPECT_EQ(walked.faceLabels[F], 1);
  EXPECT_GT(std::count(walked.faceLabels.begin(), walked.faceLabels.end(), 1), 1);

  // A segment without a spine (here segment 1), or no spine at all, leaves the input as it was.
  const SpineWalk oneSpine = walkFromSpines(mesh, weights, { apart[0] }, labels);
  EXPECT_FALSE(oneSpine.applied);
  EXPECT_EQ(oneSpine.faceLabels, labels);
  EXPECT_FALSE(walkFromSpines(mesh, weights, {}, labels).applied);
  EXPECT_FALSE(walkFromSpines(mesh, weights, {}, std::vector<int>(mesh.faceCount(), -1)).applied);

  // A spine through another segment's face, a negative label, or labels of another mesh, are refused.
  EXPECT_THROW(walkFromSpines(mesh, weights, { { -1, {} }, apart[0], apart[1] }, labels), Error);
  EXPECT_THROW(walkFromSpines(mesh, weights, { { 1, { F, notAroundC.front() } } }, labels), Error);
  EXPECT_THROW(walkFromSpines(mesh, weights, { { 0, { mesh.faceCount() } } }, labels), Error);
  EXPECT_THROW(walkFromSpines(mesh, weights, apart, std::vector<int>(3, 0)), Error);
}
