// Surface points and curves: positions, barycentric coordinates and input checks.
#include "Geodesic/SurfacePoint.h"

#include "Error.h"
#include "Geometry/ClosestPoint.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace kerf
{

Vector3 surfacePosition(const TriangleMesh& mesh, const SurfacePoint& point)
{
  const Triangle& t = mesh.triangle(point.face);
  return point.barycentric[0] * mesh.point(t[0]) + point.barycentric[1] * mesh.point(t[1]) +
    point.barycentric[2] * mesh.point(t[2]);
}

SurfacePoint vertexSurfacePoint(const TriangleMesh& mesh, int v)
{
  if (v < 0 || v >= mesh.vertexCount() || mesh.vertexFaces(v).empty())
  {
    throw Error("vertex " + std::to_string(v) + " is not a vertex of a triangle of the mesh");
  }
  SurfacePoint point;
  point.face = mesh.vertexFaces(v)[0];
  const Triangle& t = mesh.triangle(point.face);
  for (int k = 0; k < 3; ++k)
  {
    point.barycentric[k] = t[k] == v ? 1.0 : 0.0;
  }
  return point;
}

Vector3 barycentricInFace(const TriangleMesh& mesh, int face, const Vector3& p)
{
  const Triangle& t = mesh.triangle(face);
  const Vector3& a = mesh.point(t[0]);
  const Vector3 u = mesh.point(t[1]) - a;
  const Vector3 v = mesh.point(t[2]) - a;
  const Vector3 w = p - a;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v);
  const double determinant = uu * vv - uv * uv;
  if (determinant > 1e-14 * uu * vv)
  {
    const double b1 = (vv * w.dot(u) - uv * w.dot(v)) / determinant;
    const double b2 = (uu * w.dot(v) - uv * w.dot(u)) / determinant;
    return Vector3(1.0 - b1 - b2, b1, b2);
  }
  Vector3 barycentric;
  closestPointOnTriangle(p, a, mesh.point(t[1]), mesh.point(t[2]), barycentric);
  return barycentric;
}

int segmentCount(const SurfaceCurve& curve)
{
  const int points = static_cast<int>(curve.points.size());
  return curve.closed ? points : std::max(points - 1, 0);
}

void checkSurfacePoint(const TriangleMesh& mesh, const SurfacePoint& point, const char* what, double tolerance)
{
  if (point.face < 0 || point.face >= mesh.faceCount())
  {
    throw Error(
      std::string(what) + " lies in face " + std::to_string(point.face) + ", which is not a face of the mesh");
  }
  const Vector3& b = point.barycentric;
  if (!b.allFinite())
  {
    throw Error(std::string(what) + " has non-finite barycentric coordinates");
  }
  if (std::abs(b.sum() - 1.0) > tolerance || b.minCoeff() < -tolerance)
  {
    throw Error(std::string(what) + " is off the surface: its barycentric coordinates in face " +
      std::to_string(point.face) + " must be >= 0 and sum to 1");
  }
}

void checkGeodesicSource(const TriangleMesh& mesh, const GeodesicSource& source)
{
  if (source.empty())
  {
    throw Error("the geodesic source is empty: give at least one vertex, point or curve");
  }
  for (int v : source.vertices)
  {
    if (v < 0 || v >= mesh.vertexCount() || mesh.vertexFaces(v).empty())
    {
      throw Error("source vertex " + std::to_string(v) + " is not a vertex of a triangle of the mesh");
    }
  }
  for (const SurfacePoint& p : source.points)
  {
    checkSurfacePoint(mesh, p, "a source point");
  }
  const double tolerance = 1e-6 * mesh.boundingBoxDiagonal();
  for (const SurfaceCurve& curve : source.curves)
  {
    const int segments = segmentCount(curve);
    if (segments < 1 || static_cast<int>(curve.faces.size()) != segments)
    {
      throw Error("a source curve needs at least one segment and one face per segment");
    }
    for (int i = 0; i < segments; ++i)
    {
      const int f = curve.faces[i];
      if (f < 0 || f >= mesh.faceCount())
      {
        throw Error("a source curve's segment lies in face " + std::to_string(f) + ", which is not a face of the mesh");
      }
      for (const Vector3& p : { curve.points[i], curve.points[(i + 1) % curve.points.size()] })
      {
        if (!p.allFinite())
        {
          throw Error("a source curve has a non-finite point");
        }
        const Triangle& t = mesh.triangle(f);
        Vector3 barycentric;
        const Vector3 nearest =
          closestPointOnTriangle(p, mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), barycentric);
        if ((nearest - p).norm() > tolerance)
        {
          throw Error("a source curve's point lies off face " + std::to_string(f) + " that holds its segment");
        }
      }
    }
  }
}

std::vector<int> sourceComponents(const TriangleMesh& mesh, const GeodesicSource& source)
{
  std::vector<int> components;
  for (int v : source.vertices)
  {
    components.push_back(mesh.vertexComponent(v));
  }
  for (const SurfacePoint& p : source.points)
  {
    components.push_back(mesh.faceComponent(p.face));
  }
  for (const SurfaceCurve& curve : source.curves)
  {
    for (int f : curve.faces)
    {
      components.push_back(mesh.faceComponent(f));
    }
  }
  std::sort(components.begin(), components.end());
  components.erase(std::unique(components.begin(), components.end()), components.end());
  return components;
}

} // namespace kerf
