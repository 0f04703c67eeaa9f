// Screen samples on a depth image taken back to space: stroke pieces split at the background and at depth jumps,
// simplification, walks and disc rims.
#include "Sketch/SurfaceSketch.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace kerf
{

DepthImage::DepthImage(int width, int height, std::vector<float> depth, Unprojection unproject)
  : Width(width)
  , Height(height)
  , Depth(std::move(depth))
  , Unproject(std::move(unproject))
{
  if (width < 1 || height < 1 ||
    this->Depth.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
  {
    throw Error("a depth image needs width x height values");
  }
  if (!this->Unproject)
  {
    throw Error("a depth image needs its unprojection");
  }
}

std::optional<double> DepthImage::depth(double x, double y) const
{
  // The nearest pixel of (x, y) must be on the image: lround(-0.5) is -1.
  if (!(x > -0.5 && y > -0.5 && x < this->Width - 0.5 && y < this->Height - 0.5))
  {
    return std::nullopt;
  }
  auto at = [this](int column, int row) {
    return this
      ->Depth[static_cast<std::size_t>(row) * static_cast<std::size_t>(this->Width) + static_cast<std::size_t>(column)];
  };
  // Bilinear between the four pixels around (x, y) where all four show the surface, so that a
  // walk's steps follow the surface smoothly in any direction; else the nearest pixel.
  const int column = static_cast<int>(std::floor(x));
  const int row = static_cast<int>(std::floor(y));
  if (column >= 0 && row >= 0 && column + 1 < this->Width && row + 1 < this->Height)
  {
    const float corners[4] = { at(column, row), at(column + 1, row), at(column, row + 1), at(column + 1, row + 1) };
    if (corners[0] < 1.0f && corners[1] < 1.0f && corners[2] < 1.0f && corners[3] < 1.0f)
    {
      const double fx = x - column;
      const double fy = y - row;
      return (1.0 - fy) * ((1.0 - fx) * corners[0] + fx * corners[1]) +
        fy * ((1.0 - fx) * corners[2] + fx * corners[3]);
    }
  }
  const float nearest = at(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)));
  if (!(nearest < 1.0f))
  {
    return std::nullopt;
  }
  return static_cast<double>(nearest);
}

DepthImage::Unprojection DepthImage::projective(const Eigen::Matrix4d& displayToWorld)
{
  return [displayToWorld](double x, double y, double depth) {
    const Eigen::Vector4d world = displayToWorld * Eigen::Vector4d(x, y, depth, 1.0);
    return world[3] != 0.0 ? Vector3(world.head<3>() / world[3]) : Vector3(world.head<3>());
  };
}

std::optional<Vector3> DepthImage::surfacePoint(double x, double y) const
{
  const std::optional<double> value = this->depth(x, y);
  if (!value)
  {
    return std::nullopt;
  }
  return this->Unproject(x, y, *value);
}

double DepthImage::pixelSize(double x, double y, double depth) const
{
  return (this->Unproject(x + 1.0, y, depth) - this->Unproject(x, y, depth)).norm();
}

namespace
{
// Whether the step from `previous` to `next`, `pixels` apart on the screen, leaves one part of the
// surface for another (an occluding contour) rather than running along it.
bool jumps(const DepthImage& image, double x, double y, double depth, const Vector3& previous, const Vector3& next,
  double pixels, const SketchOptions& options)
{
  return (next - previous).norm() > options.jumpFactor * std::max(pixels, 1.0) * image.pixelSize(x, y, depth);
}

// The number of steps that walk a screen segment `length` pixels long.
int stepCount(double length, const SketchOptions& options)
{
  if (!(length > 0.0))
  {
    return 0;
  }
  const double step = options.step > 0.0 ? options.step : 1.0;
  return static_cast<int>(std::min(std::ceil(length / step), 1e6));
}
} // namespace

SurfaceStrokeTracer::SurfaceStrokeTracer(const DepthImage& image, double x, double y, const SketchOptions& options)
  : Image(image)
  , Options(options)
  , StartX(x)
  , StartY(y)
  , LastX(x)
  , LastY(y)
{
  this->sample(x, y);
}

void SurfaceStrokeTracer::moveTo(double x, double y)
{
  const double dx = x - this->LastX;
  const double dy = y - this->LastY;
  const int steps = stepCount(std::hypot(dx, dy), this->Options);
  const double fromX = this->LastX;
  const double fromY = this->LastY;
  for (int i = 1; i <= steps; ++i)
  {
    this->sample(fromX + dx * i / steps, fromY + dy * i / steps);
  }
  this->Reach = std::max(this->Reach, std::hypot(x - this->StartX, y - this->StartY));
}

void SurfaceStrokeTracer::sample(double x, double y)
{
  const double pixels = std::hypot(x - this->LastX, y - this->LastY);
  this->LastX = x;
  this->LastY = y;
  const std::optional<double> depth = this->Image.depth(x, y);
  if (!depth)
  {
    this->OnSurface = false;
    return;
  }
  const Vector3 point = *this->Image.surfacePoint(x, y);
  bool jumped = false;
  if (this->OnSurface)
  {
    const Vector3& previous = this->Pieces.back().back();
    jumped = jumps(this->Image, x, y, *depth, previous, point, pixels, this->Options);
    if (!jumped)
    {
      if (point != previous)
      {
        this->Pieces.back().push_back(point);
      }
      return;
    }
    // A single sample between two jumps lies between the two parts of the surface (the depth
    // interpolated across a contour): it belongs to neither.
    if (this->StartedByJump && this->Pieces.back().size() == 1)
    {
      this->Pieces.pop_back();
    }
  }
  this->Pieces.push_back({ point });
  this->OnSurface = true;
  this->StartedByJump = jumped;
}

std::vector<Vector3> simplifyPolyline(const std::vector<Vector3>& points, double tolerance)
{
  tolerance = tolerance > 0.0 ? tolerance : 0.0; // NaN as well
  std::vector<Vector3> distinct;
  for (const Vector3& p : points)
  {
    if (distinct.empty() || p != distinct.back())
    {
      distinct.push_back(p);
    }
  }
  if (distinct.size() < 3)
  {
    return distinct;
  }
  std::vector<char> kept(distinct.size(), 0);
  kept.front() = kept.back() = 1;
  std::vector<std::pair<std::size_t, std::size_t>> spans{ { 0, distinct.size() - 1 } };
  while (!spans.empty())
  {
    const auto [first, last] = spans.back();
    spans.pop_back();
    if (last <= first + 1)
    {
      continue; // no point between the ends
    }
    const Vector3& a = distinct[first];
    const Vector3 chord = distinct[last] - a;
    const double chordLength = chord.squaredNorm();
    double farthest = -1.0;
    std::size_t at = first;
    for (std::size_t i = first + 1; i < last; ++i)
    {
      const Vector3 offset = distinct[i] - a;
      const double t = chordLength > 0.0 ? std::clamp(offset.dot(chord) / chordLength, 0.0, 1.0) : 0.0;
      const double distance = (offset - t * chord).norm();
      if (distance > farthest)
      {
        farthest = distance;
        at = i;
      }
    }
    if (farthest > tolerance)
    {
      kept[at] = 1;
      spans.emplace_back(first, at);
      spans.emplace_back(at, last);
    }
  }
  std::vector<Vector3> simplified;
  for (std::size_t i = 0; i < distinct.size(); ++i)
  {
    if (kept[i])
    {
      simplified.push_back(distinct[i]);
    }
  }
  return simplified;
}

SurfaceWalk walkOnSurface(
  const DepthImage& image, double x0, double y0, double x1, double y1, const SketchOptions& options, double limit)
{
  SurfaceWalk walk;
  const std::optional<Vector3> start = image.surfacePoint(x0, y0);
  if (!start)
  {
    return walk;
  }
  walk.started = true;
  walk.end = *start;
  walk.stopX = x0;
  walk.stopY = y0;
  walk.stopDepth = *image.depth(x0, y0);
  const double dx = x1 - x0;
  const double dy = y1 - y0;
  const int steps = stepCount(std::hypot(dx, dy), options);
  const double pixels = steps > 0 ? std::hypot(dx, dy) / steps : 0.0;
  for (int i = 1; i <= steps; ++i)
  {
    const double x = x0 + dx * i / steps;
    const double y = y0 + dy * i / steps;
    const std::optional<double> depth = image.depth(x, y);
    if (!depth)
    {
      return walk;
    }
    const Vector3 point = *image.surfacePoint(x, y);
    if (jumps(image, x, y, *depth, walk.end, point, pixels, options))
    {
      return walk;
    }
    const double step = (point - walk.end).norm();
    if (limit >= 0.0 && walk.length + step >= limit)
    {
      const double fraction = step > 0.0 ? (limit - walk.length) / step : 0.0;
      walk.end += fraction * (point - walk.end);
      walk.length = limit;
      walk.reached = true;
      return walk;
    }
    walk.length += step;
    walk.end = point;
    walk.stopX = x;
    walk.stopY = y;
    walk.stopDepth = *depth;
  }
  walk.reached = true;
  return walk;
}

double dragRadius(const DepthImage& image, double x0, double y0, double x1, double y1, const SketchOptions& options)
{
  const SurfaceWalk walk = walkOnSurface(image, x0, y0, x1, y1, options);
  if (!walk.started)
  {
    return 0.0;
  }
  if (walk.reached)
  {
    return walk.length;
  }
  return walk.length +
    std::hypot(x1 - walk.stopX, y1 - walk.stopY) * image.pixelSize(walk.stopX, walk.stopY, walk.stopDepth);
}

std::vector<Vector3> discRim(
  const DepthImage& image, double x, double y, double radius, int directions, const SketchOptions& options)
{
  std::vector<Vector3> rim;
  if (!image.surfacePoint(x, y) || !(radius > 0.0) || directions < 3)
  {
    return rim;
  }
  // Far enough to leave the image in any direction: the walk stops there if not before.
  const double far = static_cast<double>(image.width()) + image.height();
  constexpr double Pi = 3.14159265358979323846;
  for (int i = 0; i < directions; ++i)
  {
    const double angle = 2.0 * Pi * i / directions;
    rim.push_back(
      walkOnSurface(image, x, y, x + far * std::cos(angle), y + far * std::sin(angle), options, radius).end);
  }
  return rim;
}

std::vector<DrawnStroke> splitDrawnStrokes(
  const std::vector<Vector3>& points, const std::vector<int>& givenSizes, const std::vector<int>& labels)
{
  std::vector<int> sizes = givenSizes;
  if (sizes.empty() && !points.empty())
  {
    sizes.push_back(static_cast<int>(points.size()));
  }
  long long total = 0;
  for (std::size_t s = 0; s < sizes.size(); ++s)
  {
    if (sizes[s] < 1)
    {
      throw Error("drawn stroke " + std::to_string(s) + " has " + std::to_string(sizes[s]) +
        " points (DrawnStrokeSizes); every stroke has at least one");
    }
    total += sizes[s];
  }
  if (total != static_cast<long long>(points.size()))
  {
    throw Error("the drawn strokes' sizes (DrawnStrokeSizes) add up to " + std::to_string(total) + " points, but " +
      std::to_string(points.size()) + " are drawn (DrawnStrokePoints)");
  }
  if (!labels.empty() && labels.size() != sizes.size())
  {
    throw Error("there are " + std::to_string(labels.size()) + " drawn stroke labels (DrawnStrokeLabels) for " +
      std::to_string(sizes.size()) + " strokes");
  }
  std::vector<DrawnStroke> strokes(sizes.size());
  std::size_t next = 0;
  for (std::size_t s = 0; s < sizes.size(); ++s)
  {
    strokes[s].points.assign(points.begin() + static_cast<std::ptrdiff_t>(next),
      points.begin() + static_cast<std::ptrdiff_t>(next + static_cast<std::size_t>(sizes[s])));
    strokes[s].label = labels.empty() ? 0 : labels[s];
    next += static_cast<std::size_t>(sizes[s]);
  }
  return strokes;
}

} // namespace kerf
