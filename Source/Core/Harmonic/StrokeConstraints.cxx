// Stroke resampling, projection and the +/- offsets of SeamCut's constraints.
#include "Harmonic/StrokeConstraints.h"

#include "Error.h"
#include "Mesh/MeshValidation.h"

#include <cmath>
#include <string>

namespace kerf
{

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
      throw Error(what + " is " + std::to_string(hit.distance) +
        " away from the surface, farther than the allowed " + std::to_string(options.maximumDistance));
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
        throw Error("stroke " + std::to_string(s) + " has a point with NaN, infinite or huge coordinates (beyond +-1e50)");
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
    const double offset =
      options.offsetLengthFraction > 0.0 ? std::min(options.offset, options.offsetLengthFraction * length) : options.offset;
    for (std::size_t j = 0; j + 1 < stroke.size(); ++j)
    {
      const Vector3 direction = stroke[j + 1] - stroke[j];
      if (direction.squaredNorm() == 0.0)
      {
        continue;
      }
      for (int k = 0; k < options.samplesPerSegment; ++k)
      {
        const double t = (k + 0.5) / options.samplesPerSegment;
        const std::string name = "stroke " + std::to_string(s) + " point " + std::to_string(j);
        const ClosestPointLocator::Hit sample = project(stroke[j] + t * direction, name);
        const Triangle& tri = mesh.triangle(sample.face);
        Vector3 normal = sample.barycentric[0] * vertexNormals[tri[0]] +
          sample.barycentric[1] * vertexNormals[tri[1]] + sample.barycentric[2] * vertexNormals[tri[2]];
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
