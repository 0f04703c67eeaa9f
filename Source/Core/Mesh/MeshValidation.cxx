// Counts mesh defects and turns them into the error sentences filters report.
#include "Mesh/MeshValidation.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

namespace kerf
{

namespace
{
bool repeatsVertex(const Triangle& t)
{
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

int localRoot(std::vector<int>& parent, int i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

// Number of edge-connected fans formed by the triangles around vertex v.
int fanCount(const TriangleMesh& mesh, int v, std::vector<int>& parent)
{
  const IndexRange faces = mesh.vertexFaces(v);
  parent.resize(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < faces.size(); ++i)
  {
    const Triangle& t = mesh.triangle(faces[i]);
    for (int k = 0; k < 3; ++k)
    {
      if (t[k] != v && t[(k + 1) % 3] != v)
      {
        continue;
      }
      const int g = mesh.faceNeighbor(faces[i], k);
      if (g < 0)
      {
        continue;
      }
      const int* found = std::lower_bound(faces.begin(), faces.end(), g);
      const int j = static_cast<int>(found - faces.begin());
      const int a = localRoot(parent, static_cast<int>(i));
      const int b = localRoot(parent, j);
      parent[std::max(a, b)] = std::min(a, b);
    }
  }
  int fans = 0;
  for (std::size_t i = 0; i < faces.size(); ++i)
  {
    fans += localRoot(parent, static_cast<int>(i)) == static_cast<int>(i) ? 1 : 0;
  }
  return fans;
}

// True if triangle f traverses edge k's vertices in the order (a, b).
bool traverses(const Triangle& t, int a, int b)
{
  for (int k = 0; k < 3; ++k)
  {
    if (t[k] == a && t[(k + 1) % 3] == b)
    {
      return true;
    }
  }
  return false;
}

void add(std::ostringstream& out, int count, const char* singular, const char* plural, const char* why,
  const std::string& where = std::string())
{
  if (count <= 0)
  {
    return;
  }
  if (out.tellp() > 0)
  {
    out << "; ";
  }
  out << count << ' ' << (count == 1 ? singular : plural);
  if (why[0] != '\0' || !where.empty())
  {
    out << " (" << why << (why[0] != '\0' && !where.empty() ? ": " : "") << where << ')';
  }
}

template <typename T>
void note(std::vector<T>& examples, const T& value)
{
  if (examples.size() < MeshReport::ExampleLimit)
  {
    examples.push_back(value);
  }
}

// "points 3, 9" or "cells 7, 12, ..." (the ellipsis when there are more than the examples).
std::string places(
  const char* what, const std::vector<int>& ids, int count, const std::vector<long long>* names = nullptr)
{
  if (ids.empty())
  {
    return std::string();
  }
  std::ostringstream out;
  out << what << ' ';
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    out << (i ? ", " : "") << (names ? (*names)[static_cast<std::size_t>(ids[i])] : ids[i]);
  }
  out << (count > static_cast<int>(ids.size()) ? ", ..." : "");
  return out.str();
}

std::string edgePlaces(const std::vector<std::array<int, 2>>& edges, int count)
{
  if (edges.empty())
  {
    return std::string();
  }
  std::ostringstream out;
  out << "points ";
  for (std::size_t i = 0; i < edges.size(); ++i)
  {
    out << (i ? ", " : "") << edges[i][0] << '-' << edges[i][1];
  }
  out << (count > static_cast<int>(edges.size()) ? ", ..." : "");
  return out.str();
}
} // namespace

MeshReport inspectMesh(const TriangleMesh& mesh)
{
  MeshReport report;
  report.vertices = mesh.vertexCount();
  report.faces = mesh.faceCount();
  report.edges = mesh.edgeCount();

  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const Vector3& p = mesh.point(v);
    if (!p.allFinite())
    {
      ++report.nonFinitePoints;
      note(report.nonFinitePointIds, v);
    }
    else if (p.cwiseAbs().maxCoeff() > CoordinateLimit)
    {
      ++report.hugePoints;
      note(report.hugePointIds, v);
    }
  }
  if (report.nonFinitePoints == 0 && report.hugePoints == 0)
  {
    report.diagonal = mesh.boundingBoxDiagonal();
  }

  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    if (repeatsVertex(t))
    {
      ++report.repeatedVertexFaces;
      note(report.repeatedVertexFaceIds, f);
      continue;
    }
    const Vector3 a = mesh.point(t[1]) - mesh.point(t[0]);
    const Vector3 b = mesh.point(t[2]) - mesh.point(t[0]);
    const Vector3 c = mesh.point(t[2]) - mesh.point(t[1]);
    const double longest = std::max({ a.squaredNorm(), b.squaredNorm(), c.squaredNorm() });
    if (isZeroArea(a.cross(b).norm(), longest))
    {
      ++report.zeroAreaFaces;
      note(report.zeroAreaFaceIds, f);
    }
    // A duplicate shares all corners, so it holds the side t[0]-t[1]: where that edge has at most
    // two triangles, the other one is the only candidate.
    const int side = mesh.faceEdge(f, 0);
    if (mesh.edgeFaceCount(side) <= 2)
    {
      const std::array<int, 2>& holders = mesh.edgeFaces(side);
      const int g = holders[0] == f ? holders[1] : holders[0];
      if (mesh.edgeFaceCount(side) == 2 && g < f)
      {
        const Triangle& other = mesh.triangle(g);
        if (std::find(other.begin(), other.end(), t[2]) != other.end())
        {
          ++report.duplicateFaces;
          note(report.duplicateFaceIds, f);
        }
      }
      continue;
    }
    // Else it is among the triangles around corner 0; with t's corners distinct, one that also
    // holds t[1] and t[2] has the same sorted corners.
    for (int g : mesh.vertexFaces(t[0]))
    {
      if (g >= f)
      {
        break;
      }
      const Triangle& other = mesh.triangle(g);
      if (std::find(other.begin(), other.end(), t[1]) != other.end() &&
        std::find(other.begin(), other.end(), t[2]) != other.end())
      {
        ++report.duplicateFaces;
        note(report.duplicateFaceIds, f);
        break;
      }
    }
  }

  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const int count = mesh.edgeFaceCount(e);
    if (count == 1)
    {
      ++report.boundaryEdges;
    }
    else if (count > 2)
    {
      ++report.nonManifoldEdges;
      note(report.nonManifoldEdgeIds, mesh.edgeVertices(e));
    }
    else
    {
      const std::array<int, 2>& ev = mesh.edgeVertices(e);
      const std::array<int, 2>& ef = mesh.edgeFaces(e);
      if (repeatsVertex(mesh.triangle(ef[0])) || repeatsVertex(mesh.triangle(ef[1])))
      {
        continue; // reported as a degenerate triangle
      }
      if (traverses(mesh.triangle(ef[0]), ev[0], ev[1]) == traverses(mesh.triangle(ef[1]), ev[0], ev[1]))
      {
        ++report.inconsistentEdges;
        note(report.inconsistentEdgeIds, ev);
      }
    }
  }

  std::vector<int> parent;
  int referenced = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (mesh.vertexFaces(v).empty())
    {
      ++report.unreferencedVertices;
      continue;
    }
    ++referenced;
    if (!mesh.isSingleFan(v) && fanCount(mesh, v, parent) > 1)
    {
      ++report.nonManifoldVertices;
      note(report.nonManifoldVertexIds, v);
    }
  }

  report.boundaryLoops = static_cast<int>(mesh.boundaryLoops().size());
  report.components = mesh.componentCount();
  report.eulerCharacteristic = referenced - report.edges + report.faces;
  return report;
}

std::string MeshReport::summary() const
{
  std::ostringstream out;
  out << vertices << " points, " << faces << " triangles, " << edges << " edges, " << components
      << (components == 1 ? " component" : " components") << ", " << boundaryLoops
      << (boundaryLoops == 1 ? " boundary loop" : " boundary loops") << ", Euler characteristic "
      << eulerCharacteristic;
  std::ostringstream defects;
  add(
    defects, nonFinitePoints, "point with NaN or infinite coordinates", "points with NaN or infinite coordinates", "");
  add(defects, hugePoints, "point with a coordinate beyond +-1e50", "points with coordinates beyond +-1e50", "");
  add(defects, repeatedVertexFaces, "triangle repeating a vertex", "triangles repeating a vertex", "");
  add(defects, zeroAreaFaces, "zero-area triangle", "zero-area triangles", "");
  add(defects, duplicateFaces, "duplicate triangle", "duplicate triangles", "");
  add(defects, nonManifoldEdges, "non-manifold edge", "non-manifold edges", "");
  add(defects, nonManifoldVertices, "non-manifold vertex", "non-manifold vertices", "");
  add(defects, inconsistentEdges, "inconsistently oriented edge", "inconsistently oriented edges", "");
  add(defects, unreferencedVertices, "unreferenced point", "unreferenced points", "");
  if (defects.tellp() > 0)
  {
    out << "; " << defects.str();
  }
  return out.str();
}

void requireOrientedManifold(const TriangleMesh& mesh, const std::string& method)
{
  const MeshReport report = inspectMesh(mesh);
  if (report.nonManifoldEdges > 0 || report.inconsistentEdges > 0)
  {
    throw Error(method + " needs an edge-manifold, consistently oriented surface (" +
      std::to_string(report.nonManifoldEdges) + " non-manifold and " + std::to_string(report.inconsistentEdges) +
      " inconsistently oriented edges)");
  }
}

std::string describeProblems(
  const MeshReport& report, const MeshRequirements& requirements, const std::vector<long long>* faceCells)
{
  const char* faces = faceCells ? "cells" : "triangles";
  std::ostringstream out;
  if (report.faces == 0)
  {
    return "the mesh has no triangles";
  }
  add(out, report.nonFinitePoints, "point has NaN or infinite coordinates", "points have NaN or infinite coordinates",
    "", places("points", report.nonFinitePointIds, report.nonFinitePoints));
  add(out, report.hugePoints, "point has a coordinate beyond +-1e50", "points have coordinates beyond +-1e50",
    "rescale the mesh", places("points", report.hugePointIds, report.hugePoints));
  if (report.nonFinitePoints == 0 && report.hugePoints == 0 && report.diagonal < 1.0 / CoordinateLimit)
  {
    if (out.tellp() > 0)
    {
      out << "; ";
    }
    out << "the mesh's bounding-box diagonal " << report.diagonal << " is below 1e-50 (rescale the mesh)";
  }
  add(out, report.repeatedVertexFaces, "triangle uses the same point twice", "triangles use the same point twice",
    "topologically degenerate", places(faces, report.repeatedVertexFaceIds, report.repeatedVertexFaces, faceCells));
  if (!requirements.allowZeroAreaFaces)
  {
    add(out, report.zeroAreaFaces, "triangle has zero area", "triangles have zero area",
      "collinear or coincident corners", places(faces, report.zeroAreaFaceIds, report.zeroAreaFaces, faceCells));
  }
  if (!requirements.allowDuplicateFaces)
  {
    add(out, report.duplicateFaces, "triangle duplicates another", "triangles duplicate others", "same three points",
      places(faces, report.duplicateFaceIds, report.duplicateFaces, faceCells));
  }
  if (requirements.manifold)
  {
    add(out, report.nonManifoldEdges, "edge is non-manifold", "edges are non-manifold",
      "shared by three or more triangles", edgePlaces(report.nonManifoldEdgeIds, report.nonManifoldEdges));
    add(out, report.nonManifoldVertices, "vertex is non-manifold", "vertices are non-manifold",
      "its triangles form several fans", places("points", report.nonManifoldVertexIds, report.nonManifoldVertices));
  }
  if (requirements.consistentOrientation)
  {
    add(out, report.inconsistentEdges, "edge joins inconsistently oriented triangles",
      "edges join inconsistently oriented triangles", "flipped normals",
      edgePlaces(report.inconsistentEdgeIds, report.inconsistentEdges));
  }
  if (!requirements.allowBoundary && report.boundaryEdges > 0)
  {
    add(out, report.boundaryLoops, "boundary loop where a closed surface is required",
      "boundary loops where a closed surface is required", "");
  }
  if (!requirements.allowSeveralComponents && report.components > 1)
  {
    if (out.tellp() > 0)
    {
      out << "; ";
    }
    out << "the mesh has " << report.components << " connected components where one is required";
  }
  return out.str();
}

} // namespace kerf
