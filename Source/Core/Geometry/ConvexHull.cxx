// The incremental convex hull in 3D: visible faces replaced by a cone from each new point to its horizon.
#include "Geometry/ConvexHull.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>

namespace kerf
{

namespace
{
struct Face
{
  Triangle corners;
  Vector3 normal;
  double offset = 0.0;
  bool alive = true;
};

Face makeFace(const std::vector<Vector3>& points, int a, int b, int c)
{
  Face face;
  face.corners = { a, b, c };
  const Vector3 n = (points[b] - points[a]).cross(points[c] - points[a]);
  const double length = n.norm();
  face.normal = length > 0.0 ? Vector3(n / length) : Vector3::Zero();
  face.offset = face.normal.dot(points[a]);
  return face;
}

// The index of the point that maximises `score` (the first of equals), or -1 for none above `floor`.
template <typename Score>
int farthest(int count, double floor, Score&& score)
{
  int best = -1;
  double bestScore = floor;
  for (int i = 0; i < count; ++i)
  {
    const double s = score(i);
    if (s > bestScore)
    {
      best = i;
      bestScore = s;
    }
  }
  return best;
}
} // namespace

ConvexHull convexHull(const std::vector<Vector3>& points, double tolerance)
{
  if (!std::isfinite(tolerance) || tolerance < 0.0)
  {
    throw Error("the convex hull's tolerance must be a finite number of at least 0");
  }
  for (const Vector3& p : points)
  {
    if (!p.allFinite())
    {
      throw Error("the convex hull's points must be finite");
    }
  }
  ConvexHull hull;
  hull.flat = true;
  const int n = static_cast<int>(points.size());
  if (n < 4)
  {
    return hull;
  }
  // The initial tetrahedron: the lowest x, the point farthest from it, from their line, from their plane.
  const int p0 = farthest(n, -std::numeric_limits<double>::infinity(), [&](int i) { return -points[i].x(); });
  const int p1 = farthest(n, tolerance, [&](int i) { return (points[i] - points[p0]).norm(); });
  if (p1 < 0)
  {
    return hull;
  }
  const Vector3 axis = (points[p1] - points[p0]).normalized();
  const int p2 = farthest(n, tolerance, [&](int i) {
    const Vector3 d = points[i] - points[p0];
    return (d - d.dot(axis) * axis).norm();
  });
  if (p2 < 0)
  {
    return hull;
  }
  const Vector3 planeNormal = axis.cross(points[p2] - points[p0]).normalized();
  const int p3 = farthest(n, tolerance, [&](int i) { return std::abs(planeNormal.dot(points[i] - points[p0])); });
  if (p3 < 0)
  {
    return hull;
  }
  hull.flat = false;
  double extent = 0.0;
  for (const Vector3& p : points)
  {
    extent = std::max(extent, (p - points[p0]).cwiseAbs().maxCoeff());
  }
  const double roundoff = 1e-12 * extent;

  std::vector<Face> faces;
  const bool above = planeNormal.dot(points[p3] - points[p0]) > 0.0;
  // Oriented so that the fourth point lies behind each face.
  if (above)
  {
    faces = { makeFace(points, p0, p2, p1), makeFace(points, p0, p1, p3), makeFace(points, p1, p2, p3),
      makeFace(points, p2, p0, p3) };
  }
  else
  {
    faces = { makeFace(points, p0, p1, p2), makeFace(points, p0, p3, p1), makeFace(points, p1, p3, p2),
      makeFace(points, p2, p3, p0) };
  }

  std::vector<int> visible;
  std::set<std::pair<int, int>> visibleEdges;
  for (int i = 0; i < n; ++i)
  {
    if (i == p0 || i == p1 || i == p2 || i == p3)
    {
      continue;
    }
    // A point within the tolerance of the hull is taken as inside; one beyond it replaces every
    // face it sees at all (a face seen only beyond the tolerance would leave the hull non-convex).
    double height = -std::numeric_limits<double>::infinity();
    visible.clear();
    for (int f = 0; f < static_cast<int>(faces.size()); ++f)
    {
      if (faces[f].alive)
      {
        const double h = faces[f].normal.dot(points[i]) - faces[f].offset;
        height = std::max(height, h);
        if (h > roundoff)
        {
          visible.push_back(f);
        }
      }
    }
    if (!(height > tolerance) || visible.empty())
    {
      continue;
    }
    visibleEdges.clear();
    for (int f : visible)
    {
      const Triangle& c = faces[f].corners;
      for (int k = 0; k < 3; ++k)
      {
        visibleEdges.emplace(c[k], c[(k + 1) % 3]);
      }
      faces[f].alive = false;
    }
    // The horizon: edges of visible faces whose other face is not visible, kept in their direction.
    for (const auto& [a, b] : visibleEdges)
    {
      if (visibleEdges.count({ b, a }) == 0)
      {
        faces.push_back(makeFace(points, a, b, i));
      }
    }
  }
  for (const Face& face : faces)
  {
    if (face.alive)
    {
      hull.faces.push_back(face.corners);
      hull.normals.push_back(face.normal);
      hull.offsets.push_back(face.offset);
    }
  }
  return hull;
}

std::vector<double> hullDepths(const ConvexHull& hull, const std::vector<Vector3>& points)
{
  std::vector<double> depths(points.size(), 0.0);
  if (hull.flat)
  {
    return depths;
  }
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    double depth = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < hull.faces.size(); ++f)
    {
      depth = std::min(depth, hull.offsets[f] - hull.normals[f].dot(points[i]));
    }
    depths[i] = std::max(depth, 0.0);
  }
  return depths;
}

double largestHullDepthFraction(const std::vector<Vector3>& points, int maximumSamples)
{
  if (maximumSamples < 4)
  {
    throw Error("the hull depth needs at least 4 samples, got " + std::to_string(maximumSamples));
  }
  const std::size_t n = points.size();
  const std::size_t stride = (n + maximumSamples - 1) / static_cast<std::size_t>(maximumSamples);
  std::vector<Vector3> samples;
  for (std::size_t i = 0; i < n; i += std::max<std::size_t>(stride, 1))
  {
    samples.push_back(points[i]);
  }
  if (samples.empty())
  {
    return 0.0;
  }
  Vector3 lowest = samples.front(), highest = samples.front();
  for (const Vector3& p : samples)
  {
    if (!p.allFinite())
    {
      throw Error("the convex hull's points must be finite");
    }
    lowest = lowest.cwiseMin(p);
    highest = highest.cwiseMax(p);
  }
  const double diagonal = (highest - lowest).norm();
  if (diagonal == 0.0)
  {
    return 0.0;
  }
  // Points within 1e-9 of the diagonal of a hull plane count as on it (rounding, not geometry).
  const ConvexHull hull = convexHull(samples, 1e-9 * diagonal);
  const std::vector<double> depths = hullDepths(hull, samples);
  return *std::max_element(depths.begin(), depths.end()) / diagonal;
}

} // namespace kerf
