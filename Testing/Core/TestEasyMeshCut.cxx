// Easy Mesh Cutting in one call: fingers cut off by closed boundaries, shorter after the snakes, deterministic.
#include "Error.h"
#include "Segmentation/EasyMeshCut.h"
#include "StrokeShapes.h"
#include "Surface/Surface.h"

#include <gtest/gtest.h>

#include <set>

namespace kerf
{
namespace
{

double totalLength(const EasyMeshCutResult& result)
{
  double length = 0.0;
  for (const EasyMeshCutBoundary& boundary : result.boundaries)
  {
    length += boundary.length;
  }
  return length;
}

TEST(EasyMeshCut, FingersAreCutOffByOneClosedBoundaryEach)
{
  const test::ProtrusionsWithStrokes shape(4);
  const auto surface = std::make_shared<const Surface>(shape.mesh);
  for (bool refine : { false, true })
  {
    EasyMeshCutOptions options;
    options.refine = refine;
    const EasyMeshCutResult result = easyMeshCut(surface, shape.strokes, options);
    ASSERT_EQ(static_cast<int>(result.faceLabels.size()), shape.mesh.faceCount());
    EXPECT_EQ(result.boundaries.size(), 3u);
    std::set<std::pair<int, int>> pairs;
    for (const EasyMeshCutBoundary& boundary : result.boundaries)
    {
      pairs.emplace(boundary.leftLabel, boundary.rightLabel);
      EXPECT_TRUE(boundary.closed);
      // The crease around a finger of width 0.35 rad on the unit sphere: a loop longer than
      // the finger's rim (about 2 pi 0.35); refined (measured 3.3 to 4.5), shorter than the
      // sphere's equator; grown along mesh edges it zigzags (measured 9.0 to 9.6).
      EXPECT_GT(boundary.length, 2.0);
      EXPECT_LT(boundary.length, refine ? 6.28 : 12.0);
    }
    EXPECT_EQ(pairs, (std::set<std::pair<int, int>>{ { 0, 1 }, { 0, 2 }, { 0, 3 } }));
    EXPECT_EQ(result.snake.sweeps > 0, refine);
    // The tips keep their strokes' labels.
    for (int f = 0; f < shape.mesh.faceCount(); ++f)
    {
      const Triangle& t = shape.mesh.triangle(f);
      const Vector3 centroid = (shape.mesh.point(t[0]) + shape.mesh.point(t[1]) + shape.mesh.point(t[2])) / 3.0;
      double angle = 0.0;
      const int finger = test::ProtrusionsWithStrokes::nearestFinger(centroid, angle);
      if (centroid.norm() > 1.5)
      {
        EXPECT_EQ(result.faceLabels[f], finger + 1);
      }
    }
  }
}

TEST(EasyMeshCut, SnakesShortenTheGrownBoundaries)
{
  const test::ProtrusionsWithStrokes shape(4);
  const auto surface = std::make_shared<const Surface>(shape.mesh);
  EasyMeshCutOptions grown;
  grown.refine = false;
  const double before = totalLength(easyMeshCut(surface, shape.strokes, grown));
  const double after = totalLength(easyMeshCut(surface, shape.strokes, EasyMeshCutOptions()));
  EXPECT_LT(after, 0.95 * before) << before << " -> " << after;
}

TEST(EasyMeshCut, IsDeterministic)
{
  const test::ProtrusionsWithStrokes shape(4);
  const EasyMeshCutResult a = easyMeshCut(std::make_shared<const Surface>(shape.mesh), shape.strokes, {});
  const EasyMeshCutResult b = easyMeshCut(std::make_shared<const Surface>(shape.mesh), shape.strokes, {});
  EXPECT_EQ(a.faceLabels, b.faceLabels);
  EXPECT_EQ(a.distances, b.distances);
  ASSERT_EQ(a.boundaries.size(), b.boundaries.size());
  for (std::size_t i = 0; i < a.boundaries.size(); ++i)
  {
    EXPECT_EQ(a.boundaries[i].points, b.boundaries[i].points);
  }
}

TEST(EasyMeshCut, RefusesStrokesOfOneLabel)
{
  const test::ProtrusionsWithStrokes shape(3);
  std::vector<LabelledStroke> strokes = shape.strokes;
  for (LabelledStroke& stroke : strokes)
  {
    stroke.label = 1;
  }
  EXPECT_THROW(easyMeshCut(std::make_shared<const Surface>(shape.mesh), strokes, {}), Error);
  EXPECT_THROW(easyMeshCut(std::make_shared<const Surface>(shape.mesh), {}, {}), Error);
}

} // namespace
} // namespace kerf
