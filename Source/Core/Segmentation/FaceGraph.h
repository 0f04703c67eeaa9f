// The dual graph of a triangle mesh (faces joined across manifold edges) with the geometry every face-clustering method
// reads.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <array>
#include <functional>
#include <limits>
#include <vector>

namespace kerf
{

class Surface;

/// One edge of the dual graph: two faces sharing a manifold mesh edge.
struct DualEdge
{
  std::array<int, 2> faces{ { -1, -1 } }; ///< smaller face index first
  int meshEdge = -1;
  double length = 0.0; ///< length of the shared mesh edge
  /// Cosine of the angle between the two face normals (1 where flat; 1 if a face is degenerate).
  double normalCosine = 1.0;
  /// The angle between the face normals in [0, pi], positive where the edge is convex, negative
  /// where it is concave (the solid's interior dihedral angle is pi - bend).
  double bend = 0.0;
  /// |c_a - m| + |c_b - m|: from each face's centroid to the midpoint m of the shared edge
  /// (Shlafman et al. 2002's physical distance; Liu and Zhang 2004's geodesic step).
  double centroidPath = 0.0;
};

/// The dual graph and per-face geometry, built once in linear time. Faces that share only a vertex,
/// or a boundary or non-manifold edge, are not joined. Deterministic: edges follow mesh edge order.
class FaceGraph
{
public:
  explicit FaceGraph(const TriangleMesh& mesh);

  const TriangleMesh& mesh() const { return *this->Mesh; }
  int faceCount() const { return static_cast<int>(this->Areas.size()); }
  int edgeCount() const { return static_cast<int>(this->Edges.size()); }

  const std::vector<DualEdge>& edges() const { return this->Edges; }
  const DualEdge& edge(int e) const { return this->Edges[e]; }
  /// The dual edges of face f (at most 3).
  const std::array<int, 3>& faceEdges(int f) const { return this->FaceDualEdges[f]; }
  /// The faces across the dual edges of face f, slot for slot with faceEdges (-1 where faceEdges has
  /// none): the dual graph's adjacency without the edges' records. Derivable from faceEdges and
  /// opposite, and kept because the dual Dijkstra reads it: 1.07 -> 0.70 ms per multi-source search
  /// on a 9,408-triangle psb-dev model.
  const std::array<int, 3>& faceNeighbours(int f) const { return this->FaceNeighbours[f]; }
  /// The face across dual edge e from f.
  int opposite(int e, int f) const
  {
    return this->Edges[e].faces[0] == f ? this->Edges[e].faces[1] : this->Edges[e].faces[0];
  }

  double area(int f) const { return this->Areas[f]; }
  const std::vector<double>& areas() const { return this->Areas; }
  double totalArea() const { return this->TotalArea; }
  const Vector3& normal(int f) const { return this->Normals[f]; } ///< unit, or zero if degenerate
  const Vector3& centroid(int f) const { return this->Centroids[f]; }
  /// Perimeter of face f.
  double perimeter(int f) const { return this->Perimeters[f]; }

  /// Connected components of the dual graph (faces joined by dual edges), numbered by first face.
  int componentCount() const { return this->ComponentCount; }
  int component(int f) const { return this->Components[f]; }

private:
  const TriangleMesh* Mesh;
  std::vector<DualEdge> Edges;
  std::vector<std::array<int, 3>> FaceDualEdges;
  std::vector<std::array<int, 3>> FaceNeighbours;
  std::vector<double> Areas;
  std::vector<double> Perimeters;
  std::vector<Vector3> Normals;
  std::vector<Vector3> Centroids;
  double TotalArea = 0.0;
  int ComponentCount = 0;
  std::vector<int> Components;
};

/// The dual graph of a surface's mesh, built on first use and cached on it (Surface::derived).
const FaceGraph& faceGraph(const Surface& surface);

/// Throws kerf::Error unless 1 <= k <= the number of faces (a method asked for k segments).
void checkSegmentCount(int k, int faceCount);

/// Multi-source Dijkstra on the dual graph with a length per dual edge: each face's distance to
/// the nearest source and that source's position in `sources`. Ties go to the smaller face
/// index, so the result is deterministic; unreachable faces get +infinity and -1. With a `limit`,
/// faces farther than it are not reached (the search stops there).
struct DualDistances
{
  std::vector<double> distance;
  std::vector<int> nearest;
};
DualDistances dualDijkstra(const FaceGraph& graph, const std::vector<double>& edgeLengths,
  const std::vector<int>& sources, double limit = std::numeric_limits<double>::infinity());

/// Relabels so that every label is one connected set of faces (a label spread over several
/// pieces becomes several labels), numbered in order of first face.
std::vector<int> splitIntoConnectedSegments(const FaceGraph& graph, const std::vector<int>& labels);

/// Numbers labels 0.. in order of their first face.
std::vector<int> numberByFirstFace(const std::vector<int>& labels);

/// Neighbouring segments with what their shared boundary holds, merged one pair at a time.
/// Every method's merging (small patches, watershed depth, segment count) runs on this.
class RegionAdjacency
{
public:
  /// What two neighbouring regions share.
  struct Boundary
  {
    double length = 0.0;
    double lowestHeight = 0.0; ///< min over the boundary's dual edges of `edgeHeight` (if given)
  };

  /// Regions are the labels (0..count-1, every face labelled); `edgeHeight` (per dual edge) is
  /// optional and feeds Boundary::lowestHeight.
  RegionAdjacency(
    const FaceGraph& graph, const std::vector<int>& labels, const std::vector<double>* edgeHeight = nullptr);

  int regionCount() const { return static_cast<int>(this->Areas.size()); }
  /// Regions not merged into another yet.
  int liveCount() const { return this->Live; }
  bool alive(int r) const { return this->Parent[r] == r; }
  double area(int r) const { return this->Areas[r]; }
  /// Neighbours of a live region, sorted by region index.
  const std::vector<std::pair<int, Boundary>>& neighbours(int r) const { return this->Neighbours[r]; }
  /// Merges region `from` into `into` (both alive and different); `into` keeps its index.
  void merge(int from, int into);
  /// The live region a region now belongs to.
  int find(int r) const;
  /// Per face, the live region numbered by first face.
  std::vector<int> labels() const;
  /// The neighbour of r with the longest shared boundary (-1 if none; ties to the smaller index).
  int longestBoundaryNeighbour(int r) const;
  /// The neighbour of r with the largest area (-1 if none; ties to the smaller index).
  int largestNeighbour(int r) const;

private:
  std::vector<int> FaceRegion;
  std::vector<double> Areas;
  std::vector<std::vector<std::pair<int, Boundary>>> Neighbours;
  mutable std::vector<int> Parent;
  int Live = 0;
};

/// Merges, smallest area first, every region below `minimumArea` into the neighbour `chooser`
/// picks (largestNeighbour or longestBoundaryNeighbour); regions without neighbours stay.
void mergeSmallRegions(
  RegionAdjacency& regions, double minimumArea, const std::function<int(const RegionAdjacency&, int)>& chooser);

/// Merges the smallest region (by area) into the neighbour `chooser` picks (by default the one it
/// shares the longest boundary with) until at most `count` regions remain (or no region has a
/// neighbour left).
void mergeSmallestUntil(
  RegionAdjacency& regions, int count, const std::function<int(const RegionAdjacency&, int)>& chooser = nullptr);

/// The clean-up every method ends with: segments split into connected pieces, then the smallest
/// pieces merged into the neighbour with the longest shared boundary until `k` remain (never fewer
/// than the dual graph's components, which cannot merge), numbered by first face.
std::vector<int> finalizeSegments(const FaceGraph& graph, const std::vector<int>& labels, int k);

/// How many of k segments each dual-graph component gets: at least one each, the rest in
/// proportion to area (largest remainder, ties to the first component). Needs k >= components.
std::vector<int> segmentsPerComponent(const FaceGraph& graph, int k);

/// Runs `segmentComponent` on every dual-graph component as a mesh of its own, asking each for its
/// share of k (segmentsPerComponent; one segment each when k is smaller than the number of
/// components), and joins the labels. `segmentComponent` gets the component's mesh and its k.
std::vector<int> segmentComponents(
  const FaceGraph& graph, int k, const std::function<std::vector<int>(const TriangleMesh&, int)>& segmentComponent);

/// segmentComponents for methods that read a kerf::Surface (and what it caches): a connected
/// surface is handed over itself, each component of another as a Surface of its own.
std::vector<int> segmentSurfaceComponents(
  const Surface& surface, int k, const std::function<std::vector<int>(const Surface&, int)>& segmentComponent);

/// Runs `segmentComponent` on every dual-graph component as a Surface of its own (a connected
/// surface itself), each choosing its own number of segments (a component of one face stays one
/// segment without the call), and joins the labels, numbered by first face.
std::vector<int> segmentEachSurfaceComponent(
  const Surface& surface, const std::function<std::vector<int>(const Surface&)>& segmentComponent);

} // namespace kerf
