// Core extraction against shapes with known parts: the three fingers (4 parts), a bent copy (pose
// invariance), a sphere and a plane (no parts), two components.
#include "Error.h"
#include "Evaluation/SegmentationMetrics.h"
#include "Mesh/MeshGenerators.h"
#include "Segmentation/CoreExtraction.h"
#include "Segmentation/FaceGraph.h"
#include "SegmentationShapes.h"

#include <gtest/gtest.h>

#include <iostream>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace kerf
{
namespace
{

int distinctLabels(const std::vector<int>& labels)
{
  return static_cast<int>(std::set<int>(labels.begin(), labels.end()).size());
}

// The fingers with finger 0 (along +x) bent up by `angle` about the y axis through (pivot, 0, 0):
// points beyond pivot + blend turn rigidly, those between by a share growing linearly (a bend).
TriangleMesh bentFingers(double angle, double pivot, double blend)
{
  const TriangleMesh& mesh = test::fingers().surface->mesh();
  std::vector<Vector3> points = mesh.points();
  for (Vector3& p : points)
  {
    if (p.x() <= pivot)
    {
      continue;
    }
    const double share = std::min(1.0, (p.x() - pivot) / blend);
    const double a = share * angle;
    const Vector3 d = p - Vector3(pivot, 0.0, 0.0);
    p = Vector3(pivot + std::cos(a) * d.x() - std::sin(a) * d.z(), d.y(), std::sin(a) * d.x() + std::cos(a) * d.z());
  }
  return mesh.withPoints(std::move(points));
}

TEST(CoreExtraction, FingersGiveTheBodyAndThreeFingers)
{
  const test::Fingers& shape = test::fingers();
  const FaceGraph graph(shape.surface->mesh());
  const CoreExtractionResult result = segmentByCoreExtraction(graph, CoreExtractionOptions());
  ASSERT_EQ(static_cast<int>(result.labels.size()), graph.faceCount());
  EXPECT_EQ(result.segmentCount, 4);
  EXPECT_EQ(distinctLabels(result.labels), 4);
  EXPECT_GE(result.featurePoints, 3);
  // Measured 0.068, what the same minimum cuts give from the construction's own labels (the cuts
  // settle a few rows of triangles off its crease angle); 0.059 with the coarse boundaries.
  const double error = compareSegmentations(graph.mesh(), result.labels, shape.parts).randIndexError;
  std::cout << "core extraction on the fingers: " << result.segmentCount << " segments, " << result.featurePoints
            << " feature points, 1 - Rand index " << error << "\n";
  EXPECT_LE(error, 0.075) << error;
  // The core is the body: no fingertip face lies in it.
  for (int f : result.featureFaces)
  {
    if (shape.parts[f] > 0)
    {
      EXPECT_EQ(result.core[f], 0);
    }
  }
  // Deterministic, bit for bit.
  EXPECT_EQ(segmentByCoreExtraction(graph, CoreExtractionOptions()).labels, result.labels);
}

TEST(CoreExtraction, PoseInvariantUnderABentFinger)
{
  const test::Fingers& shape = test::fingers();
  const FaceGraph straight(shape.surface->mesh());
  const TriangleMesh bentMesh = bentFingers(1.0, 1.3, 0.3);
  const FaceGraph bent(bentMesh);
  const CoreExtractionResult a = segmentByCoreExtraction(straight, CoreExtractionOptions());
  const CoreExtractionResult b = segmentByCoreExtraction(bent, CoreExtractionOptions());
  EXPECT_EQ(a.segmentCount, 4);
  EXPECT_EQ(b.segmentCount, a.segmentCount);
  const double errorA = compareSegmentations(straight.mesh(), a.labels, shape.parts).randIndexError;
  const double errorB = compareSegmentations(bentMesh, b.labels, shape.parts).randIndexError;
  std::cout << "straight " << errorA << ", bent " << errorB << "\n";
  EXPECT_LE(std::abs(errorA - errorB), 0.02) << errorA << " " << errorB;
}

TEST(CoreExtraction, ShapesWithoutPartsAreOneSegment)
{
  for (const TriangleMesh& mesh : { makeIcosphere(1.0, 4), makeGrid(2.0, 1.0, 40, 20) })
  {
    const CoreExtractionResult result = segmentByCoreExtraction(FaceGraph(mesh), CoreExtractionOptions());
    EXPECT_EQ(result.segmentCount, 1);
    EXPECT_EQ(distinctLabels(result.labels), 1);
  }
}

TEST(CoreExtraction, EachComponentApart)
{
  const TriangleMesh& one = test::fingers().surface->mesh();
  std::vector<Vector3> points = one.points();
  std::vector<Triangle> triangles = one.triangles();
  for (const Vector3& p : one.points())
  {
    points.push_back(p + Vector3(10.0, 0.0, 0.0));
  }
  for (Triangle t : one.triangles())
  {
    for (int& v : t)
    {
      v += one.vertexCount();
    }
    triangles.push_back(t);
  }
  const TriangleMesh two(std::move(points), std::move(triangles));
  const CoreExtractionResult single = segmentByCoreExtraction(FaceGraph(one), CoreExtractionOptions());
  const CoreExtractionResult both = segmentByCoreExtraction(FaceGraph(two), CoreExtractionOptions());
  EXPECT_EQ(both.segmentCount, 2 * single.segmentCount);
  // The first copy is segmented as it is alone.
  EXPECT_TRUE(std::equal(single.labels.begin(), single.labels.end(), both.labels.begin()));
}

TEST(CoreExtraction, RefusesOptionsOutOfRange)
{
  const FaceGraph graph(makeIcosphere(1.0, 2));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CoreExtractionOptions options;
  options.coarseSize = 9;
  EXPECT_THROW(segmentByCoreExtraction(graph, options), Error);
  for (double value : { 0.0, 1.5, nan })
  {
    options = CoreExtractionOptions();
    options.featureRadius = value;
    EXPECT_THROW(segmentByCoreExtraction(graph, options), Error);
  }
  for (double value : { -0.1, 1.0, nan })
  {
    options = CoreExtractionOptions();
    options.hullTolerance = value;
    EXPECT_THROW(segmentByCoreExtraction(graph, options), Error);
    options = CoreExtractionOptions();
    options.minimumSegmentArea = value;
    EXPECT_THROW(segmentByCoreExtraction(graph, options), Error);
  }
  for (double value : { 0.0, 1.0, nan })
  {
    options = CoreExtractionOptions();
    options.extensionFactor = value;
    EXPECT_THROW(segmentByCoreExtraction(graph, options), Error);
  }
  options = CoreExtractionOptions();
  options.refinement.bandWidth = -1.0;
  EXPECT_THROW(segmentByCoreExtraction(graph, options), Error);
  // The empty mesh: no labels, no error.
  EXPECT_TRUE(segmentByCoreExtraction(FaceGraph(TriangleMesh()), CoreExtractionOptions()).labels.empty());
}

} // namespace
} // namespace kerf
