// Convex hull, minimal-area bounding box and shelf packing of the charts' boxes.
#include "Parameterization/ChartPacking.h"

#include "Error.h"
#include "Mesh/Planar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace kerf
{
namespace
{

// Lays boxes on shelves in a square of side `side`; false if they do not fit.
bool shelfPack(const std::vector<Vector2>& sizes, const std::vector<int>& order, double side, double gap,
  std::vector<Vector2>& corners)
{
  double x = gap;
  double y = gap;
  double shelfHeight = 0.0;
  for (int i : order)
  {
    const Vector2& size = sizes[static_cast<std::size_t>(i)];
    if (x + size.x() + gap > side && x > gap)
    {
      y += shelfHeight + gap;
      x = gap;
      shelfHeight = 0.0;
    }
    if (x + size.x() + gap > side || y + size.y() + gap > side)
    {
      return false;
    }
    corners[static_cast<std::size_t>(i)] = Vector2(x, y);
    x += size.x() + gap;
    shelfHeight = std::max(shelfHeight, size.y());
  }
  return true;
}

} // namespace

std::vector<Vector2> convexHull(std::vector<Vector2> points)
{
  std::sort(points.begin(), points.end(),
    [](const Vector2& a, const Vector2& b) { return a.y() < b.y() || (a.y() == b.y() && a.x() < b.x()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3)
  {
    return points;
  }
  // Monotone chain over the points sorted by (y, x): right chain upwards, left chain downwards.
  std::vector<Vector2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    while (k >= 2 && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
  {
    while (k >= lower && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

double minimalBoundingBoxRotation(const std::vector<Vector2>& points)
{
  const std::vector<Vector2> hull = convexHull(points);
  double bestAngle = 0.0;
  double bestArea = std::numeric_limits<double>::infinity();
  Vector2 bestSize(0.0, 0.0);
  for (std::size_t e = 0; e < hull.size(); ++e)
  {
    const Vector2 edge = hull[(e + 1) % hull.size()] - hull[e];
    if (edge.squaredNorm() == 0.0)
    {
      continue;
    }
    const Vector2 along = edge.normalized();
    const Vector2 across(-along.y(), along.x());
    double minAlong = std::numeric_limits<double>::infinity(), maxAlong = -minAlong;
    double minAcross = minAlong, maxAcross = -minAlong;
    for (const Vector2& p : hull)
    {
      minAlong = std::min(minAlong, p.dot(along));
      maxAlong = std::max(maxAlong, p.dot(along));
      minAcross = std::min(minAcross, p.dot(across));
      maxAcross = std::max(maxAcross, p.dot(across));
    }
    const double area = (maxAlong - minAlong) * (maxAcross - minAcross);
    // A relative tolerance keeps the choice among equal boxes (a rectangle's four sides) stable.
    if (area < bestArea * (1.0 - 1e-12))
    {
      bestArea = area;
      bestAngle = -std::atan2(along.y(), along.x());
      bestSize = Vector2(maxAlong - minAlong, maxAcross - minAcross);
    }
  }
  if (bestSize.y() > bestSize.x())
  {
    bestAngle += 0.5 * M_PI;
  }
  return bestAngle;
}

std::vector<Vector2> packBoxes(const std::vector<Vector2>& sizes, double margin, double& scale)
{
  if (!(margin >= 0.0 && margin <= 0.25))
  {
    throw Error("the margin between charts is " + std::to_string(margin) + ", outside [0, 0.25]");
  }
  double area = 0.0;
  double widest = 0.0;
  for (const Vector2& size : sizes)
  {
    if (!size.allFinite() || size.minCoeff() < 0.0)
    {
      throw Error("a chart's bounding box has a negative or non-finite size");
    }
    area += size.x() * size.y();
    widest = std::max(widest, size.maxCoeff());
  }
  std::vector<Vector2> corners(sizes.size(), Vector2::Zero());
  if (sizes.empty() || widest == 0.0)
  {
    scale = 1.0;
    return corners;
  }
  std::vector<int> order(sizes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const Vector2& sa = sizes[static_cast<std::size_t>(a)];
    const Vector2& sb = sizes[static_cast<std::size_t>(b)];
    return sa.y() > sb.y() || (sa.y() == sb.y() && sa.x() > sb.x());
  });
  // No square smaller than the boxes' total area or the widest box (with the margins) can hold them.
  double side = std::max(std::sqrt(area), widest) / (1.0 - 2.0 * margin);
  while (!shelfPack(sizes, order, side, margin * side, corners))
  {
    side *= 1.01;
  }
  scale = 1.0 / side;
  for (Vector2& corner : corners)
  {
    corner *= scale;
  }
  return corners;
}

} // namespace kerf
