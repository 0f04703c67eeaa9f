// The Core triangle mesh: points, triangles and the adjacency every Kerf algorithm needs.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <vector>

namespace kerf
{

using Vector3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;

/// A read-only view of consecutive indices (one row of a compressed adjacency table).
class IndexRange
{
public:
  IndexRange(const int* first, const int* last)
    : First(first)
    , Last(last)
  {
  }
  const int* begin() const { return this->First; }
  const int* end() const { return this->Last; }
  std::size_t size() const { return static_cast<std::size_t>(this->Last - this->First); }
  bool empty() const { return this->First == this->Last; }
  int operator[](std::size_t i) const { return this->First[i]; }

private:
  const int* First;
  const int* Last;
};

/// A triangle mesh with its adjacency, built once and then read by the algorithms.
///
/// Edges are the unordered vertex pairs used by at least one triangle. Edge k of triangle f joins
/// corner k to corner k+1 (mod 3). A triangle that repeats a vertex has no edge for the repeated
/// pair (index -1); such triangles are reported by validation and refused by the filters.
/// Non-manifold edges (three or more triangles) are kept: they have no face neighbours.
/// Everything is deterministic: the same points and triangles give the same numbering.
class TriangleMesh
{
public:
  TriangleMesh() = default;

  /// Builds the mesh and its adjacency. Throws kerf::Error when a triangle index is negative or
  /// not smaller than the number of points.
  TriangleMesh(std::vector<Vector3> points, std::vector<Triangle> triangles);

  /// The same triangles and adjacency with other coordinates (one per point), without building
  /// the adjacency again. Throws kerf::Error for another number of points.
  TriangleMesh withPoints(std::vector<Vector3> points) const;

  /// The mesh with some of this mesh's triangles split into smaller ones. `points` keeps this
  /// mesh's points at their indices and may add new ones after them; triangles[i] lies in this
  /// mesh's triangle originalFaces[i], which never decreases with i, and a triangle left whole
  /// appears once, unchanged. The result equals TriangleMesh(points, triangles) in every number
  /// and list, but only the adjacency around split triangles is built again: the rest is this
  /// mesh's, renumbered. Throws kerf::Error as the constructor does, and when originalFaces has
  /// another length than triangles, names a triangle out of range or decreases.
  TriangleMesh refined(
    std::vector<Vector3> points, std::vector<Triangle> triangles, const std::vector<int>& originalFaces) const;

  /// Each connected component (componentCount() of them, in order) as its own mesh: the
  /// component's points and triangles in increasing order, renumbered from 0 (unreferenced points
  /// belong to none). Each equals TriangleMesh(its points, its triangles) in every number and
  /// list, but its adjacency is this mesh's, renumbered, not searched again.
  std::vector<TriangleMesh> componentMeshes() const;

  /// Throws kerf::Error naming the first triangle that uses an index outside [0, pointCount).
  static void checkIndices(const std::vector<Triangle>& triangles, int pointCount);

  int vertexCount() const { return static_cast<int>(this->Points.size()); }
  int faceCount() const { return static_cast<int>(this->Triangles.size()); }
  int edgeCount() const { return static_cast<int>(this->EdgeVertices.size()); }
  bool empty() const { return this->Triangles.empty(); }

  const std::vector<Vector3>& points() const { return this->Points; }
  const Vector3& point(int v) const { return this->Points[v]; }
  const std::vector<Triangle>& triangles() const { return this->Triangles; }
  const Triangle& triangle(int f) const { return this->Triangles[f]; }

  /// Triangles that use vertex v, in increasing order.
  IndexRange vertexFaces(int v) const { return this->row(this->VertexFaceOffsets, this->VertexFaceList, v); }
  /// Vertices joined to v by an edge; vertexEdges(v)[i] is the edge to vertexNeighbors(v)[i].
  IndexRange vertexNeighbors(int v) const { return this->row(this->VertexEdgeOffsets, this->VertexNeighborList, v); }
  IndexRange vertexEdges(int v) const { return this->row(this->VertexEdgeOffsets, this->VertexEdgeList, v); }

  /// The two vertices of edge e, smaller index first.
  const std::array<int, 2>& edgeVertices(int e) const { return this->EdgeVertices[e]; }
  /// Number of triangles using edge e: 1 on a boundary, 2 inside, 3 or more if non-manifold.
  int edgeFaceCount(int e) const { return this->EdgeFaceCounts[e]; }
  /// The first two triangles using edge e (-1 where there are fewer).
  const std::array<int, 2>& edgeFaces(int e) const { return this->EdgeFaces[e]; }
  bool isBoundaryEdge(int e) const { return this->EdgeFaceCounts[e] == 1; }
  bool isManifoldEdge(int e) const { return this->EdgeFaceCounts[e] <= 2; }

  /// Edge k of triangle f (from corner k to corner k+1), or -1 if the triangle repeats that vertex.
  int faceEdge(int f, int k) const { return this->FaceEdges[f][k]; }
  /// The triangle across edge k of triangle f, or -1 on a boundary or non-manifold edge.
  int faceNeighbor(int f, int k) const { return this->FaceNeighbors[f][k]; }

  /// True when v's triangles form one fan: walking from v's first triangle across the edges at v
  /// held by exactly two triangles, both ways, reaches every triangle at v (a fan is a path or a
  /// cycle of triangles). False when they form several fans or none, and when a triangle at v
  /// repeats a vertex (the walk cannot tell then; MeshValidation counts those fans in full).
  bool isSingleFan(int v) const;

  /// True if v lies on a boundary edge.
  bool isBoundaryVertex(int v) const { return this->BoundaryVertex[v] != 0; }
  /// Closed boundary loops as vertex sequences, each following the orientation of its triangles.
  const std::vector<std::vector<int>>& boundaryLoops() const { return this->BoundaryLoops; }

  /// Connected components: triangles sharing a vertex belong to the same component.
  int componentCount() const { return this->ComponentCount; }
  int faceComponent(int f) const { return this->FaceComponents[f]; }
  /// Component of vertex v, or -1 if no triangle uses v.
  int vertexComponent(int v) const { return this->VertexComponents[v]; }

  /// Axis-aligned bounding box diagonal of the referenced vertices (0 for an empty mesh).
  double boundingBoxDiagonal() const;
  /// Mean length of the edges (0 for a mesh without edges).
  double meanEdgeLength() const;

private:
  IndexRange row(const std::vector<int>& offsets, const std::vector<int>& list, int i) const
  {
    return IndexRange(list.data() + offsets[i], list.data() + offsets[i + 1]);
  }
  void checkSize() const;
  void buildVertexFaces();
  void buildEdges();
  void discoverEdges(int v, std::vector<int>& stamp, std::vector<int>& slot);
  int neighborAcross(int f, int k) const;
  void buildEdgesFrom(const TriangleMesh& base, const std::vector<int>& originalFaces, const std::vector<int>& keptAs,
    std::vector<int>& edgeShift);
  bool copyComponents(const TriangleMesh& base, const std::vector<int>& originalFaces, const std::vector<int>& keptAs);
  void buildVertexEdges();
  void buildBoundaryLoops();
  void buildComponents();

  std::vector<Vector3> Points;
  std::vector<Triangle> Triangles;

  std::vector<int> VertexFaceOffsets;
  std::vector<int> VertexFaceList;
  std::vector<int> VertexEdgeOffsets;
  std::vector<int> VertexNeighborList;
  std::vector<int> VertexEdgeList;

  std::vector<std::array<int, 2>> EdgeVertices;
  std::vector<std::array<int, 2>> EdgeFaces;
  std::vector<int> EdgeFaceCounts;
  std::vector<std::array<int, 3>> FaceEdges;
  std::vector<std::array<int, 3>> FaceNeighbors;

  std::vector<char> BoundaryVertex;
  std::vector<std::vector<int>> BoundaryLoops;

  int ComponentCount = 0;
  std::vector<int> FaceComponents;
  std::vector<int> VertexComponents;
};

} // namespace kerf
