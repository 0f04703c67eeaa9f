// Builds the adjacency of kerf::TriangleMesh in linear time with counting sorts.
#include "Mesh/TriangleMesh.h"

#include "Error.h"
#include "Mesh/UnionFind.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>

namespace kerf
{

namespace
{
// edgeShift's mark for a vertex whose triangles changed in a refinement.
constexpr int ChangedVertex = std::numeric_limits<int>::min();

void checkTriangle(const Triangle& triangle, std::size_t f, int pointCount)
{
  for (int corner : triangle)
  {
    if (corner < 0 || corner >= pointCount)
    {
      throw Error("triangle " + std::to_string(f) + " uses point " + std::to_string(corner) + ", but the mesh has " +
        std::to_string(pointCount) + " points");
    }
  }
}

} // namespace

TriangleMesh::TriangleMesh(std::vector<Vector3> points, std::vector<Triangle> triangles)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
{
  this->checkSize();
  checkIndices(this->Triangles, this->vertexCount());
  this->buildVertexFaces();
  this->buildEdges();
  this->buildVertexEdges();
  this->buildBoundaryLoops();
  this->buildComponents();
}

std::vector<TriangleMesh> TriangleMesh::componentMeshes() const
{
  const int count = this->ComponentCount;
  std::vector<TriangleMesh> parts(static_cast<std::size_t>(count));
  // Local indices: components keep the increasing order of vertices, triangles and edges, so
  // each component's edges are found in the order a fresh build would number them.
  std::vector<int> localVertex(this->Points.size(), -1);
  std::vector<int> localFace(this->Triangles.size());
  std::vector<int> localEdge(this->EdgeVertices.size());
  std::vector<int> vertexCounts(static_cast<std::size_t>(count), 0);
  std::vector<int> faceCounts(static_cast<std::size_t>(count), 0);
  std::vector<int> edgeCounts(static_cast<std::size_t>(count), 0);
  std::vector<int> incidenceCounts(static_cast<std::size_t>(count), 0);
  for (int v = 0; v < this->vertexCount(); ++v)
  {
    const int c = this->VertexComponents[v];
    if (c >= 0)
    {
      localVertex[v] = vertexCounts[c]++;
      incidenceCounts[c] += this->VertexFaceOffsets[v + 1] - this->VertexFaceOffsets[v];
    }
  }
  for (int f = 0; f < this->faceCount(); ++f)
  {
    localFace[f] = faceCounts[this->FaceComponents[f]]++;
  }
  for (int e = 0; e < this->edgeCount(); ++e)
  {
    localEdge[e] = edgeCounts[this->VertexComponents[this->EdgeVertices[e][0]]]++;
  }
  for (int c = 0; c < count; ++c)
  {
    TriangleMesh& part = parts[c];
    part.Points.resize(vertexCounts[c]);
    part.VertexFaceOffsets.resize(vertexCounts[c] + 1);
    part.VertexFaceOffsets[0] = 0;
    part.VertexFaceList.resize(incidenceCounts[c]);
    part.Triangles.resize(faceCounts[c]);
    part.FaceEdges.resize(faceCounts[c]);
    part.FaceNeighbors.resize(faceCounts[c]);
    part.EdgeVertices.resize(edgeCounts[c]);
    part.EdgeFaces.resize(edgeCounts[c]);
    part.EdgeFaceCounts.resize(edgeCounts[c]);
    part.ComponentCount = 1;
    part.FaceComponents.assign(faceCounts[c], 0);
    part.VertexComponents.assign(vertexCounts[c], 0);
  }
  const auto mapped = [](const std::vector<int>& local, int i) { return i < 0 ? -1 : local[i]; };
  for (int v = 0; v < this->vertexCount(); ++v)
  {
    const int c = this->VertexComponents[v];
    if (c < 0)
    {
      continue;
    }
    TriangleMesh& part = parts[c];
    const int local = localVertex[v];
    part.Points[local] = this->Points[v];
    int at = part.VertexFaceOffsets[local];
    for (int f : this->vertexFaces(v))
    {
      part.VertexFaceList[at++] = localFace[f];
    }
    part.VertexFaceOffsets[local + 1] = at;
  }
  for (int f = 0; f < this->faceCount(); ++f)
  {
    TriangleMesh& part = parts[this->FaceComponents[f]];
    const int local = localFace[f];
    const Triangle& t = this->Triangles[f];
    part.Triangles[local] = { localVertex[t[0]], localVertex[t[1]], localVertex[t[2]] };
    const std::array<int, 3>& edges = this->FaceEdges[f];
    part.FaceEdges[local] = { mapped(localEdge, edges[0]), mapped(localEdge, edges[1]), mapped(localEdge, edges[2]) };
    const std::array<int, 3>& neighbors = this->FaceNeighbors[f];
    part.FaceNeighbors[local] = { mapped(localFace, neighbors[0]), mapped(localFace, neighbors[1]),
      mapped(localFace, neighbors[2]) };
  }
  for (int e = 0; e < this->edgeCount(); ++e)
  {
    const std::array<int, 2>& ev = this->EdgeVertices[e];
    TriangleMesh& part = parts[this->VertexComponents[ev[0]]];
    const int local = localEdge[e];
    part.EdgeVertices[local] = { localVertex[ev[0]], localVertex[ev[1]] };
    part.EdgeFaces[local] = { mapped(localFace, this->EdgeFaces[e][0]), mapped(localFace, this->EdgeFaces[e][1]) };
    part.EdgeFaceCounts[local] = this->EdgeFaceCounts[e];
  }
  for (TriangleMesh& part : parts)
  {
    part.buildVertexEdges();
    part.buildBoundaryLoops();
  }
  return parts;
}

void TriangleMesh::checkSize() const
{
  if (this->Points.size() >= static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
    this->Triangles.size() >= static_cast<std::size_t>(std::numeric_limits<int>::max() / 3))
  {
    throw Error("the mesh has too many points or triangles for 32-bit indices");
  }
}

void TriangleMesh::checkIndices(const std::vector<Triangle>& triangles, int pointCount)
{
  for (std::size_t f = 0; f < triangles.size(); ++f)
  {
    checkTriangle(triangles[f], f, pointCount);
  }
}

TriangleMesh TriangleMesh::withPoints(std::vector<Vector3> points) const
{
  if (points.size() != this->Points.size())
  {
    throw Error(
      "the mesh has " + std::to_string(this->Points.size()) + " points, not " + std::to_string(points.size()));
  }
  TriangleMesh moved(*this);
  moved.Points = std::move(points);
  return moved;
}

double TriangleMesh::meanEdgeLength() const
{
  double sum = 0.0;
  for (const std::array<int, 2>& edge : this->EdgeVertices)
  {
    sum += (this->Points[edge[0]] - this->Points[edge[1]]).norm();
  }
  return this->EdgeVertices.empty() ? 0.0 : sum / static_cast<double>(this->EdgeVertices.size());
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
  std::partial_sum(this->VertexFaceOffsets.begin(), this->VertexFaceOffsets.end(), this->VertexFaceOffsets.begin());
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
  // A closed manifold surface has 3/2 edges per triangle; reserving that for the three edge
  // arrays spares most of their regrowth (copies and fresh pages) on large meshes.
  const std::size_t expectedEdges = this->Triangles.size() * 3 / 2 + 16;
  this->EdgeVertices.reserve(expectedEdges);
  this->EdgeFaces.reserve(expectedEdges);
  this->EdgeFaceCounts.reserve(expectedEdges);

  std::vector<int> stamp(n, -1);
  std::vector<int> slot(n, -1);
  for (int v = 0; v < n; ++v)
  {
    this->discoverEdges(v, stamp, slot);
  }
  this->FaceNeighbors.resize(this->Triangles.size());
  for (int f = 0; f < this->faceCount(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->FaceNeighbors[f][k] = this->neighborAcross(f, k);
    }
  }
}

// Numbers the edges whose smaller vertex is v, in the order v's triangles meet them, after all
// edges of smaller vertices; stamp[w] == v marks that the edge (v, w) already exists with index
// slot[w].
void TriangleMesh::discoverEdges(int v, std::vector<int>& stamp, std::vector<int>& slot)
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

bool TriangleMesh::isSingleFan(int v) const
{
  const IndexRange faces = this->vertexFaces(v);
  if (faces.empty())
  {
    return false;
  }
  // The two sides of triangle f at v (side k joins corners k and k + 1); false when f repeats a vertex.
  auto sidesAt = [&](int f, std::array<int, 2>& sides) {
    const Triangle& t = this->Triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
    {
      return false;
    }
    int found = 0;
    for (int k = 0; k < 3; ++k)
    {
      if (t[k] == v || t[(k + 1) % 3] == v)
      {
        sides[found++] = k;
      }
    }
    return found == 2;
  };
  const int first = faces[0];
  std::array<int, 2> firstSides{};
  if (!sidesAt(first, firstSides))
  {
    return false;
  }
  std::size_t reached = 1;
  for (int way = 0; way < 2; ++way)
  {
    int f = first;
    int side = firstSides[static_cast<std::size_t>(way)];
    while (reached <= faces.size())
    {
      const int g = this->faceNeighbor(f, side);
      if (g < 0)
      {
        break;
      }
      if (g == first)
      {
        return reached == faces.size(); // a closed fan, walked once round
      }
      ++reached;
      std::array<int, 2> sides{};
      if (!sidesAt(g, sides))
      {
        return false;
      }
      const int arrival = this->faceEdge(f, side);
      side = this->faceEdge(g, sides[0]) == arrival ? sides[1] : sides[0];
      f = g;
    }
  }
  return reached == faces.size();
}

// The triangle across side k of f, where that edge is manifold and interior.
int TriangleMesh::neighborAcross(int f, int k) const
{
  const int e = this->FaceEdges[f][k];
  if (e < 0 || this->EdgeFaceCounts[e] != 2)
  {
    return -1;
  }
  const std::array<int, 2>& faces = this->EdgeFaces[e];
  return faces[0] == f ? faces[1] : faces[0];
}

TriangleMesh TriangleMesh::refined(
  std::vector<Vector3> points, std::vector<Triangle> triangles, const std::vector<int>& originalFaces) const
{
  if (points.size() < this->Points.size())
  {
    throw Error("a refined mesh has " + std::to_string(points.size()) + " points, fewer than the " +
      std::to_string(this->Points.size()) + " it refines");
  }
  if (originalFaces.size() != triangles.size())
  {
    throw Error("a refined mesh names the original triangle of " + std::to_string(originalFaces.size()) + " of its " +
      std::to_string(triangles.size()) + " triangles");
  }
  TriangleMesh mesh;
  mesh.Points = std::move(points);
  mesh.Triangles = std::move(triangles);
  mesh.checkSize();

  // keptAs[f]: the one triangle of the refined mesh that is this mesh's triangle f unchanged (-1
  // where f was split). A vertex of this mesh is changed when it is a corner of a split triangle
  // or of one of its pieces (edgeShift[v] = ChangedVertex); every other vertex has the same
  // triangles as here, renumbered in the same order. A kept triangle uses this mesh's points
  // only, so only the pieces need their indices checked.
  std::vector<int> keptAs(this->Triangles.size(), -1);
  std::vector<int> edgeShift(this->Points.size(), 0);
  const int baseVertices = this->vertexCount();
  auto markCorners = [&](const Triangle& t) {
    for (int v : t)
    {
      if (v < baseVertices)
      {
        edgeShift[v] = ChangedVertex;
      }
    }
  };
  const int faces = mesh.faceCount();
  int next = 0; // the first base triangle not yet met
  for (int g = 0; g < faces;)
  {
    const int f = originalFaces[g];
    if (f < 0 || f >= this->faceCount() || (g > 0 && f < originalFaces[g - 1]))
    {
      throw Error("triangle " + std::to_string(g) + " of a refined mesh names original triangle " + std::to_string(f) +
        ", out of range or out of order");
    }
    for (; next < f; ++next)
    {
      markCorners(this->Triangles[next]); // a triangle left without pieces
    }
    next = f + 1;
    const Triangle& original = this->Triangles[f];
    const Triangle& t = mesh.Triangles[g];
    if ((g + 1 == faces || originalFaces[g + 1] != f) && t[0] == original[0] && t[1] == original[1] &&
      t[2] == original[2])
    {
      keptAs[f] = g++;
      continue;
    }
    markCorners(original);
    for (; g < faces && originalFaces[g] == f; ++g)
    {
      checkTriangle(mesh.Triangles[g], g, mesh.vertexCount());
      markCorners(mesh.Triangles[g]);
    }
  }
  for (; next < this->faceCount(); ++next)
  {
    markCorners(this->Triangles[next]);
  }
  mesh.buildVertexFaces();
  mesh.buildEdgesFrom(*this, originalFaces, keptAs, edgeShift);
  mesh.buildVertexEdges();
  mesh.buildBoundaryLoops();
  if (!mesh.copyComponents(*this, originalFaces, keptAs))
  {
    mesh.buildComponents();
  }
  return mesh;
}

// buildEdges for a refinement of `base`. Edges are numbered by their smaller vertex, so the edges
// of an unchanged vertex are a block of the base's edges: copied whole (their triangles
// renumbered, the block's shift stored in edgeShift), while those of changed and new vertices
// are discovered again. A kept triangle's side from an unchanged vertex is the base's edge,
// shifted, with the base's neighbour across it.
void TriangleMesh::buildEdgesFrom(const TriangleMesh& base, const std::vector<int>& originalFaces,
  const std::vector<int>& keptAs, std::vector<int>& edgeShift)
{
  const int n = this->vertexCount();
  const int baseVertices = base.vertexCount();
  this->FaceEdges.assign(this->Triangles.size(), { -1, -1, -1 });
  this->EdgeVertices.clear();
  this->EdgeFaces.clear();
  this->EdgeFaceCounts.clear();
  const std::size_t expected = std::max(base.EdgeVertices.size(), this->Triangles.size() * 3 / 2) + 16;
  this->EdgeVertices.reserve(expected);
  this->EdgeFaces.reserve(expected);
  this->EdgeFaceCounts.reserve(expected);

  std::vector<int> stamp(n, -1);
  std::vector<int> slot(n, -1);
  const int baseEdges = base.edgeCount();
  int next = 0; // the base's first edge whose smaller vertex is v or more
  for (int v = 0; v < n; ++v)
  {
    const int first = next;
    while (next < baseEdges && base.EdgeVertices[next][0] == v)
    {
      ++next;
    }
    if (v >= baseVertices || edgeShift[v] == ChangedVertex)
    {
      this->discoverEdges(v, stamp, slot);
      continue;
    }
    edgeShift[v] = this->edgeCount() - first;
    this->EdgeVertices.insert(
      this->EdgeVertices.end(), base.EdgeVertices.begin() + first, base.EdgeVertices.begin() + next);
    this->EdgeFaceCounts.insert(
      this->EdgeFaceCounts.end(), base.EdgeFaceCounts.begin() + first, base.EdgeFaceCounts.begin() + next);
    for (int e = first; e < next; ++e)
    {
      // Both triangles contain the unchanged vertex v, so both were kept. Written element by
      // element: a pair built on the stack and pushed whole stalls on store forwarding (two
      // 4-byte stores read back as one 8-byte load).
      const std::array<int, 2>& faces = base.EdgeFaces[e];
      std::array<int, 2>& renumbered = this->EdgeFaces.emplace_back();
      renumbered[0] = faces[0] >= 0 ? keptAs[faces[0]] : -1;
      renumbered[1] = faces[1] >= 0 ? keptAs[faces[1]] : -1;
    }
  }
  this->FaceNeighbors.resize(this->Triangles.size());
  for (int g = 0; g < this->faceCount(); ++g)
  {
    const int f = originalFaces[g];
    const Triangle& t = this->Triangles[g];
    const bool kept = keptAs[f] == g;
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      const int shift = kept && a != b ? edgeShift[std::min(a, b)] : ChangedVertex;
      if (shift != ChangedVertex)
      {
        const int across = base.FaceNeighbors[f][k];
        this->FaceEdges[g][k] = base.FaceEdges[f][k] + shift;
        this->FaceNeighbors[g][k] = across >= 0 ? keptAs[across] : -1;
      }
      else
      {
        this->FaceNeighbors[g][k] = this->neighborAcross(g, k);
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
  std::partial_sum(this->VertexEdgeOffsets.begin(), this->VertexEdgeOffsets.end(), this->VertexEdgeOffsets.begin());
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
  bool anyBoundary = false;
  for (int e = 0; e < this->edgeCount(); ++e)
  {
    if (this->EdgeFaceCounts[e] == 1)
    {
      this->BoundaryVertex[this->EdgeVertices[e][0]] = 1;
      this->BoundaryVertex[this->EdgeVertices[e][1]] = 1;
      anyBoundary = true;
    }
  }
  if (!anyBoundary)
  {
    return;
  }
  std::vector<char> visited(this->EdgeVertices.size(), 0);
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
    joinRoots(parent, t[0], t[1]);
    joinRoots(parent, t[0], t[2]);
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

// The components of a refinement of `base` are the base's (numbered alike, since the triangles
// keep their order) when each split triangle's pieces join all its corners and use no other
// vertex of the base, and each new vertex lies in the pieces of one component. Returns false,
// leaving the components to buildComponents, when that does not hold.
bool TriangleMesh::copyComponents(
  const TriangleMesh& base, const std::vector<int>& originalFaces, const std::vector<int>& keptAs)
{
  const int baseVertices = base.vertexCount();
  this->VertexComponents.resize(this->Points.size());
  std::copy(base.VertexComponents.begin(), base.VertexComponents.end(), this->VertexComponents.begin());
  std::fill(this->VertexComponents.begin() + baseVertices, this->VertexComponents.end(), -1);
  this->FaceComponents.resize(this->Triangles.size());
  std::vector<int> local;  // the vertices of one split triangle's pieces, its corners first
  std::vector<int> parent; // union-find over `local`
  auto localIndex = [&](int v) {
    const auto found = std::find(local.begin(), local.end(), v);
    if (found != local.end())
    {
      return static_cast<int>(found - local.begin());
    }
    local.push_back(v);
    parent.push_back(static_cast<int>(parent.size()));
    return static_cast<int>(local.size()) - 1;
  };
  const int faces = this->faceCount();
  int expected = 0; // the base triangle whose pieces come next: every one has some
  for (int g = 0; g < faces;)
  {
    const int f = originalFaces[g];
    const int component = base.FaceComponents[f];
    if (f != expected++)
    {
      return false;
    }
    if (keptAs[f] == g)
    {
      this->FaceComponents[g++] = component;
      continue;
    }
    local.clear();
    parent.clear();
    for (int v : base.Triangles[f])
    {
      localIndex(v);
    }
    const std::size_t corners = local.size();
    for (; g < faces && originalFaces[g] == f; ++g)
    {
      this->FaceComponents[g] = component;
      const Triangle& t = this->Triangles[g];
      const int a = localIndex(t[0]), b = localIndex(t[1]), c = localIndex(t[2]);
      joinRoots(parent, a, b);
      joinRoots(parent, a, c);
    }
    for (std::size_t i = 0; i < local.size(); ++i)
    {
      if (findRoot(parent, static_cast<int>(i)) != 0)
      {
        return false; // the pieces do not join all corners
      }
      if (i < corners)
      {
        continue;
      }
      if (local[i] < baseVertices)
      {
        return false; // a piece uses a base vertex that is not a corner of f
      }
      int& label = this->VertexComponents[local[i]];
      if (label >= 0 && label != component)
      {
        return false;
      }
      label = component;
    }
  }
  if (expected != base.faceCount())
  {
    return false;
  }
  this->ComponentCount = base.ComponentCount;
  return true;
}

} // namespace kerf
