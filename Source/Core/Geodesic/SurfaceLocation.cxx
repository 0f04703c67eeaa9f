// Points and polylines placed on a surface: projection with the locator, and segments followed across triangles.
#include "Geodesic/SurfaceLocation.h"

#include "Error.h"
#include "Geometry/ClosestPoint.h"
#include "Mesh/MeshValidation.h"
#include "Surface/Surface.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf
{

SurfacePoint projectOntoSurface(
  const Surface& surface, const Vector3& position, double maximumDistance, const std::string& what)
{
  if (!position.allFinite() || position.cwiseAbs().maxCoeff() > CoordinateLimit)
  {
    throw Error(what + " has a NaN, infinite or huge coordinate");
  }
  const ClosestPointLocator::Hit hit = surface.locator().closest(position);
  if (hit.face < 0)
  {
    throw Error(what + " cannot be placed on a mesh without triangles");
  }
  if (hit.distance > maximumDistance)
  {
    throw Error(what + " lies off the surface: " + std::to_string(hit.distance) +
      " from its nearest point, farther than the allowed " + std::to_string(maximumDistance));
  }
  SurfacePoint point;
  point.face = hit.face;
  point.barycentric = hit.barycentric;
  return point;
}

int coincidentVertex(const TriangleMesh& mesh, const SurfacePoint& point, double tolerance)
{
  for (int k = 0; k < 3; ++k)
  {
    if (point.barycentric[k] >= 1.0 - tolerance)
    {
      return mesh.triangle(point.face)[k];
    }
  }
  return -1;
}

std::vector<int> facesHolding(const TriangleMesh& mesh, const SurfacePoint& point, double tolerance)
{
  std::vector<int> faces{ point.face };
  const Triangle& t = mesh.triangle(point.face);
  for (int k = 0; k < 3; ++k)
  {
    if (point.barycentric[k] >= 1.0 - tolerance)
    {
      faces.insert(faces.end(), mesh.vertexFaces(t[k]).begin(), mesh.vertexFaces(t[k]).end());
    }
    // Edge k joins corners k and k + 1: the point is on it when the third coordinate is 0.
    const int across = mesh.faceNeighbor(point.face, k);
    if (point.barycentric[(k + 2) % 3] <= tolerance && across >= 0)
    {
      faces.push_back(across);
    }
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

namespace
{
Vector3 faceNormal(const TriangleMesh& mesh, int f)
{
  const Triangle& t = mesh.triangle(f);
  return (mesh.point(t[1]) - mesh.point(t[0])).cross(mesh.point(t[2]) - mesh.point(t[0])).normalized();
}

// Where the plane {x : m . (x - origin) = 0} crosses edge k of face f, if it does; a corner on
// the plane counts as on its positive side, so every face is crossed on zero or two edges.
bool crossEdge(const TriangleMesh& mesh, int f, int k, const Vector3& m, const Vector3& origin, Vector3& crossing)
{
  const Vector3& p = mesh.point(mesh.triangle(f)[k]);
  const Vector3& q = mesh.point(mesh.triangle(f)[(k + 1) % 3]);
  const double sp = m.dot(p - origin), sq = m.dot(q - origin);
  if ((sp >= 0.0) == (sq >= 0.0))
  {
    return false;
  }
  crossing = p + (sp / (sp - sq)) * (q - p);
  return true;
}

// The edge of face g that face f lies across edge k of f.
int entryEdge(const TriangleMesh& mesh, int f, int k, int g)
{
  for (int j = 0; j < 3; ++j)
  {
    if (mesh.faceEdge(g, j) == mesh.faceEdge(f, k))
    {
      return j;
    }
  }
  return -1;
}

// Appends the segment from `a` (already the curve's last point) to `b` to the curve: the faces
// holding each piece and the crossing points in between, not `b` itself.
void followSegment(const TriangleMesh& mesh, const SurfacePoint& a, const SurfacePoint& b, int index,
  const std::string& what, SurfaceCurve& curve)
{
  const std::vector<int> fromFaces = facesHolding(mesh, a);
  const std::vector<int> toFaces = facesHolding(mesh, b);
  for (int f : fromFaces)
  {
    if (std::binary_search(toFaces.begin(), toFaces.end(), f))
    {
      curve.faces.push_back(f);
      return;
    }
  }
  const std::string segment = "segment " + std::to_string(index) + " of " + what;
  if (mesh.faceComponent(a.face) != mesh.faceComponent(b.face))
  {
    throw Error(segment + " joins two connected components of the mesh");
  }
  const Vector3 xa = surfacePosition(mesh, a);
  const Vector3 xb = surfacePosition(mesh, b);
  const Vector3 d = xb - xa;
  Vector3 normal = faceNormal(mesh, a.face) + faceNormal(mesh, b.face);
  if (normal.norm() < 1e-6)
  {
    normal = faceNormal(mesh, a.face);
  }
  const Vector3 m = d.cross(normal);
  if (!(m.norm() > 1e-12 * d.norm()) || !m.allFinite())
  {
    throw Error(segment + " runs along the surface normal; give more points along the line");
  }
  const Vector3 planeNormal = m.normalized();

  // The first crossing: the one farthest towards b from the triangles holding a.
  int face = -1, edge = -1;
  Vector3 crossing;
  double progress = -std::numeric_limits<double>::infinity();
  for (int f : fromFaces)
  {
    for (int k = 0; k < 3; ++k)
    {
      Vector3 x;
      if (crossEdge(mesh, f, k, planeNormal, xa, x) && d.dot(x - xa) > progress)
      {
        progress = d.dot(x - xa);
        face = f;
        edge = k;
        crossing = x;
      }
    }
  }
  // Across each crossed edge the plane leaves the next triangle through its one other crossed
  // edge, until a triangle holding b.
  for (int step = 0; face >= 0 && step <= mesh.faceCount(); ++step)
  {
    curve.faces.push_back(face);
    curve.points.push_back(crossing);
    const int next = mesh.faceNeighbor(face, edge);
    if (next < 0)
    {
      throw Error(segment + " meets the mesh's boundary or a non-manifold edge before its end");
    }
    if (std::binary_search(toFaces.begin(), toFaces.end(), next))
    {
      curve.faces.push_back(next);
      return;
    }
    const int entry = entryEdge(mesh, face, edge, next);
    face = -1;
    for (int k = 0; k < 3; ++k)
    {
      if (k != entry && crossEdge(mesh, next, k, planeNormal, xa, crossing))
      {
        face = next;
        edge = k;
        break;
      }
    }
  }
  throw Error(segment + " cannot be followed across the surface to its end; give more points along the line");
}
} // namespace

SurfaceCurve placeCurveOnSurface(const Surface& surface, const std::vector<Vector3>& points, bool closed,
  double maximumDistance, const std::string& what)
{
  const TriangleMesh& mesh = surface.mesh();
  std::vector<SurfacePoint> placed;
  std::vector<Vector3> positions;
  const double repeat = 1e-12 * mesh.boundingBoxDiagonal();
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const SurfacePoint p =
      projectOntoSurface(surface, points[i], maximumDistance, "point " + std::to_string(i) + " of " + what);
    const Vector3 x = surfacePosition(mesh, p);
    if (positions.empty() || (x - positions.back()).norm() > repeat)
    {
      placed.push_back(p);
      positions.push_back(x);
    }
  }
  if (closed && positions.size() > 1 && (positions.back() - positions.front()).norm() <= repeat)
  {
    placed.pop_back();
    positions.pop_back();
  }
  const std::size_t needed = closed ? 3 : 2;
  if (placed.size() < needed)
  {
    throw Error(what + " needs at least " + std::to_string(needed) + " distinct points on the surface, got " +
      std::to_string(placed.size()));
  }
  SurfaceCurve curve;
  curve.closed = closed;
  const std::size_t segments = closed ? placed.size() : placed.size() - 1;
  for (std::size_t i = 0; i < segments; ++i)
  {
    curve.points.push_back(positions[i]);
    followSegment(mesh, placed[i], placed[(i + 1) % placed.size()], static_cast<int>(i), what, curve);
  }
  if (!closed)
  {
    curve.points.push_back(positions.back());
  }
  return curve;
}

} // namespace kerf
