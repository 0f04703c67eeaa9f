// A mesh made of some triangles of another, with the index maps both ways, and the edge joining two vertices.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// The triangles `faces` of a mesh as a mesh of their own: its vertices are the used ones,
/// renumbered in increasing order of their index in the whole mesh; its triangles keep the
/// order of `faces`.
struct Submesh
{
  TriangleMesh mesh;
  std::vector<int> globalVertex; ///< local -> whole-mesh vertex
  std::vector<int> localVertex;  ///< whole-mesh -> local vertex, or -1
  std::vector<int> globalFace;   ///< local -> whole-mesh triangle
};

Submesh extractSubmesh(const TriangleMesh& mesh, const std::vector<int>& faces);

/// The edge joining vertices a and b, or -1 if there is none.
int edgeBetween(const TriangleMesh& mesh, int a, int b);

} // namespace kerf
