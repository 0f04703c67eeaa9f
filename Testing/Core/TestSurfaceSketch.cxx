// Sketching on a depth image: strokes on a sphere seen from above, split where they leave it or cross a contour;
// simplification; walks and rims against great circles.
#include "Error.h"
#include "Sketch/SurfaceSketch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace kerf;

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A sphere seen along -z by an orthographic camera: 200 x 200 pixels over [-1.5, 1.5]^2, the depth
// running from 0 at z = 1.5 to 1 at z = -1.5.
struct Ball
{
  Vector3 centre;
  double radius;
};

constexpr int Size = 200;
constexpr double HalfWidth = 1.5;

double worldX(double pixel)
{
  return (pixel - 0.5 * Size) / (0.5 * Size) * HalfWidth;
}

DepthImage::Unprojection orthographic()
{
  return
    [](double x, double y, double depth) { return Vector3(worldX(x), worldX(y), HalfWidth - 2.0 * HalfWidth * depth); };
}

// The depth image of balls (the nearest one shows), the background at 1.
DepthImage render(const std::vector<Ball>& balls)
{
  std::vector<float> depth(static_cast<std::size_t>(Size) * Size, 1.0f);
  for (int row = 0; row < Size; ++row)
  {
    for (int column = 0; column < Size; ++column)
    {
      for (const Ball& ball : balls)
      {
        const double dx = worldX(column) - ball.centre.x();
        const double dy = worldX(row) - ball.centre.y();
        const double h = ball.radius * ball.radius - dx * dx - dy * dy;
        if (h < 0.0)
        {
          continue;
        }
        const float d = static_cast<float>((HalfWidth - (ball.centre.z() + std::sqrt(h))) / (2.0 * HalfWidth));
        float& pixel = depth[static_cast<std::size_t>(row) * Size + column];
        pixel = std::min(pixel, d);
      }
    }
  }
  return DepthImage(Size, Size, std::move(depth), orthographic());
}

// The distance of a point from the ball's surface.
double offSurface(const Vector3& p, const Ball& ball)
{
  return std::abs((p - ball.centre).norm() - ball.radius);
}

// A float depth quantises z by about 3 / 2^24 near the far plane; the sphere's slope near its
// contour multiplies that.
constexpr double DepthTolerance = 1e-4;
} // namespace

TEST(SurfaceSketch, DepthImageReadsPixelsAndRefusesBadSizes)
{
  const Ball ball{ Vector3::Zero(), 1.0 };
  const DepthImage image = render({ ball });
  ASSERT_TRUE(image.surfacePoint(100, 100));
  EXPECT_NEAR(image.surfacePoint(100, 100)->z(), 1.0, DepthTolerance);
  EXPECT_FALSE(image.surfacePoint(2, 2));    // background
  EXPECT_FALSE(image.surfacePoint(-1, 100)); // off the image
  EXPECT_FALSE(image.surfacePoint(Size, 100));
  // Half a pixel beyond the first row or column rounds to -1: off the image, not before it.
  EXPECT_FALSE(image.depth(-0.5, 100));
  EXPECT_FALSE(image.depth(100, -0.5));
  EXPECT_FALSE(image.depth(Size - 0.5, 100));
  EXPECT_FALSE(image.depth(100, Size - 0.5));
  // A tracer walking off the image's edge ends its piece there.
  SurfaceStrokeTracer edge(image, 100, 100);
  edge.moveTo(-1.0, 101.0);
  edge.moveTo(-30.0, -30.0);
  EXPECT_EQ(edge.pieces().size(), 1u);
  EXPECT_FALSE(image.surfacePoint(std::nan(""), 100));
  EXPECT_NEAR(image.pixelSize(100, 100, 0.0), 2.0 * HalfWidth / Size, 1e-12);
  EXPECT_THROW(DepthImage(2, 2, std::vector<float>(3, 0.5f), orthographic()), Error);
  EXPECT_THROW(DepthImage(0, 2, {}, orthographic()), Error);
  EXPECT_THROW(DepthImage(1, 1, { 0.5f }, nullptr), Error);
}

TEST(SurfaceSketch, StrokeAcrossASphereStaysOnIt)
{
  const Ball ball{ Vector3::Zero(), 1.0 };
  const DepthImage image = render({ ball });
  // From the background on the left across the sphere to the background on the right, in two
  // moves (a fast mouse): one piece, every pixel of the way on the sphere.
  SurfaceStrokeTracer tracer(image, 10, 100);
  tracer.moveTo(100, 100);
  tracer.moveTo(190, 100);
  ASSERT_EQ(tracer.pieces().size(), 1u);
  const std::vector<Vector3>& piece = tracer.pieces()[0];
  EXPECT_GE(piece.size(), 125u); // about 133 pixels across the disc of radius 66.7 pixels
  for (const Vector3& p : piece)
  {
    EXPECT_LE(offSurface(p, ball), DepthTolerance * 50.0);
    EXPECT_NEAR(p.y(), 0.0, 1e-12);
  }
  EXPECT_LT(piece.front().x(), -0.95);
  EXPECT_GT(piece.back().x(), 0.95);
  EXPECT_DOUBLE_EQ(tracer.reach(), 180.0);
}

TEST(SurfaceSketch, StrokeIsSplitWhereItLeavesTheSurfaceOrCrossesAContour)
{
  // Two balls side by side with a gap: the stroke goes off the surface between them.
  const Ball left{ Vector3(-0.75, 0.0, 0.0), 0.6 };
  const Ball right{ Vector3(0.75, 0.0, 0.0), 0.6 };
  const DepthImage twoBalls = render({ left, right });
  SurfaceStrokeTracer apart(twoBalls, 40, 100);
  apart.moveTo(160, 100);
  // Every point of each piece on the ball it should be on.
  auto expectOn = [](const SurfaceStrokeTracer& tracer, const std::vector<Ball>& balls) {
    ASSERT_EQ(tracer.pieces().size(), balls.size());
    for (std::size_t i = 0; i < balls.size(); ++i)
    {
      for (const Vector3& p : tracer.pieces()[i])
      {
        EXPECT_LE(offSurface(p, balls[i]), 0.01) << "piece " << i;
      }
    }
  };
  expectOn(apart, { left, right });
  // A small ball in front of a large one: across the small one's contour the depth jumps, so the
  // stroke has three pieces (large, small, large) although it never leaves the surface.
  const Ball back{ Vector3(0.0, 0.0, -0.5), 1.0 };
  const Ball front{ Vector3(0.0, 0.0, 1.0), 0.3 };
  const DepthImage nested = render({ back, front });
  SurfaceStrokeTracer across(nested, 50, 100);
  across.moveTo(150, 100);
  expectOn(across, { back, front, back });
  // Pressed and released on the background: nothing.
  SurfaceStrokeTracer miss(nested, 3, 3);
  miss.moveTo(5, 4);
  EXPECT_TRUE(miss.pieces().empty());
  // A click on the surface: one piece of one point.
  SurfaceStrokeTracer click(nested, 100, 100);
  ASSERT_EQ(click.pieces().size(), 1u);
  EXPECT_EQ(click.pieces()[0].size(), 1u);
  EXPECT_EQ(click.reach(), 0.0);
}

TEST(SurfaceSketch, SimplificationKeepsEveryPointWithinTheTolerance)
{
  // A quarter circle of radius 1 sampled at 1,000 points: chords of angle a lie within
  // 1 - cos(a / 2) of the arc, so a tolerance of 1e-3 needs about 18 segments.
  std::vector<Vector3> arc;
  for (int i = 0; i <= 1000; ++i)
  {
    const double a = 0.5 * Pi * i / 1000.0;
    arc.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  const double tolerance = 1e-3;
  const std::vector<Vector3> simple = simplifyPolyline(arc, tolerance);
  EXPECT_EQ(simple.front(), arc.front());
  EXPECT_EQ(simple.back(), arc.back());
  const int expected = static_cast<int>(std::ceil(0.5 * Pi / (2.0 * std::acos(1.0 - tolerance))));
  EXPECT_GE(static_cast<int>(simple.size()) - 1, expected);
  EXPECT_LE(static_cast<int>(simple.size()) - 1, 2 * expected);
  for (const Vector3& p : arc)
  {
    double nearest = 1e9;
    for (std::size_t i = 0; i + 1 < simple.size(); ++i)
    {
      const Vector3 chord = simple[i + 1] - simple[i];
      const double t = std::clamp((p - simple[i]).dot(chord) / chord.squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (p - simple[i] - t * chord).norm());
    }
    EXPECT_LE(nearest, tolerance);
  }
  // A straight line keeps its ends; repeated points go; a corner stays.
  EXPECT_EQ(
    simplifyPolyline({ Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(1, 0, 0), Vector3(2, 0, 0) }, 1e-9).size(), 2u);
  EXPECT_EQ(simplifyPolyline({ Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(1, 1, 0) }, 1e-3).size(), 3u);
  EXPECT_EQ(simplifyPolyline({ Vector3(0, 0, 0), Vector3(0, 0, 0) }, 1e-3).size(), 1u);
  EXPECT_TRUE(simplifyPolyline({}, 1e-3).empty());
  // A negative or NaN tolerance is 0: every corner stays, and the simplification ends.
  EXPECT_EQ(simplifyPolyline({ Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(1, 1, 0) }, -5.0).size(), 3u);
  EXPECT_EQ(simplifyPolyline({ Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(2, 0, 0) }, std::nan("")).size(), 2u);
}

TEST(SurfaceSketch, DrawnStrokesSplitByTheirSizes)
{
  const std::vector<Vector3> points{ Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(2, 0, 0) };
  const std::vector<DrawnStroke> two = splitDrawnStrokes(points, { 1, 2 }, { 4, 0 });
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].points.size(), 1u);
  EXPECT_EQ(two[1].points[1], Vector3(2, 0, 0));
  EXPECT_EQ(two[0].label, 4);
  const std::vector<DrawnStroke> one = splitDrawnStrokes(points, {}, {});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].points.size(), 3u);
  EXPECT_EQ(one[0].label, 0);
  EXPECT_TRUE(splitDrawnStrokes({}, {}, {}).empty());
  EXPECT_THROW(splitDrawnStrokes(points, { 2, 2 }, {}), Error);
  EXPECT_THROW(splitDrawnStrokes(points, { 3, 0 }, {}), Error);
  EXPECT_THROW(splitDrawnStrokes(points, { 1, 2 }, { 1 }), Error);
}

TEST(SurfaceSketch, WalksAndRimsFollowGreatCircles)
{
  // Seen from above, a screen line through the sphere's centre is a great circle through its top:
  // the walk's length is the arc's angle (a little less: it sums chords), and the rim of a disc
  // around the top lies at that geodesic distance from it.
  const Ball ball{ Vector3::Zero(), 1.0 };
  const DepthImage image = render({ ball });
  const double angle = 0.6; // x = sin(0.6) = 0.565 is pixel 137.6
  const double pixel = 100.0 + std::sin(angle) / HalfWidth * 0.5 * Size;
  const SurfaceWalk walk = walkOnSurface(image, 100, 100, std::round(pixel), 100);
  EXPECT_TRUE(walk.started);
  EXPECT_TRUE(walk.reached);
  const double walked = std::asin(worldX(std::round(pixel)));
  EXPECT_NEAR(walk.length, walked, 0.01 * walked);
  // With a limit, the walk stops at it, between two pixels.
  const SurfaceWalk limited = walkOnSurface(image, 100, 100, 190, 100, SketchOptions(), 0.5);
  EXPECT_TRUE(limited.reached);
  EXPECT_DOUBLE_EQ(limited.length, 0.5);
  EXPECT_NEAR(std::acos(limited.end.normalized().z()), 0.5, 0.01);
  // Past the contour the walk leaves the sphere.
  const SurfaceWalk off = walkOnSurface(image, 100, 100, 199, 100);
  EXPECT_TRUE(off.started);
  EXPECT_FALSE(off.reached);
  EXPECT_GT(off.length, 1.3); // most of the quarter circle, pi / 2
  EXPECT_FALSE(walkOnSurface(image, 2, 2, 100, 100).started);

  // A drag's radius: the walk's length on the sphere; past the contour it goes on growing with
  // the screen distance at the contour's scale (a pixel there is 2 * 1.5 / 200 long).
  EXPECT_NEAR(dragRadius(image, 100, 100, std::round(pixel), 100), walk.length, 1e-12);
  const double atContour = dragRadius(image, 100, 100, 199, 100);
  EXPECT_NEAR(atContour, off.length + (199.0 - off.stopX) * 2.0 * HalfWidth / Size, 1e-9);
  EXPECT_GT(dragRadius(image, 100, 100, 230, 100), atContour);
  EXPECT_EQ(dragRadius(image, 2, 2, 100, 100), 0.0);

  const double radius = 0.5;
  const std::vector<Vector3> rim = discRim(image, 100, 100, radius, 32);
  ASSERT_EQ(rim.size(), 32u);
  for (const Vector3& p : rim)
  {
    EXPECT_LE(offSurface(p, ball), 0.01);
    EXPECT_NEAR(std::acos(std::clamp(p.normalized().z(), -1.0, 1.0)), radius, 0.02);
  }
  // A disc larger than what shows: its rim runs along the contour, where the walks leave the sphere.
  for (const Vector3& p : discRim(image, 100, 100, 3.0, 16))
  {
    EXPECT_GT(std::hypot(p.x(), p.y()), 0.97);
  }
  EXPECT_TRUE(discRim(image, 2, 2, radius).empty());
  EXPECT_TRUE(discRim(image, 100, 100, 0.0).empty());
}
