// Stroke resampling, projection and the +/- offsets of SeamCut's constraints.
#include "Harmonic/StrokeConstraints.h"

#include "Error.h"
#include "Mesh/MeshValidation.h"

#include <cmath>
#include <string>

namespace kerf
{

namespace
{
// Bisections of a segment whose chord leaves the surface: enough for a chord across a sixth of a
// sphere to follow it within a thousandth of its radius.
constexpr int FollowDepth = 12;

// The vertex normals interpolated at a surface point (unnormalised; zero where they cancel).
Vector3 interpolatedNormal(
  const TriangleMesh& mesh, const std::vector<Vector3>& vertexNormals, const ClosestPointLocator::Hit& hit)
{
  const Triangle& tri = mesh.triangle(hit.face);
  return hit.barycentric[0] * vertexNormals[tri[0]] + hit.barycentric[1] * vertexNormals[tri[1]] +
    hit.barycentric[2] * vertexNormals[tri[2]];
}

struct PathFollower
{
  const TriangleMesh& mesh;
  const ClosestPointLocator& locator;
  const std::vector<Vector3>& vertexNormals;
  double tolerance;

  // Appends the way from `a` to `b` (both on the surface) to `path`, which ends at `a`: their
  // chord if its midpoint is within the tolerance of the surface; otherwise the surface point
  // under the midpoint, seen along the ends' mean normal (the nearest surface point to the
  // midpoint moved along that normal, projected again), and each half in turn.
  void follow(
    const ClosestPointLocator::Hit& a, const ClosestPointLocator::Hit& b, int depth, std::vector<Vector3>& path) const
  {
    const Vector3 middle = 0.5 * (a.position + b.position);
    ClosestPointLocator::Hit hit = this->locator.closest(middle);
    if (depth == 0 || hit.distance <= this->tolerance)
    {
      if (b.position != path.back())
      {
        path.push_back(b.position);
      }
      return;
    }
    const Vector3 normal =
      interpolatedNormal(this->mesh, this->vertexNormals, a) + interpolatedNormal(this->mesh, this->vertexNormals, b);
    if (normal.squaredNorm() > 0.0)
    {
      const Vector3 n = normal.normalized();
      hit = this->locator.closest(middle + (hit.position - middle).dot(n) * n);
    }
    this->follow(a, hit, depth - 1, path);
    this->follow(hit, b, depth - 1, path);
  }
};

// The way along which a stroke segment from `a` to `b` is sampled: their chord while its samples
// stay within the allowed distance of the surface (as a stroke drawn on the surface and sampled
// densely does); otherwise followed along the surface (PathFollower) until each piece's midpoint
// is within half the allowed distance.
std::vector<Vector3> segmentPath(const TriangleMesh& mesh, const ClosestPointLocator& locator,
  const std::vector<Vector3>& vertexNormals, const Vector3& a, const Vector3& b, const StrokeOptions& options)
{
  std::vector<Vector3> path{ a, b };
  if (!(options.maximumDistance > 0.0))
  {
    return path;
  }
  bool leaves = false;
  for (int k = 0; k < options.samplesPerSegment && !leaves; ++k)
  {
    const double t = (k + 0.5) / options.samplesPerSegment;
    leaves = locator.closest(a + t * (b - a)).distance > options.maximumDistance;
  }
  if (!leaves)
  {
    return path;
  }
  const ClosestPointLocator::Hit start = locator.closest(a);
  path = { start.position };
  const PathFollower follower{ mesh, locator, vertexNormals, 0.5 * options.maximumDistance };
  follower.follow(start, locator.closest(b), FollowDepth, path);
  return path;
}
} // namespace

StrokeConstraintSet strokeConstraints(const TriangleMesh& mesh, const ClosestPointLocator& locator,
  const std::vector<Vector3>& vertexNormals, const std::vector<std::vector<Vector3>>& strokes,
  const StrokeOptions& options)
{
  if (options.samplesPerSegment < 1)
  {
    throw Error("a stroke needs at least one sample per segment");
  }
  if (!(options.offset > 0.0) || !std::isfinite(options.offset))
  {
    throw Error("the constraint offset must be a positive length");
  }
  StrokeConstraintSet out;
  auto project = [&](const Vector3& p, const std::string& what) {
    const ClosestPointLocator::Hit hit = locator.closest(p);
    if (hit.face < 0)
    {
      throw Error("the mesh has no triangles");
    }
    if (options.maximumDistance > 0.0 && hit.distance > options.maximumDistance)
    {
      throw Error(what + " is " + std::to_string(hit.distance) + " away from the surface, farther than the allowed " +
        std::to_string(options.maximumDistance));
    }
    return hit;
  };
  for (std::size_t s = 0; s < strokes.size(); ++s)
  {
    const std::vector<Vector3>& stroke = strokes[s];
    for (const Vector3& p : stroke)
    {
      if (!p.allFinite() || p.cwiseAbs().maxCoeff() > CoordinateLimit)
      {
        throw Error(
          "stroke " + std::to_string(s) + " has a point with NaN, infinite or huge coordinates (beyond +-1e50)");
      }
    }
    bool distinct = false;
    for (std::size_t j = 1; j < stroke.size(); ++j)
    {
      distinct = distinct || stroke[j] != stroke[0];
    }
    if (!distinct)
    {
      throw Error("stroke " + std::to_string(s) + " needs at least two distinct points");
    }
    double length = 0.0;
    for (std::size_t j = 0; j + 1 < stroke.size(); ++j)
    {
      length += (stroke[j + 1] - stroke[j]).norm();
    }
    const double offset = options.offsetLengthFraction > 0.0
      ? std::min(options.offset, options.offsetLengthFraction * length)
      : options.offset;
    for (std::size_t j = 0; j < stroke.size(); ++j)
    {
      project(stroke[j], "stroke " + std::to_string(s) + " point " + std::to_string(j));
    }
    for (std::size_t j = 0; j + 1 < stroke.size(); ++j)
    {
      if (stroke[j + 1] == stroke[j])
      {
        continue;
      }
      const std::string name = "stroke " + std::to_string(s) + " point " + std::to_string(j);
      const std::vector<Vector3> path = segmentPath(mesh, locator, vertexNormals, stroke[j], stroke[j + 1], options);
      if (path.size() < 2)
      {
        continue; // both ends project onto the same surface point
      }
      std::vector<double> arc(path.size(), 0.0);
      for (std::size_t i = 1; i < path.size(); ++i)
      {
        arc[i] = arc[i - 1] + (path[i] - path[i - 1]).norm();
      }
      std::size_t piece = 0;
      for (int k = 0; k < options.samplesPerSegment; ++k)
      {
        const double along = arc.back() * (k + 0.5) / options.samplesPerSegment;
        while (piece + 2 < path.size() && arc[piece + 1] < along)
        {
          ++piece;
        }
        const Vector3 direction = path[piece + 1] - path[piece];
        // A chord is sampled at its fractions exactly; a followed path at its arc lengths.
        const double within = path.size() == 2 ? (k + 0.5) / options.samplesPerSegment
                                               : (along - arc[piece]) / (arc[piece + 1] - arc[piece]);
        const ClosestPointLocator::Hit sample = project(path[piece] + within * direction, name);
        const Triangle& tri = mesh.triangle(sample.face);
        Vector3 normal = interpolatedNormal(mesh, vertexNormals, sample);
        if (normal.squaredNorm() == 0.0)
        {
          normal = (mesh.point(tri[1]) - mesh.point(tri[0])).cross(mesh.point(tri[2]) - mesh.point(tri[0]));
        }
        const Vector3 side = normal.cross(direction);
        if (!(side.norm() > 1e-12 * normal.norm() * direction.norm()))
        {
          continue; // the stroke runs along the normal here
        }
        const Vector3 d = side.normalized();
        out.strokeSamples.push_back(sample.position);
        for (const double sign : { 1.0, -1.0 })
        {
          const ClosestPointLocator::Hit hit = locator.closest(sample.position + sign * offset * d);
          SoftConstraint c;
          c.face = hit.face;
          c.barycentric = hit.barycentric;
          c.value = options.isoValue + sign;
          out.constraints.push_back(c);
          out.positions.push_back(hit.position);
        }
      }
    }
  }
  if (out.constraints.empty())
  {
    throw Error("the strokes give no constraint");
  }
  return out;
}

} // namespace kerf
