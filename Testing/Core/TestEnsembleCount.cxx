// The ensemble choosing its own number of segments, and the Rand index distance it chooses by.
#include "Error.h"
#include "Evaluation/SegmentationMetrics.h"
#include "Mesh/MeshGenerators.h"
#include "Segmentation/EnsembleSegmentation.h"
#include "Segmentation/PartitionDistance.h"
#include "SegmentationShapes.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <vector>

using namespace kerf;
using namespace kerf::test;

TEST(PartitionDistance, CountsThePairsOnWhichTwoPartitionsDisagree)
{
  // Four faces, {0,1}{2,3} against {0,2}{1,3}: of the 6 pairs, the 4 that one keeps together.
  EXPECT_DOUBLE_EQ(randIndexError({ 0, 0, 1, 1 }, { 0, 1, 0, 1 }), 4.0 / 6.0);
  // Label values do not matter, only which faces share one.
  EXPECT_DOUBLE_EQ(randIndexError({ 7, 7, 3, 3 }, { 1, 1, 0, 0 }), 0.0);
  // One segment against all apart: every pair disagrees.
  EXPECT_DOUBLE_EQ(randIndexError({ 0, 0, 0, 0, 0 }, { 0, 1, 2, 3, 4 }), 1.0);
  // {0,1,2}{3} against {0,1}{2,3}: pairs (0,2), (1,2) and (2,3) disagree, 3 of 6.
  EXPECT_DOUBLE_EQ(randIndexError({ 0, 0, 0, 1 }, { 5, 5, 6, 6 }), 0.5);
  EXPECT_DOUBLE_EQ(randIndexError({}, {}), 0.0);
  EXPECT_DOUBLE_EQ(randIndexError({ 3 }, { 1 }), 0.0);
  EXPECT_THROW(randIndexError({ 0, 1 }, { 0 }), Error);
  EXPECT_THROW(randIndexError({ 0, -1 }, { 0, 0 }), Error);
}

// The benchmark's metric and this one agree on a real pair of partitions.
TEST(PartitionDistance, EqualsTheBenchmarksRandIndexError)
{
  const TriangleMesh& mesh = fingers().surface->mesh();
  std::vector<int> other(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    other[f] = mesh.point(mesh.triangle(f)[0]).z() > 0.0 ? 1 : 0;
  }
  const SegmentationEvaluator evaluator(mesh);
  const double benchmark =
    evaluator.compare(evaluator.prepare(fingers().parts), evaluator.prepare(other)).randIndexError;
  EXPECT_NEAR(randIndexError(fingers().parts, other), benchmark, 1e-12);
  EXPECT_GT(benchmark, 0.1);
}

TEST(EnsembleCount, ChoosesTheCountNearestToAllTheMembers)
{
  const Surface& surface = *fingers().surface;
  const EnsembleSegmentationOptions options;
  const EnsembleSegmentationResult chosen = segmentByEnsembleChoosingCount(surface, 2, 7, options);
  ASSERT_EQ(chosen.countScores.size(), 6u);
  // The chosen count has the least score, and the smaller count wins a tie.
  const auto best = std::min_element(chosen.countScores.begin(), chosen.countScores.end());
  EXPECT_EQ(chosen.segmentCount, 2 + static_cast<int>(best - chosen.countScores.begin()));
  EXPECT_EQ(chosen.countScore, *best);
  for (double score : chosen.countScores)
  {
    EXPECT_GT(score, 0.0);
    EXPECT_LT(score, 1.0);
  }
  // The body and three fingers: the construction's count (measured: scores 0.359, 0.326, 0.3134,
  // 0.3139, 0.365, 0.453 for 2..7), or one more, where a finger's base comes off the body; the two
  // scores differ by 0.0006, so rounding on another factorization route may swap them.
  EXPECT_GE(chosen.segmentCount, FingerCount + 1);
  EXPECT_LE(chosen.segmentCount, FingerCount + 2);
  EXPECT_LT(chosen.countScores[0], 0.37);
  EXPECT_GT(chosen.countScores[5], 0.44);
  const EnsembleSegmentationResult atCount = segmentByEnsemble(surface, chosen.segmentCount, options);
  EXPECT_EQ(chosen.labels, atCount.labels);
  EXPECT_EQ(atCount.segmentCount, chosen.segmentCount);
  EXPECT_EQ(chosen.members, 5);
  // Deterministic.
  EXPECT_EQ(segmentByEnsembleChoosingCount(surface, 2, 7, options).labels, chosen.labels);
  // One count to choose from is that count.
  const EnsembleSegmentationResult only = segmentByEnsembleChoosingCount(surface, 3, 3, options);
  EXPECT_EQ(only.segmentCount, 3);
  EXPECT_EQ(only.labels, segmentByEnsemble(surface, 3, options).labels);
  ASSERT_EQ(only.countScores.size(), 1u);
}

// A copy of a mesh's triangles from..to, its points numbered by first use (as segmentComponents
// numbers a component's), moved along x.
TriangleMesh copyOfFaces(const TriangleMesh& mesh, int from, int to, double shift)
{
  std::vector<int> number(mesh.vertexCount(), -1);
  std::vector<Vector3> points;
  std::vector<Triangle> triangles;
  for (int f = from; f < to; ++f)
  {
    Triangle t = mesh.triangle(f);
    for (int& v : t)
    {
      if (number[v] < 0)
      {
        number[v] = static_cast<int>(points.size());
        points.push_back(mesh.point(v) + Vector3(shift, 0.0, 0.0));
      }
      v = number[v];
    }
    triangles.push_back(t);
  }
  return TriangleMesh(std::move(points), std::move(triangles));
}

TEST(EnsembleCount, EachComponentChoosesItsOwnCount)
{
  // Two copies of the fingers side by side, the default range 5 to 11: each copy is segmented as
  // it is alone (the count within the range for each), the labels numbered across both.
  const TriangleMesh& one = fingers().surface->mesh();
  const int n = one.faceCount();
  std::vector<Vector3> points;
  std::vector<Triangle> triangles;
  for (int copy = 0; copy < 2; ++copy)
  {
    const int offset = static_cast<int>(points.size());
    for (int v = 0; v < one.vertexCount(); ++v)
    {
      points.push_back(one.point(v) + Vector3(5.0 * copy, 0.0, 0.0));
    }
    for (int f = 0; f < n; ++f)
    {
      Triangle t = one.triangle(f);
      for (int& v : t)
      {
        v += offset;
      }
      triangles.push_back(t);
    }
  }
  const TriangleMesh bothMesh(std::move(points), std::move(triangles));
  const Surface both{ bothMesh };
  const EnsembleSegmentationOptions options;
  const EnsembleSegmentationResult result = segmentByEnsembleChoosingCount(both, 5, 11, options);
  EXPECT_TRUE(result.countScores.empty());
  EXPECT_EQ(result.countScore, 0.0);
  const Surface firstPart{ copyOfFaces(bothMesh, 0, n, 0.0) };
  const Surface secondPart{ copyOfFaces(bothMesh, n, 2 * n, 0.0) };
  const EnsembleSegmentationResult firstAlone = segmentByEnsembleChoosingCount(firstPart, 5, 11, options);
  const EnsembleSegmentationResult secondAlone = segmentByEnsembleChoosingCount(secondPart, 5, 11, options);
  EXPECT_EQ(result.segmentCount, firstAlone.segmentCount + secondAlone.segmentCount);
  EXPECT_GE(firstAlone.segmentCount, 5);
  EXPECT_LE(firstAlone.segmentCount, 11);
  for (int f = 0; f < n; ++f)
  {
    ASSERT_EQ(result.labels[f], firstAlone.labels[f]);
    ASSERT_EQ(result.labels[n + f], firstAlone.segmentCount + secondAlone.labels[f]);
  }
}

TEST(EnsembleCount, RefusesBadRanges)
{
  const Surface& surface = *fingers().surface;
  EXPECT_THROW(segmentByEnsembleChoosingCount(surface, 1, 5, EnsembleSegmentationOptions()), Error);
  EXPECT_THROW(segmentByEnsembleChoosingCount(surface, 6, 5, EnsembleSegmentationOptions()), Error);
  // At most MaximumCountsToChoose counts: 2 to 41 is allowed, 2 to 42 refused before any work.
  EXPECT_THROW(
    segmentByEnsembleChoosingCount(surface, 2, 2 + MaximumCountsToChoose, EnsembleSegmentationOptions()), Error);
  EXPECT_THROW(segmentByEnsembleChoosingCount(surface, 2, 1000000, EnsembleSegmentationOptions()), Error);
  // No faces.
  const Surface empty{ TriangleMesh({}, {}) };
  EXPECT_THROW(segmentByEnsembleChoosingCount(empty, 5, 11, EnsembleSegmentationOptions()), Error);
  EnsembleSegmentationOptions none;
  none.consensusCutsWeight = none.spectralWeight = none.convexFloodingWeight = none.kMeansWeight =
    none.watershedWeight = 0.0;
  EXPECT_THROW(segmentByEnsembleChoosingCount(surface, 2, 5, none), Error);
  // A count above the faces is clipped to them: a 2-triangle square cannot have more than 2.
  const Surface square{ TriangleMesh(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 2, 3 } }) };
  EXPECT_LE(segmentByEnsembleChoosingCount(square, 2, 11, EnsembleSegmentationOptions()).segmentCount, 2);
}
