// Segmentation metrics against hand-computed values, invariances and the benchmark's human agreement.
#include "Error.h"
#include "Evaluation/SegmentationMetrics.h"
#include "Evaluation/SimulatedStrokes.h"
#include "Geodesic/GraphDistance.h"
#include "IO/MeshFormats.h"
#include "Mesh/MeshGenerators.h"
#include "Mesh/Triangulation.h"
#include "Segmentation/SegmentSpines.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

using namespace kerf;

namespace
{
// Labels per grid column for a grid of `columns` x 1 unit cells (two triangles per cell).
std::vector<int> byColumn(const std::vector<int>& columnLabels)
{
  std::vector<int> labels;
  for (int label : columnLabels)
  {
    labels.push_back(label);
    labels.push_back(label);
  }
  return labels;
}

void expectAllZero(const SegmentationScores& s)
{
  EXPECT_EQ(s.cutDiscrepancy, 0.0);
  EXPECT_EQ(s.hammingDistance, 0.0);
  EXPECT_EQ(s.missingRate, 0.0);
  EXPECT_EQ(s.falseAlarmRate, 0.0);
  EXPECT_EQ(s.randIndexError, 0.0);
  EXPECT_EQ(s.globalConsistencyError, 0.0);
  EXPECT_EQ(s.localConsistencyError, 0.0);
}

// Labels 0, 5 and 9 for the faces of a cylinder of height 3 below z = 1, between 1 and 2, above.
std::vector<int> threeBands(const TriangleMesh& cylinder)
{
  std::vector<int> labels(cylinder.faceCount());
  for (int f = 0; f < cylinder.faceCount(); ++f)
  {
    const Triangle& t = cylinder.triangle(f);
    const double z = (cylinder.point(t[0]) + cylinder.point(t[1]) + cylinder.point(t[2])).z() / 3.0;
    labels[f] = z < 1.0 ? 0 : (z < 2.0 ? 5 : 9);
  }
  return labels;
}
} // namespace

TEST(GraphDistance, GridDistancesAreEdgePathLengths)
{
  const TriangleMesh grid = makeGrid(4.0, 4.0, 4, 4);
  const std::vector<double> d = edgeGraphDistances(grid, { 0 });
  EXPECT_DOUBLE_EQ(d[0], 0.0);
  EXPECT_DOUBLE_EQ(d[4], 4.0);                                // along the bottom row
  EXPECT_DOUBLE_EQ(d[24], 4.0 * std::sqrt(2.0));              // along the diagonals
  EXPECT_DOUBLE_EQ(d[5 * 4 + 2], std::sqrt(2.0) * 2.0 + 2.0); // (2, 4): two diagonals, two up
  EXPECT_THROW(edgeGraphDistances(grid, { 99 }), Error);
}

TEST(GraphDistance, LoweringEqualsTheMinimumOfFullSearches)
{
  // Farthest-point sampling's update: each new source lowers the distances in place, bit for bit
  // the minimum of the old values and a full search from the new source, and visits less.
  const TriangleMesh sphere = makeIcosphere(1.0, 4);
  std::vector<double> lowered = edgeGraphDistances(sphere, { 0 });
  std::vector<double> minimum = lowered;
  for (int source : { 2000, 517, 1999, 0, 2561 })
  {
    lowerEdgeGraphDistances(sphere, source, lowered);
    const std::vector<double> full = edgeGraphDistances(sphere, { source });
    for (int v = 0; v < sphere.vertexCount(); ++v)
    {
      minimum[v] = std::min(minimum[v], full[v]);
    }
    EXPECT_EQ(lowered, minimum) << "after source " << source;
  }
  EXPECT_EQ(lowered, edgeGraphDistances(sphere, { 0, 2000, 517, 1999, 2561 }));
  EXPECT_THROW(lowerEdgeGraphDistances(sphere, -1, lowered), Error);
  std::vector<double> tooShort(3, 0.0);
  EXPECT_THROW(lowerEdgeGraphDistances(sphere, 0, tooShort), Error);
}

TEST(SegmentationMetrics, IdenticalSegmentationsScoreZero)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 3);
  std::vector<int> labels(sphere.faceCount());
  for (int f = 0; f < sphere.faceCount(); ++f)
  {
    const Triangle& t = sphere.triangle(f);
    labels[f] = (sphere.point(t[0]) + sphere.point(t[1]) + sphere.point(t[2])).z() > 0 ? 3 : 8;
  }
  const SegmentationScores s = compareSegmentations(sphere, labels, labels);
  expectAllZero(s);
  EXPECT_TRUE(s.cutsCompared);
  EXPECT_EQ(s.segments1, 2);
  EXPECT_EQ(s.comparedFaces, sphere.faceCount());
}

TEST(SegmentationMetrics, SwappedLabelsScoreZero)
{
  const TriangleMesh grid = makeGrid(4.0, 1.0, 4, 1);
  expectAllZero(compareSegmentations(grid, byColumn({ 0, 0, 1, 1 }), byColumn({ 1, 1, 0, 0 })));
  expectAllZero(compareSegmentations(grid, byColumn({ 0, 0, 1, 1 }), byColumn({ 70, 70, 5, 5 })));
}

TEST(SegmentationMetrics, KnownPartialDisagreement)
{
  // S1 cuts the 4 x 1 strip at x = 2, S2 at x = 1. Areas: S1 (2, 2), S2 (1, 3), overlaps
  // (0,0) = 1, (0,1) = 1, (1,1) = 2 out of 4; face counts twice the areas.
  const TriangleMesh grid = makeGrid(4.0, 1.0, 4, 1);
  const SegmentationScores s = compareSegmentations(grid, byColumn({ 0, 0, 1, 1 }), byColumn({ 0, 1, 1, 1 }));
  EXPECT_DOUBLE_EQ(s.missingRate, 0.25);    // S2's segment 1 misses 1 of its 3
  EXPECT_DOUBLE_EQ(s.falseAlarmRate, 0.25); // S1's segment 0 has 1 of 2 outside its match
  EXPECT_DOUBLE_EQ(s.hammingDistance, 0.25);
  // Pairs: 28; split in S1 only or S2 only: (12 + 16 - 2 * 8) = 12.
  EXPECT_DOUBLE_EQ(s.randIndexError, 12.0 / 28.0);
  // E12 per cell: 1/2, 1/2, 0; E21: 0, 2/3, 1/3. GCE = min(1, 4/3) / 4, LCE = (1/2) / 4.
  EXPECT_DOUBLE_EQ(s.globalConsistencyError, 0.25);
  EXPECT_DOUBLE_EQ(s.localConsistencyError, 0.125);
  // Each cut vertex is one unit from the other cut; the average radius of the 10 vertices
  // around (2, 0.5) is (2 sqrt(4.25) + 2 sqrt(1.25) + 0.5) / 5.
  const double radius = (2.0 * std::sqrt(4.25) + 2.0 * std::sqrt(1.25) + 0.5) / 5.0;
  EXPECT_NEAR(s.cutDiscrepancy, 2.0 / radius, 1e-12);
  EXPECT_NEAR(s.directionalCutDiscrepancy12, 1.0 / radius, 1e-12);

  // Swapping the roles swaps the missing and false-alarm rates; the rest is symmetric.
  const SegmentationScores t = compareSegmentations(grid, byColumn({ 0, 1, 1, 1 }), byColumn({ 0, 0, 1, 1 }));
  EXPECT_DOUBLE_EQ(t.missingRate, s.falseAlarmRate);
  EXPECT_DOUBLE_EQ(t.falseAlarmRate, s.missingRate);
  EXPECT_DOUBLE_EQ(t.randIndexError, s.randIndexError);
  EXPECT_DOUBLE_EQ(t.globalConsistencyError, s.globalConsistencyError);
  EXPECT_DOUBLE_EQ(t.localConsistencyError, s.localConsistencyError);
  EXPECT_DOUBLE_EQ(t.cutDiscrepancy, s.cutDiscrepancy);
}

TEST(SegmentationMetrics, InvariantUnderLabelPermutation)
{
  const TriangleMesh torus = makeTorus(3.0, 1.0, 48, 16);
  std::mt19937 random(7);
  std::uniform_int_distribution<int> pick(0, 5);
  std::vector<int> a(torus.faceCount()), b(torus.faceCount());
  for (int f = 0; f < torus.faceCount(); ++f)
  {
    a[f] = (f / 96) % 4;
    b[f] = pick(random) == 0 ? (a[f] + 1) % 4 : a[f];
  }
  const std::vector<int> permutation = { 17, 3, 42, 0 };
  std::vector<int> aPermuted(a.size());
  for (std::size_t f = 0; f < a.size(); ++f)
  {
    aPermuted[f] = permutation[a[f]];
  }
  const SegmentationScores s = compareSegmentations(torus, a, b);
  const SegmentationScores t = compareSegmentations(torus, aPermuted, b);
  EXPECT_GT(s.randIndexError, 0.0);
  EXPECT_DOUBLE_EQ(s.randIndexError, t.randIndexError);
  EXPECT_DOUBLE_EQ(s.hammingDistance, t.hammingDistance);
  EXPECT_DOUBLE_EQ(s.globalConsistencyError, t.globalConsistencyError);
  EXPECT_DOUBLE_EQ(s.localConsistencyError, t.localConsistencyError);
  EXPECT_DOUBLE_EQ(s.cutDiscrepancy, t.cutDiscrepancy);
}

TEST(SegmentationMetrics, UnlabelledFacesAreLeftOut)
{
  const TriangleMesh grid = makeGrid(4.0, 1.0, 4, 1);
  // The last column is unlabelled in S1: only the first three columns are compared.
  const SegmentationScores s = compareSegmentations(grid, byColumn({ 0, 0, 1, -1 }), byColumn({ 0, 0, 1, 2 }));
  EXPECT_EQ(s.comparedFaces, 6);
  EXPECT_EQ(s.segments2, 3);
  EXPECT_DOUBLE_EQ(s.randIndexError, 0.0);
  EXPECT_DOUBLE_EQ(s.hammingDistance, 0.0);
}

TEST(SegmentationMetrics, OneSegmentHasNoCut)
{
  const TriangleMesh grid = makeGrid(4.0, 1.0, 4, 1);
  const SegmentationScores s = compareSegmentations(grid, byColumn({ 0, 0, 0, 0 }), byColumn({ 0, 0, 1, 1 }));
  EXPECT_FALSE(s.cutsCompared);
  EXPECT_EQ(s.cutDiscrepancy, 0.0);
  // Each reference segment lies inside S1's single segment: nothing is missed, but half of S1's
  // segment lies outside its best match.
  EXPECT_DOUBLE_EQ(s.missingRate, 0.0);
  EXPECT_DOUBLE_EQ(s.falseAlarmRate, 0.5);
  EXPECT_DOUBLE_EQ(s.globalConsistencyError, 0.0); // a refinement: no consistency error
}

TEST(SegmentationMetrics, BadInputIsRefused)
{
  const TriangleMesh grid = makeGrid(4.0, 1.0, 4, 1);
  const SegmentationEvaluator evaluator(grid);
  EXPECT_THROW(evaluator.prepare({ 0, 1, 2 }), Error);
  EXPECT_THROW(evaluator.prepare(byColumn({ 0, -2, 1, 1 })), Error);
}

TEST(SegmentationMetrics, HumanAgreementOnPrincetonModel)
{
  // Model 1 of the benchmark: the mean 1 - RI over all pairs of its 16 human segmentations is
  // 0.073 (psb-dev/README.md).
  const std::filesystem::path root = std::filesystem::path(KERF_SHARED_DATA) / "psb-dev";
  if (!std::filesystem::exists(root / "off" / "1.off"))
  {
    GTEST_SKIP() << "../shared/data/psb-dev is absent";
  }
  PolygonMesh polygons = readOFF((root / "off" / "1.off").string());
  Triangulation triangles = triangulatePolygons(polygons);
  const TriangleMesh mesh(polygons.points, triangles.triangles);
  const SegmentationEvaluator evaluator(mesh);
  std::vector<PreparedSegmentation> humans;
  for (int j = 0; j < 16; ++j)
  {
    humans.push_back(
      evaluator.prepare(readSegmentation((root / "seg" / "1" / ("1_" + std::to_string(j) + ".seg")).string())));
  }
  double sum = 0.0;
  int count = 0;
  for (std::size_t a = 0; a < humans.size(); ++a)
  {
    for (std::size_t b = a + 1; b < humans.size(); ++b)
    {
      sum += evaluator.compare(humans[a], humans[b]).randIndexError;
      ++count;
    }
  }
  EXPECT_NEAR(sum / count, 0.073, 0.0005);
}

TEST(SegmentationMetrics, MatchLabelsFollowsTheLargestOverlap)
{
  // Segment 7 overlaps reference 2 most, segment 4 reference 0; segment 9 has no free match.
  const std::vector<int> labels{ 7, 7, 7, 4, 4, 9, -1 };
  const std::vector<int> reference{ 2, 2, 0, 0, 0, 2, 1 };
  EXPECT_EQ(matchLabels(labels, reference), (std::vector<int>{ 2, 2, 2, 0, 0, 3, -1 }));
  EXPECT_THROW(matchLabels({ 1 }, { 1, 2 }), Error);
}

TEST(SimulatedStrokes, OneStrokePerBoundaryChain)
{
  // A cylinder cut into three bands: two boundaries, each a loop around the axis.
  const TriangleMesh cylinder = makeCylinder(1.0, 3.0, 48, 31);
  std::vector<int> labels = threeBands(cylinder);
  const std::vector<BoundaryStroke> strokes = boundaryStrokes(cylinder, labels, 0.2);
  ASSERT_EQ(strokes.size(), 2u);
  EXPECT_EQ(strokes[0].label1, 0);
  EXPECT_EQ(strokes[0].label2, 5);
  EXPECT_EQ(strokes[1].label1, 5);
  EXPECT_EQ(strokes[1].label2, 9);
  for (const BoundaryStroke& stroke : strokes)
  {
    const double height = stroke.label1 == 0 ? 1.0 : 2.0;
    // A closed loop of circumference 2 pi, sampled about 0.2 apart.
    EXPECT_NEAR(static_cast<double>(stroke.points.size()), 2.0 * 3.14159265 / 0.2 + 1.0, 2.0);
    EXPECT_LT((stroke.points.front() - stroke.points.back()).norm(), 1e-12);
    for (const Vector3& p : stroke.points)
    {
      EXPECT_NEAR(p.z(), height, 1e-12);
      EXPECT_NEAR(std::hypot(p.x(), p.y()), 1.0, 0.01);
    }
  }
  // A second, disjoint boundary between the same pair gives a second stroke.
  for (int f = 0; f < cylinder.faceCount(); ++f)
  {
    labels[f] = labels[f] == 9 ? 0 : labels[f];
  }
  EXPECT_EQ(boundaryStrokes(cylinder, labels, 0.2).size(), 2u);
  EXPECT_THROW(boundaryStrokes(cylinder, { 1, 2 }, 0.2), Error);
}

TEST(SimulatedStrokes, SpinesAreFacePathsInsideTheirSegments)
{
  // kerf::segmentSpines, which innermostStrokes draws through: each spine is a path of faces of
  // its own label, each sharing an edge with the next, whose centroids are the stroke's points.
  const TriangleMesh cylinder = makeCylinder(1.0, 3.0, 48, 31);
  const std::vector<int> labels = threeBands(cylinder);
  const std::vector<SegmentSpine> spines = segmentSpines(cylinder, labels, 0.2);
  const std::vector<SegmentStroke> strokes = innermostStrokes(cylinder, labels, 0.2);
  ASSERT_EQ(spines.size(), strokes.size());
  for (std::size_t s = 0; s < spines.size(); ++s)
  {
    EXPECT_EQ(spines[s].label, strokes[s].label);
    ASSERT_EQ(spines[s].faces.size(), strokes[s].points.size());
    for (std::size_t i = 0; i < spines[s].faces.size(); ++i)
    {
      const int f = spines[s].faces[i];
      EXPECT_EQ(labels[f], spines[s].label);
      const Triangle& t = cylinder.triangle(f);
      EXPECT_EQ(
        strokes[s].points[i], Vector3((cylinder.point(t[0]) + cylinder.point(t[1]) + cylinder.point(t[2])) / 3.0));
      if (i > 0)
      {
        const int previous = spines[s].faces[i - 1];
        bool neighbours = false;
        for (int k = 0; k < 3; ++k)
        {
          neighbours |= cylinder.faceNeighbor(f, k) == previous;
        }
        EXPECT_TRUE(neighbours) << "spine " << s << " step " << i;
      }
    }
  }
  EXPECT_THROW(segmentSpines(cylinder, labels, 0.0), Error);
}

TEST(SimulatedStrokes, InnermostStrokesRunAlongTheMiddleOfEachSegment)
{
  // Three bands of height 1 on an open cylinder of radius 1 and height 3. Distances inside are
  // counted from the borders with other labels only: the middle band's innermost faces lie around
  // its middle (0.5 inside), the end bands' near the cylinder's open ends (about 1 inside). With
  // depth 0.2 a stroke keeps to the faces at least a fifth as far inside as the innermost one, and
  // it is the longest path through them: half way around the cylinder at least (pi, less the
  // centroids' chords).
  const TriangleMesh cylinder = makeCylinder(1.0, 3.0, 48, 31);
  std::vector<int> labels = threeBands(cylinder);
  const std::vector<SegmentStroke> strokes = innermostStrokes(cylinder, labels, 0.2);
  ASSERT_EQ(strokes.size(), 3u);
  const std::vector<int> expectedLabels{ 0, 5, 9 };
  for (std::size_t s = 0; s < strokes.size(); ++s)
  {
    EXPECT_EQ(strokes[s].label, expectedLabels[s]);
    ASSERT_GE(strokes[s].points.size(), 20u);
    double length = 0.0;
    for (std::size_t i = 0; i < strokes[s].points.size(); ++i)
    {
      const Vector3& p = strokes[s].points[i];
      EXPECT_NEAR(std::hypot(p.x(), p.y()), 1.0, 0.01);
      if (s == 1)
      {
        EXPECT_LT(std::abs(p.z() - 1.5), 0.4 + 0.05); // 0.1 inside at least
      }
      else
      {
        EXPECT_GT(std::abs(p.z() - 1.5), 0.7 - 0.05); // 0.2 inside at least (1 at the open end)
      }
      if (i > 0)
      {
        const double step = (p - strokes[s].points[i - 1]).norm();
        EXPECT_LT(step, 0.15); // neighbouring faces' centroids: the stroke stays on the surface
        length += step;
      }
    }
    EXPECT_GT(length, 3.0);
  }
  // Depth 1 keeps the innermost faces only: the middle band's stroke runs around its middle row.
  const std::vector<SegmentStroke> deepest = innermostStrokes(cylinder, labels, 1.0);
  for (const Vector3& p : deepest[1].points)
  {
    EXPECT_LT(std::abs(p.z() - 1.5), 0.1);
  }
  // A whole component (no border with another label) starts at its first face; unlabelled faces
  // get no stroke.
  auto centroid = [&cylinder](int f) {
    const Triangle& t = cylinder.triangle(f);
    return Vector3((cylinder.point(t[0]) + cylinder.point(t[1]) + cylinder.point(t[2])) / 3.0);
  };
  std::vector<int> whole(cylinder.faceCount(), 3);
  const std::vector<SegmentStroke> single = innermostStrokes(cylinder, whole, 0.5);
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].label, 3);
  ASSERT_EQ(single[0].points.size(), 1u);
  EXPECT_EQ(single[0].points[0], centroid(0));
  whole[0] = -1;
  const std::vector<SegmentStroke> labelledOnly = innermostStrokes(cylinder, whole, 0.5);
  ASSERT_EQ(labelledOnly.size(), 1u);
  EXPECT_EQ(labelledOnly[0].label, 3);
  EXPECT_THROW(innermostStrokes(cylinder, { 1, 2 }, 0.2), Error);
  EXPECT_THROW(innermostStrokes(cylinder, labels, 0.0), Error);
  EXPECT_THROW(innermostStrokes(cylinder, labels, 1.5), Error);
  EXPECT_THROW(innermostStrokes(cylinder, labels, std::nan("")), Error);
}
