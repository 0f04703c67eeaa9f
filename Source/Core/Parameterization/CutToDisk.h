// Cutting a chart that is not a disk (closed, several boundary loops, handles) open into one disk.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <array>
#include <vector>

namespace kerf
{

/// A mesh cut open along some of its edges.
struct EdgeCut
{
  TriangleMesh mesh;               ///< the same triangles (order, orientation); vertices copied along the cut
  std::vector<int> originalVertex; ///< per vertex of `mesh`: the input vertex it copies
  std::vector<int> cutEdges;       ///< the input edges cut (interior edges), ascending
  double cutLength = 0.0;          ///< their total length
};

/// Shortest paths along the edges of a mesh (Euclidean edge lengths) from the nearest of a set of
/// source vertices: per vertex its distance (infinite where no source is reached) and the edge
/// of its path towards the source (-1 at the sources). Dijkstra; ties broken by index.
struct EdgePathTree
{
  std::vector<double> distance;
  std::vector<int> towards;
};
EdgePathTree shortestEdgePaths(const TriangleMesh& mesh, const std::vector<int>& sources);

/// Splits `mesh` open along the interior edges flagged in `cut` (one flag per edge of `mesh`;
/// boundary and non-manifold edges are left as they are): around each vertex, the triangles
/// joined across uncut edges share one copy of it. Copies are numbered by input vertex, then by
/// their lowest triangle, so uncut meshes keep their numbering. Deterministic.
EdgeCut splitAlongEdges(const TriangleMesh& mesh, const std::vector<char>& cut);

/// Cuts a connected, manifold, consistently oriented chart into a topological disk (one boundary
/// loop, genus 0) along a cut graph of short paths; a disk comes back uncut. The rule:
/// - every boundary loop is capped by a virtual vertex joined to its vertices at length 0, and
///   the shortest-path tree T of the capped mesh is grown from the first loop's cap (from vertex
///   0 when there is no boundary);
/// - the tree-cotree decomposition of Eppstein 2003 (section 2), with the cotree the maximum
///   spanning tree of the dual graph under the weights of Erickson and Whittlesey 2005 (section
///   3: the length of the edge's loop through T), leaves 2 g edges; each closes a loop through T
///   (an arc between boundary points when there is a boundary) that cuts a handle;
/// - every other boundary loop is joined to the first by its path in T (the shortest path
///   between them);
/// - a closed chart of genus 0 is cut along the shortest edge path between two vertices far
///   apart (two Dijkstra sweeps from vertex 0), so the cut opens it like a peel.
/// Edge lengths are Euclidean; ties are broken by index. Throws kerf::Error for a chart that is
/// empty, not connected, not manifold or not consistently oriented, or when the cut fails to give
/// a disk.
EdgeCut cutToDisk(const TriangleMesh& chart);

} // namespace kerf
