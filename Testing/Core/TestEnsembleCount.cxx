// The ensemble choosing its own number of segments, and the Rand index distance it chooses by.
#include "Error.h"
#include "Evaluation/SegmentationMetrics.h"
#include "Mesh/MeshGenerators.h"
#include "Segmentation/EnsembleSegmentation.h"
#include "Segmentation/FaceGraph.h"
#include "Segmentation/KMeansSegmentation.h"
#include "Segmentation/PartitionDistance.h"
#include "Segmentation/WatershedSegmentation.h"
#include "SegmentationShapes.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <utility>
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
  // Labels far above the faces (the hash map's route) and more cells than a dense table holds: 200
  // faces all apart, numbered by 10^9 + 7 f on one side and backwards on the other, agree on every
  // pair; against halves, the 2 x 4950 pairs inside the halves disagree, of 19,900.
  std::vector<int> spread(200), backwards(200), halves(200);
  for (int f = 0; f < 200; ++f)
  {
    spread[f] = 1000000000 + 7 * f;
    backwards[f] = 199 - f;
    halves[f] = f < 100 ? 1000000000 : 3;
  }
  EXPECT_DOUBLE_EQ(randIndexError(spread, backwards), 0.0);
  EXPECT_DOUBLE_EQ(randIndexError(spread, halves), 9900.0 / 19900.0);
  EXPECT_DOUBLE_EQ(randIndexError(halves, backwards), 9900.0 / 19900.0);
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

// The members that share their work across counts give at each count what a run at that count
// gives, bit for bit: the watershed's merging reaches every higher count on the way down, and
// k-means' first k representatives are the k-count's.
TEST(EnsembleCount, MembersAtCountsEqualTheirRunsAtEachCount)
{
  const TriangleMesh& one = fingers().surface->mesh();
  const TriangleMesh two = withMovedCopy(one, Vector3(5.0, 0.0, 0.0));
  for (const TriangleMesh* mesh : { &one, &two })
  {
    const FaceGraph graph(*mesh);
    // The watershed's regions before any merge: counts from 1 (below what two components can
    // reach) to past them (no merge at all).
    WatershedOptions unmerged;
    unmerged.segmentCount = mesh->faceCount();
    const int regions = segmentByWatershed(graph, unmerged).segmentCount;
    ASSERT_GT(regions, 12);
    for (const auto& [lowest, highest] : { std::pair{ 1, 12 }, std::pair{ regions - 2, regions + 2 } })
    {
      const std::vector<WatershedResult> shared =
        segmentByWatershedAtCounts(graph, WatershedOptions(), lowest, highest);
      ASSERT_EQ(shared.size(), static_cast<std::size_t>(highest - lowest + 1));
      for (int k = lowest; k <= highest; ++k)
      {
        WatershedOptions atK;
        atK.segmentCount = k;
        const WatershedResult alone = segmentByWatershed(graph, atK);
        const WatershedResult& at = shared[static_cast<std::size_t>(k - lowest)];
        EXPECT_EQ(at.labels, alone.labels) << "watershed, count " << k;
        EXPECT_EQ(at.segmentCount, alone.segmentCount) << "watershed, count " << k;
        EXPECT_EQ(at.basins, alone.basins);
        EXPECT_EQ(at.segmentCount, std::min(std::max(k, graph.componentCount()), regions));
      }
    }
    const std::vector<KMeansSegmentationResult> kMeans =
      segmentByKMeansAtCounts(graph, 2, 9, KMeansSegmentationOptions());
    ASSERT_EQ(kMeans.size(), 8u);
    for (int k = 2; k <= 9; ++k)
    {
      const KMeansSegmentationResult alone = segmentByKMeans(graph, k, KMeansSegmentationOptions());
      const KMeansSegmentationResult& at = kMeans[static_cast<std::size_t>(k - 2)];
      EXPECT_EQ(at.labels, alone.labels) << "k-means, count " << k;
      EXPECT_EQ(at.representatives, alone.representatives) << "k-means, count " << k;
      EXPECT_EQ(at.iterations, alone.iterations);
      EXPECT_EQ(*std::max_element(at.labels.begin(), at.labels.end()) + 1, k);
    }
    EXPECT_THROW(segmentByWatershedAtCounts(graph, WatershedOptions(), 0, 3), Error);
    EXPECT_THROW(segmentByWatershedAtCounts(graph, WatershedOptions(), 4, 3), Error);
    EXPECT_THROW(segmentByKMeansAtCounts(graph, 0, 3, KMeansSegmentationOptions()), Error);
    EXPECT_THROW(segmentByKMeansAtCounts(graph, 4, 3, KMeansSegmentationOptions()), Error);
    EXPECT_THROW(segmentByKMeansAtCounts(graph, 2, mesh->faceCount() + 1, KMeansSegmentationOptions()), Error);
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
  // A maximum above the faces is refused: a 2-triangle square cannot have 3 segments.
  const Surface square{ TriangleMesh(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 2, 3 } }) };
  EXPECT_THROW(segmentByEnsembleChoosingCount(square, 2, 3, EnsembleSegmentationOptions()), Error);
  EXPECT_EQ(segmentByEnsembleChoosingCount(square, 2, 2, EnsembleSegmentationOptions()).segmentCount, 1);
  // The convex tolerance is a fraction of the diagonal, in [0, 1).
  for (double tolerance : { -0.1, 1.0, std::numeric_limits<double>::quiet_NaN() })
  {
    EnsembleSegmentationOptions bad;
    bad.convexTolerance = tolerance;
    EXPECT_THROW(segmentByEnsembleChoosingCount(surface, 5, 11, bad), Error);
  }
}

// A surface with no parts (Hoffman and Richards 1984's minima rule puts part boundaries at concavities,
// and a convex surface has none) stays one segment when the count is chosen; with the convex
// tolerance 0 it gets a count in the range like any other.
TEST(EnsembleCount, ConvexSurfacesStayOneSegment)
{
  const EnsembleSegmentationOptions options;
  const auto expectOneSegment = [&](const TriangleMesh& mesh, const char* what) {
    const Surface surface{ mesh };
    const EnsembleSegmentationResult result = segmentByEnsembleChoosingCount(surface, 5, 11, options);
    EXPECT_EQ(result.segmentCount, 1) << what;
    EXPECT_EQ(result.labels, std::vector<int>(mesh.faceCount(), 0)) << what;
    EXPECT_TRUE(result.countScores.empty()) << what;
  };
  const TriangleMesh sphere = makeIcosphere(0.5, 4);
  expectOneSegment(sphere, "sphere");
  expectOneSegment(makeGrid(2.0, 1.0, 20, 10), "planar patch");
  // A scanned sphere: every vertex moved along its radius by up to 0.4% of the radius (a fixed
  // pattern), so that many of its edges are slightly concave.
  std::vector<Vector3> noisy = sphere.points();
  for (std::size_t v = 0; v < noisy.size(); ++v)
  {
    noisy[v] *= 1.0 + 0.004 * std::sin(12.9898 * static_cast<double>(v));
  }
  expectOneSegment(TriangleMesh(noisy, sphere.triangles()), "noisy sphere");
  EnsembleSegmentationOptions everyComponent;
  everyComponent.convexTolerance = 0.0;
  const Surface sphereSurface{ sphere };
  const EnsembleSegmentationResult forced = segmentByEnsembleChoosingCount(sphereSurface, 5, 11, everyComponent);
  EXPECT_GE(forced.segmentCount, 5);
  EXPECT_LE(forced.segmentCount, 11);
  // The fingers (deep concavities between body and fingers) are not convex: their count is chosen.
  EXPECT_GE(segmentByEnsembleChoosingCount(*fingers().surface, 5, 11, options).segmentCount, 5);
}

// A sphere beside the fingers: the sphere one segment, the fingers as they are alone.
TEST(EnsembleCount, AConvexComponentBesideOneWithParts)
{
  const TriangleMesh& one = fingers().surface->mesh();
  const TriangleMesh sphere = makeIcosphere(0.5, 3);
  std::vector<Vector3> points = one.points();
  std::vector<Triangle> triangles = one.triangles();
  const int offset = static_cast<int>(points.size());
  for (const Vector3& p : sphere.points())
  {
    points.push_back(p + Vector3(6.0, 0.0, 0.0));
  }
  for (Triangle t : sphere.triangles())
  {
    for (int& v : t)
    {
      v += offset;
    }
    triangles.push_back(t);
  }
  const Surface both{ TriangleMesh(std::move(points), std::move(triangles)) };
  const EnsembleSegmentationOptions options;
  const EnsembleSegmentationResult result = segmentByEnsembleChoosingCount(both, 5, 11, options);
  const EnsembleSegmentationResult alone = segmentByEnsembleChoosingCount(*fingers().surface, 5, 11, options);
  ASSERT_EQ(result.segmentCount, alone.segmentCount + 1);
  const int n = one.faceCount();
  for (int f = 0; f < n; ++f)
  {
    ASSERT_EQ(result.labels[f], alone.labels[f]);
  }
  for (int f = n; f < both.mesh().faceCount(); ++f)
  {
    ASSERT_EQ(result.labels[f], alone.segmentCount);
  }
}
