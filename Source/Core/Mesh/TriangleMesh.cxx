// Builds the adjacency of kerf::TriangleMesh in linear time with counting sorts.
#include "Mesh/TriangleMesh.h"

#include "Error.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>

namespace kerf
{

namespace
{
// Union-find with path halving; deterministic (the smaller root wins).
int findRoot(std::vector<int>& parent, int i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

void unite(std::vector<int>& parent, int a, int b)
{
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  if (a < b)
  {
    parent[b] = a;
  }
  else if (b < a)
  {
    parent[a] = b;
  }
}
} // namespace

TriangleMesh::TriangleMesh(std::vector<Vector3> points, std::vector<Triangle> triangles)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
{
  if (this->Points.size() >= static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
    this->Triangles.size() >= static_cast<std::size_t>(std::numeric_limits<int>::max() / 3))
  {
    throw Error("the mesh has too many points or triangles for 32-bit indices");
  }
  checkIndices(this->Triangles, this->vertexCount());
  this->buildVertexFaces();
  this->buildEdges();
  this->buildVertexEdges();
  this->buildBoundaryLoops();
  this->buildComponents();
}

void TriangleMesh::checkIndices(const std::vector<Triangle>& triangles, int pointCount)
{
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    for (int corner : triangles[f])
    {
      if (corner < 0 || corner >= pointCount)
      {
        throw Error("triangle " + std::to_string(f) + " uses point " + std::to_string(corner) +
          ", but the mesh has " + std::to_string(pointCount) + " points");
      }
    }
  }
}

TriangleMesh TriangleMesh::withPoints(std::vector<Vector3> points) const
{
  if (points.size() != this->Points.size())
  {
    throw Error("the mesh has " + std::to_string(this->Points.size()) + " points, not " +
      std::to_string(points.size()));
  }
  TriangleMesh moved(*this);
  moved.Points = std::move(points);
  return moved;
}

double TriangleMesh::boundingBoxDiagonal() const
{
  Vector3 lo = Vector3::Constant(std::numeric_limits<double>::infinity());
  Vector3 hi = -lo;
  bool any = false;
  for (int v = 0; v < this->vertexCount(); ++v)
  {
    if (this->VertexComponents[v] < 0)
    {
      continue;
    }
    lo = lo.cwiseMin(this->Points[v]);
    hi = hi.cwiseMax(this->Points[v]);
    any = true;
  }
  return any ? (hi - lo).norm() : 0.0;
}

void TriangleMesh::buildVertexFaces()
{
  const int n = this->vertexCount();
  this->VertexFaceOffsets.assign(n + 1, 0);
  for (const Triangle& t : this->Triangles)
  {
    ++this->VertexFaceOffsets[t[0] + 1];
    // A triangle repeating a vertex is listed once per distinct vertex.
    if (t[1] != t[0])
    {
      ++this->VertexFaceOffsets[t[1] + 1];
    }
    if (t[2] != t[0] && t[2] != t[1])
    {
      ++this->VertexFaceOffsets[t[2] + 1];
    }
  }
  std::partial_sum(this->VertexFaceOffsets.begin(), this->VertexFaceOffsets.end(),
    this->VertexFaceOffsets.begin());
  this->VertexFaceList.resize(this->VertexFaceOffsets[n]);
  std::vector<int> fill(this->VertexFaceOffsets.begin(), this->VertexFaceOffsets.end() - 1);
  for (int f = 0; f < this->faceCount(); ++f)
  {
    const Triangle& t = this->Triangles[f];
    this->VertexFaceList[fill[t[0]]++] = f;
    if (t[1] != t[0])
    {
      this->VertexFaceList[fill[t[1]]++] = f;
    }
    if (t[2] != t[0] && t[2] != t[1])
    {
      this->VertexFaceList[fill[t[2]]++] = f;
    }
  }
}

void TriangleMesh::buildEdges()
{
  const int n = this->vertexCount();
  this->FaceEdges.assign(this->Triangles.size(), { -1, -1, -1 });
  this->EdgeVertices.clear();
  this->EdgeFaces.clear();
  this->EdgeFaceCounts.clear();
  this->EdgeVertices.reserve(this->Triangles.size() * 3 / 2 + 16);

  // Each edge is discovered from its smaller vertex; stamp[w] == v marks that the edge (v, w)
  // already exists with index slot[w].
  std::vector<int> stamp(n, -1);
  std::vector<int> slot(n, -1);
  for (int v = 0; v < n; ++v)
  {
    for (int f : this->vertexFaces(v))
    {
      const Triangle& t = this->Triangles[f];
      for (int k = 0; k < 3; ++k)
      {
        const int a = t[k];
        const int b = t[(k + 1) % 3];
        if (a == b || std::min(a, b) != v)
        {
          continue;
        }
        const int w = std::max(a, b);
        int e;
        if (stamp[w] == v)
        {
          e = slot[w];
        }
        else
        {
          e = this->edgeCount();
          stamp[w] = v;
          slot[w] = e;
          this->EdgeVertices.push_back({ v, w });
          this->EdgeFaces.push_back({ -1, -1 });
          this->EdgeFaceCounts.push_back(0);
        }
        this->FaceEdges[f][k] = e;
        int& count = this->EdgeFaceCounts[e];
        if (count > 0 && this->EdgeFaces[e][std::min(count, 2) - 1] == f)
        {
          continue; // a triangle repeating a vertex uses its one real edge twice
        }
        if (count < 2)
        {
          this->EdgeFaces[e][count] = f;
        }
        ++count;
      }
    }
  }
  // The triangle across each edge, where the edge is manifold and interior.
  this->FaceNeighbors.assign(this->Triangles.size(), { -1, -1, -1 });
  for (std::size_t f = 0; f < this->Triangles.size(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int e = this->FaceEdges[f][k];
      if (e >= 0 && this->EdgeFaceCounts[e] == 2)
      {
        const std::array<int, 2>& faces = this->EdgeFaces[e];
        this->FaceNeighbors[f][k] = faces[0] == static_cast<int>(f) ? faces[1] : faces[0];
      }
    }
  }
}

void TriangleMesh::buildVertexEdges()
{
  const int n = this->vertexCount();
  this->VertexEdgeOffsets.assign(n + 1, 0);
  for (const std::array<int, 2>& ev : this->EdgeVertices)
  {
    ++this->VertexEdgeOffsets[ev[0] + 1];
    ++this->VertexEdgeOffsets[ev[1] + 1];
  }
  std::partial_sum(this->VertexEdgeOffsets.begin(), this->VertexEdgeOffsets.end(),
    this->VertexEdgeOffsets.begin());
  this->VertexEdgeList.resize(this->VertexEdgeOffsets[n]);
  this->VertexNeighborList.resize(this->VertexEdgeOffsets[n]);
  std::vector<int> fill(this->VertexEdgeOffsets.begin(), this->VertexEdgeOffsets.end() - 1);
  for (int e = 0; e < this->edgeCount(); ++e)
  {
    const std::array<int, 2>& ev = this->EdgeVertices[e];
    this->VertexEdgeList[fill[ev[0]]] = e;
    this->VertexNeighborList[fill[ev[0]]++] = ev[1];
    this->VertexEdgeList[fill[ev[1]]] = e;
    this->VertexNeighborList[fill[ev[1]]++] = ev[0];
  }
}

void TriangleMesh::buildBoundaryLoops()
{
  this->BoundaryVertex.assign(this->Points.size(), 0);
  this->BoundaryLoops.clear();
  std::vector<char> visited(this->EdgeVertices.size(), 0);
  for (int e = 0; e < this->edgeCount(); ++e)
  {
    if (this->EdgeFaceCounts[e] == 1)
    {
      this->BoundaryVertex[this->EdgeVertices[e][0]] = 1;
      this->BoundaryVertex[this->EdgeVertices[e][1]] = 1;
    }
  }
  for (int e = 0; e < this->edgeCount(); ++e)
  {
    if (this->EdgeFaceCounts[e] != 1 || visited[e])
    {
      continue;
    }
    // Start along the orientation of the edge's triangle.
    const int f = this->EdgeFaces[e][0];
    int k = 0;
    while (this->FaceEdges[f][k] != e)
    {
      ++k;
    }
    const int start = this->Triangles[f][k];
    int current = this->Triangles[f][(k + 1) % 3];
    visited[e] = 1;
    std::vector<int> loop{ start };
    while (current != start)
    {
      loop.push_back(current);
      int next = -1;
      const IndexRange edges = this->vertexEdges(current);
      const IndexRange neighbors = this->vertexNeighbors(current);
      for (std::size_t i = 0; i < edges.size(); ++i)
      {
        if (this->EdgeFaceCounts[edges[i]] == 1 && !visited[edges[i]])
        {
          visited[edges[i]] = 1;
          next = neighbors[i];
          break;
        }
      }
      if (next < 0)
      {
        break; // an open chain, possible only around non-manifold edges
      }
      current = next;
    }
    this->BoundaryLoops.push_back(std::move(loop));
  }
}

void TriangleMesh::buildComponents()
{
  const int n = this->vertexCount();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const Triangle& t : this->Triangles)
  {
    unite(parent, t[0], t[1]);
    unite(parent, t[0], t[2]);
  }
  // Number components by their first triangle.
  std::vector<int> label(n, -1);
  this->ComponentCount = 0;
  this->FaceComponents.resize(this->Triangles.size());
  for (int f = 0; f < this->faceCount(); ++f)
  {
    const int root = findRoot(parent, this->Triangles[f][0]);
    if (label[root] < 0)
    {
      label[root] = this->ComponentCount++;
    }
    this->FaceComponents[f] = label[root];
  }
  this->VertexComponents.assign(n, -1);
  for (int v = 0; v < n; ++v)
  {
    if (this->VertexFaceOffsets[v + 1] > this->VertexFaceOffsets[v])
    {
      this->VertexComponents[v] = label[findRoot(parent, v)];
    }
  }
}

} // namespace kerf
