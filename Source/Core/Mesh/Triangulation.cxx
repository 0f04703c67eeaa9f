// Ear-clipping triangulation of polygons in their Newell plane.
#include "Mesh/Triangulation.h"

#include "Error.h"
#include "Mesh/Planar.h"

#include <Eigen/Geometry>

#include <string>

namespace kerf
{

namespace
{
bool insideTriangle(
  const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c)
{
  return cross2(b - a, p - a) >= 0.0 && cross2(c - b, p - b) >= 0.0 && cross2(a - c, p - c) >= 0.0;
}

void fan(const std::vector<int>& corners, int polygon, Triangulation& out)
{
  for (std::size_t k = 1; k + 1 < corners.size(); ++k)
  {
    out.triangles.push_back({ corners[0], corners[k], corners[k + 1] });
    out.sourcePolygon.push_back(polygon);
  }
}

void earClip(const PolygonMesh& mesh, std::vector<int> corners, int polygon, Triangulation& out)
{
  Vector3 normal = Vector3::Zero();
  for (std::size_t k = 0; k < corners.size(); ++k)
  {
    const Vector3& a = mesh.points[corners[k]];
    const Vector3& b = mesh.points[corners[(k + 1) % corners.size()]];
    normal +=
      Vector3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()), (a.x() - b.x()) * (a.y() + b.y()));
  }
  if (!(normal.norm() > 0.0) || !normal.allFinite())
  {
    fan(corners, polygon, out);
    return;
  }
  normal.normalize();
  const Vector3 axis = std::abs(normal.x()) < 0.9 ? Vector3::UnitX() : Vector3::UnitY();
  const Vector3 e1 = normal.cross(axis).normalized();
  const Vector3 e2 = normal.cross(e1);
  std::vector<Eigen::Vector2d> uv(corners.size());
  for (std::size_t k = 0; k < corners.size(); ++k)
  {
    const Vector3& p = mesh.points[corners[k]];
    uv[k] = Eigen::Vector2d(p.dot(e1), p.dot(e2));
  }
  std::vector<int> remaining(corners.size());
  for (std::size_t k = 0; k < remaining.size(); ++k)
  {
    remaining[k] = static_cast<int>(k);
  }
  while (remaining.size() > 3)
  {
    bool clipped = false;
    const std::size_t m = remaining.size();
    for (std::size_t i = 0; i < m && !clipped; ++i)
    {
      const int a = remaining[(i + m - 1) % m];
      const int b = remaining[i];
      const int c = remaining[(i + 1) % m];
      if (cross2(uv[b] - uv[a], uv[c] - uv[a]) <= 0.0)
      {
        continue; // reflex or flat corner
      }
      bool empty = true;
      for (int other : remaining)
      {
        if (other != a && other != b && other != c && insideTriangle(uv[other], uv[a], uv[b], uv[c]))
        {
          empty = false;
          break;
        }
      }
      if (empty)
      {
        out.triangles.push_back({ corners[a], corners[b], corners[c] });
        out.sourcePolygon.push_back(polygon);
        remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i));
        clipped = true;
      }
    }
    if (!clipped)
    {
      std::vector<int> rest;
      for (int k : remaining)
      {
        rest.push_back(corners[k]);
      }
      fan(rest, polygon, out);
      return;
    }
  }
  out.triangles.push_back({ corners[remaining[0]], corners[remaining[1]], corners[remaining[2]] });
  out.sourcePolygon.push_back(polygon);
}
} // namespace

Triangulation triangulatePolygons(const PolygonMesh& mesh)
{
  const int points = static_cast<int>(mesh.points.size());
  for (int f = 0; f < mesh.polygonCount(); ++f)
  {
    for (int k = mesh.polygonOffsets[f]; k < mesh.polygonOffsets[f + 1]; ++k)
    {
      if (mesh.polygonIndices[k] < 0 || mesh.polygonIndices[k] >= points)
      {
        throw Error("polygon " + std::to_string(f) + " uses point " + std::to_string(mesh.polygonIndices[k]) +
          ", but the mesh has " + std::to_string(points) + " points");
      }
    }
  }
  Triangulation out;
  out.triangles.reserve(mesh.polygonIndices.size() / 3);
  out.sourcePolygon.reserve(mesh.polygonIndices.size() / 3);
  for (int f = 0; f < mesh.polygonCount(); ++f)
  {
    const int first = mesh.polygonOffsets[f];
    const int size = mesh.polygonOffsets[f + 1] - first;
    if (size == 3)
    {
      out.triangles.push_back(
        { mesh.polygonIndices[first], mesh.polygonIndices[first + 1], mesh.polygonIndices[first + 2] });
      out.sourcePolygon.push_back(f);
      continue;
    }
    out.allTriangles = false;
    if (size < 3)
    {
      continue; // not a surface element
    }
    std::vector<int> corners(mesh.polygonIndices.begin() + first, mesh.polygonIndices.begin() + first + size);
    earClip(mesh, std::move(corners), f, out);
  }
  return out;
}

} // namespace kerf
