// Chart layout: the hull of known point sets, minimal boxes against their analytic areas, and the packing's scale.
#include "Error.h"
#include "Parameterization/ChartPacking.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <vector>

namespace kerf
{
namespace
{

// The width and height of the axis-aligned box of `points` turned by `angle`.
Vector2 turnedBoxSize(const std::vector<Vector2>& points, double angle)
{
  const Eigen::Rotation2Dd turn(angle);
  Vector2 low = Vector2::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const Vector2& p : points)
  {
    low = low.cwiseMin(turn * p);
    high = high.cwiseMax(turn * p);
  }
  return high - low;
}

} // namespace

TEST(ChartPacking, HullOfAKnownPointSet)
{
  // A 4 x 3 rectangle with points inside, on its sides and repeated: its four corners remain,
  // counter-clockwise from the lowest-then-leftmost.
  const std::vector<Vector2> points = { { 2, 1 }, { 4, 3 }, { 0, 3 }, { 2, 0 }, { 4, 1.5 }, { 0, 0 }, { 1, 2 },
    { 4, 0 }, { 0, 3 }, { 3, 3 }, { 0, 1 }, { 4, 0 } };
  const std::vector<Vector2> expected = { { 0, 0 }, { 4, 0 }, { 4, 3 }, { 0, 3 } };
  EXPECT_EQ(convexHull(points), expected);
  // A regular hexagon around its centre: its six vertices, counter-clockwise (positive area).
  std::vector<Vector2> hexagon = { { 0.0, 0.0 } };
  for (int i = 0; i < 6; ++i)
  {
    hexagon.push_back(Vector2(std::cos(M_PI / 3.0 * i - M_PI / 2.0), std::sin(M_PI / 3.0 * i - M_PI / 2.0)));
  }
  const std::vector<Vector2> hull = convexHull(hexagon);
  ASSERT_EQ(hull.size(), 6u);
  EXPECT_EQ(hull[0], hexagon[1]);
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < hull.size(); ++i)
  {
    const Vector2& a = hull[i];
    const Vector2& b = hull[(i + 1) % hull.size()];
    twiceArea += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_NEAR(0.5 * twiceArea, 1.5 * std::sqrt(3.0), 1e-12);
  // Fewer than three distinct points come back sorted and without repeats.
  EXPECT_EQ(convexHull({ { 1, 1 }, { 1, 1 } }).size(), 1u);
  EXPECT_TRUE(convexHull({}).empty());
}

TEST(ChartPacking, MinimalBoxAreaOfRotatedRectangles)
{
  // A 2.5 x 1 rectangle (its corners, side points and inside points), moved and turned by several
  // angles: the box after the returned turn has the rectangle's area and lies flat.
  std::vector<Vector2> rectangle;
  for (int i = 0; i <= 5; ++i)
  {
    for (int j = 0; j <= 4; ++j)
    {
      rectangle.push_back(Vector2(0.5 * i, 0.25 * j));
    }
  }
  for (double angle : { 0.0, 0.1, 0.7, 1.2, 2.0, -0.5, 3.0 })
  {
    const Eigen::Rotation2Dd turn(angle);
    std::vector<Vector2> points;
    for (const Vector2& p : rectangle)
    {
      points.push_back(turn * p + Vector2(-3.0, 7.0));
    }
    const Vector2 size = turnedBoxSize(points, minimalBoundingBoxRotation(points));
    EXPECT_NEAR(size.x() * size.y(), 2.5, 1e-12) << angle;
    EXPECT_NEAR(size.x(), 2.5, 1e-12) << angle;
    EXPECT_NEAR(size.y(), 1.0, 1e-12) << angle;
  }
  // A regular octagon of circumradius R: its least box is the square on four of its sides, of
  // side 2 R cos(pi / 8), area (2 + sqrt 2) R^2, where an axis through two vertices gives 4 R^2.
  const double radius = 1.5;
  std::vector<Vector2> octagon;
  for (int i = 0; i < 8; ++i)
  {
    octagon.push_back(radius * Vector2(std::cos(M_PI / 4.0 * i + 0.3), std::sin(M_PI / 4.0 * i + 0.3)));
  }
  const Vector2 size = turnedBoxSize(octagon, minimalBoundingBoxRotation(octagon));
  EXPECT_NEAR(size.x() * size.y(), (2.0 + std::sqrt(2.0)) * radius * radius, 1e-12);
  EXPECT_GE(size.x(), size.y());
}

TEST(ChartPacking, PackingScaleOfSimpleLayouts)
{
  // One 2 x 1 box: it fills the square's width between the margins, so scale = (1 - 2 margin) / 2
  // (or a step of the 1% search below it), at the lower-left corner (margin, margin).
  double scale = 0.0;
  const double margin = 0.05;
  std::vector<Vector2> corners = packBoxes({ { 2.0, 1.0 } }, margin, scale);
  ASSERT_EQ(corners.size(), 1u);
  EXPECT_LE(scale, (1.0 - 2.0 * margin) / 2.0 * (1.0 + 1e-12));
  EXPECT_GE(scale, (1.0 - 2.0 * margin) / 2.0 / 1.01);
  EXPECT_NEAR(corners[0].x(), margin, 1e-12);
  EXPECT_NEAR(corners[0].y(), margin, 1e-12);
  // Two unit squares without margin need a square of side 2 (side by side or stacked).
  corners = packBoxes({ { 1.0, 1.0 }, { 1.0, 1.0 } }, 0.0, scale);
  EXPECT_LE(scale, 0.5);
  EXPECT_GE(scale, 0.5 / 1.01);
  // Nothing to pack, or only empty boxes: scale 1, every corner at the origin.
  EXPECT_TRUE(packBoxes({}, margin, scale).empty());
  EXPECT_EQ(scale, 1.0);
  corners = packBoxes({ { 0.0, 0.0 } }, margin, scale);
  EXPECT_EQ(scale, 1.0);
  EXPECT_EQ(corners[0], Vector2::Zero());
  EXPECT_THROW(packBoxes({ { -1.0, 1.0 } }, margin, scale), Error);
  EXPECT_THROW(packBoxes({ { std::nan(""), 1.0 } }, margin, scale), Error);
}

// Two triangles that share part of the square count as one pair when they belong to two charts,
// none in one chart; a third chart apart from both adds nothing, and a clockwise triangle counts
// as its counter-clockwise twin.
TEST(ChartPacking, OverlapCountSeesOverlappingCharts)
{
  const std::vector<Vector2> uv = { { 0.1, 0.1 }, { 0.6, 0.1 }, { 0.1, 0.6 }, { 0.2, 0.2 }, { 0.9, 0.2 }, { 0.2, 0.9 },
    { 0.7, 0.7 }, { 0.95, 0.7 }, { 0.7, 0.95 } };
  const std::vector<Triangle> triangles = { { { 0, 1, 2 } }, { { 3, 4, 5 } }, { { 6, 7, 8 } } };
  EXPECT_EQ(countChartOverlaps(uv, triangles, { 0, 1, 2 }, 64), 1);
  EXPECT_EQ(countChartOverlaps(uv, triangles, { 0, 0, 2 }, 64), 0);
  const std::vector<Triangle> clockwise = { { { 0, 2, 1 } }, { { 3, 4, 5 } }, { { 6, 7, 8 } } };
  EXPECT_EQ(countChartOverlaps(uv, clockwise, { 0, 1, 2 }, 64), 1);
  EXPECT_THROW(countChartOverlaps(uv, triangles, { 0, 1, 2 }, 0), Error);
  EXPECT_THROW(countChartOverlaps(uv, triangles, { 0, 1, 2 }, 65537), Error);
}

} // namespace kerf
