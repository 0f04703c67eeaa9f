// Convex hull, minimal-area bounding box and shelf packing of the charts' boxes.
#include "Parameterization/ChartPacking.h"

#include "Error.h"
#include "Mesh/Planar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <string>
#include <utility>

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

int countChartOverlaps(const std::vector<Vector2>& uv, const std::vector<Triangle>& triangles,
  const std::vector<int>& faceChart, int resolution)
{
  if (resolution < 1 || resolution > 65536)
  {
    throw Error("the overlap grid's resolution " + std::to_string(resolution) + " is outside [1, 65536]");
  }
  std::vector<int> owner(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution), -1);
  std::set<std::pair<int, int>> pairs;
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    Vector2 t[3];
    for (int k = 0; k < 3; ++k)
    {
      t[k] = uv[static_cast<std::size_t>(triangles[f][static_cast<std::size_t>(k)])] * resolution;
    }
    if (cross2(t[1] - t[0], t[2] - t[0]) < 0.0)
    {
      std::swap(t[1], t[2]);
    }
    const auto clampCell = [&](double value) {
      return static_cast<int>(std::min(std::max(std::floor(value), 0.0), static_cast<double>(resolution - 1)));
    };
    const int x0 = clampCell(std::min({ t[0].x(), t[1].x(), t[2].x() }));
    const int x1 = clampCell(std::max({ t[0].x(), t[1].x(), t[2].x() }));
    const int y0 = clampCell(std::min({ t[0].y(), t[1].y(), t[2].y() }));
    const int y1 = clampCell(std::max({ t[0].y(), t[1].y(), t[2].y() }));
    const int chart = faceChart[f];
    for (int y = y0; y <= y1; ++y)
    {
      for (int x = x0; x <= x1; ++x)
      {
        const Vector2 sample(x + 0.5, y + 0.5);
        if (cross2(t[1] - t[0], sample - t[0]) > 0.0 && cross2(t[2] - t[1], sample - t[1]) > 0.0 &&
          cross2(t[0] - t[2], sample - t[2]) > 0.0)
        {
          int& cell =
            owner[static_cast<std::size_t>(y) * static_cast<std::size_t>(resolution) + static_cast<std::size_t>(x)];
          if (cell >= 0 && cell != chart)
          {
            pairs.emplace(std::min(cell, chart), std::max(cell, chart));
          }
          cell = chart;
        }
      }
    }
  }
  return static_cast<int>(pairs.size());
}

} // namespace kerf
