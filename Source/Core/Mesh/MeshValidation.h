// Mesh validation shared by every filter: what is wrong with a mesh, and whether a filter accepts it.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <array>
#include <string>
#include <vector>

namespace kerf
{

/// Counts of every defect Kerf checks for. Zero means absent.
struct MeshReport
{
  int vertices = 0;
  int faces = 0;
  int edges = 0;
  int nonFinitePoints = 0;      ///< points with a NaN or infinite coordinate (used or not)
  int hugePoints = 0;           ///< finite points with a coordinate beyond +-CoordinateLimit
  double diagonal = 0.0;        ///< bounding-box diagonal of the points used by triangles
  int repeatedVertexFaces = 0;  ///< triangles that use one vertex twice
  int zeroAreaFaces = 0;        ///< triangles with (numerically) zero area
  int duplicateFaces = 0;       ///< triangles with the same three vertices as an earlier one
  int nonManifoldEdges = 0;     ///< edges shared by three or more triangles
  int nonManifoldVertices = 0;  ///< vertices whose triangles form more than one fan
  int inconsistentEdges = 0;    ///< interior edges whose two triangles are oriented alike
  int unreferencedVertices = 0; ///< points used by no triangle
  int boundaryEdges = 0;
  int boundaryLoops = 0;
  int components = 0;
  int eulerCharacteristic = 0; ///< V - E + F over referenced vertices

  /// The first few (up to ExampleLimit) of each defect, named in messages so a user can select
  /// them: point ids, triangle ids, and edges as their two point ids.
  std::vector<int> nonFinitePointIds, hugePointIds, nonManifoldVertexIds;
  std::vector<int> repeatedVertexFaceIds, zeroAreaFaceIds, duplicateFaceIds;
  std::vector<std::array<int, 2>> nonManifoldEdgeIds, inconsistentEdgeIds;
  static constexpr std::size_t ExampleLimit = 5;

  /// One line listing the size and every non-zero count.
  std::string summary() const;
};

/// Inspects a mesh. Linear in its size.
MeshReport inspectMesh(const TriangleMesh& mesh);

/// What a filter accepts beyond what every filter requires (at least one triangle, finite
/// coordinates within CoordinateLimit, no triangle repeating a vertex).
struct MeshRequirements
{
  bool manifold = true;              ///< refuse non-manifold edges and vertices
  bool consistentOrientation = true; ///< refuse inconsistently oriented neighbouring triangles
  bool allowZeroAreaFaces = true;
  bool allowDuplicateFaces = false;
  bool allowBoundary = true;
  bool allowSeveralComponents = true;
};

/// An empty string when the report meets the requirements, otherwise a sentence naming every
/// problem and its first few places, for example "3 edges are non-manifold (shared by three or
/// more triangles: points 4-9, 9-12, 30-31)". Triangles are named by `faceCells[f]` ("cells 7,
/// 12") when given (the cell each triangle came from), else by their index ("triangles 7, 12").
std::string describeProblems(
  const MeshReport& report, const MeshRequirements& requirements, const std::vector<long long>* faceCells = nullptr);

/// Throws kerf::Error unless the mesh is edge-manifold and consistently oriented: "<method> needs
/// an edge-manifold, consistently oriented surface (n non-manifold and m inconsistently oriented
/// edges)". For Core methods that assemble a Laplacian or read face orientation.
void requireOrientedManifold(const TriangleMesh& mesh, const std::string& method);

/// Coordinates are refused beyond +-CoordinateLimit, and meshes whose bounding-box diagonal is
/// below 1 / CoordinateLimit: squared lengths, areas and their products stay far from overflow
/// and underflow (rescale such a mesh first).
constexpr double CoordinateLimit = 1e50; // messages say "1e50"

/// Relative threshold below which a triangle counts as zero-area: twice its area is at most this
/// times the square of its longest edge.
constexpr double ZeroAreaTolerance = 1e-12;

/// Whether a triangle whose doubled area is `twiceArea` (the norm of two edges' cross product)
/// and whose longest edge has squared length `longestSquaredEdge` counts as zero-area.
inline bool isZeroArea(double twiceArea, double longestSquaredEdge)
{
  return twiceArea <= ZeroAreaTolerance * longestSquaredEdge;
}

} // namespace kerf
