// Boundaries between labels as snakes on the mesh, refined greedily and edited by override strokes (Easy Mesh Cutting,
// section 5).
#pragma once

#include "Mesh/TriangleMesh.h"

#include <memory>
#include <vector>

namespace kerf
{

class Surface;

/// Parameters of the refinement (Ji et al. 2006, section 5.1).
struct SnakeOptions
{
  /// The most sweeps over the snaxels.
  int iterations = 100;
  /// A sweep in which no snaxel moves farther than this fraction of the mean edge length (and no
  /// vertex snaxel splits) ends the refinement.
  double convergence = 0.01;
  /// Added to E_ext = |k_min| + |k_max| (curvatures of the mesh scaled into a unit bounding box,
  /// as the metric): with the paper's product E_int * E_ext alone, every position in a flat region
  /// has zero energy and the snake would not straighten there.
  double curvatureOffset = 1.0;
  /// Evenly spaced positions a snaxel tries along its edge in a slide (both ends included), besides
  /// the position that straightens it.
  int slideSamples = 8;
};

/// What a refinement did.
struct SnakeStatistics
{
  int sweeps = 0;   ///< sweeps run
  int slides = 0;   ///< snaxel moves along their edges
  int splits = 0;   ///< vertex snaxels split onto the edges of the other side
  int removals = 0; ///< snaxels removed by splits (their two segments would share a triangle)
  bool converged = false;
};

/// A point of a snake: a snaxel on a mesh edge (at a vertex when its parameter is 0 or 1), or the
/// meeting point of three labels inside a face.
struct SnakePoint
{
  Vector3 position = Vector3::Zero();
  int edge = -1;  ///< the supporting edge, or -1 for a meeting point
  double t = 0.0; ///< from the edge's first vertex (edgeVertices(edge)[0]) to its second
  int face = -1;  ///< the face of a meeting point, or -1
};

/// One boundary curve between two labels: consecutive points lie in a common triangle, coincident
/// consecutive snaxels (a vertex snaxel) appear once. The smaller label is on the left seen from
/// outside.
struct SnakeCurve
{
  int leftLabel = -1;
  int rightLabel = -1;
  bool closed = false; ///< a closed curve does not repeat its first point
  std::vector<SnakePoint> points;
};

/// The boundaries of a per-face labelling as snakes (Ji et al. 2006, section 5.1), embedded in the
/// mesh: every vertex has a label; each edge whose two vertices differ carries one snaxel at a
/// parameter in [0, 1]; a face with two labels holds one snake segment between its two snaxels, a
/// face with three the meeting point (the mean of its three snaxels). So segments always lie
/// inside triangles, no two consecutive segments share one, and the snake cannot cross itself.
/// A vertex snaxel is a vertex where every snaxel of its edges sits. The three operations:
/// - slide: a snaxel moves along its edge to the position that maximises its energy;
/// - split: a vertex snaxel whose corner is cut on its own label's side changes the vertex's
///   label: snaxels appear on the edges to its former neighbours (at the vertex, to slide away);
/// - removal: the snaxels of the vertex's other edges, whose segments would now share triangles,
///   disappear with the split.
/// A vertex splits only where its neighbours form one run of each of the two labels and it is not
/// on the mesh's border, so regions neither split nor merge; snaxels on the mesh's border and in
/// faces where three labels meet stay where they are.
///
/// The initial snake follows the labelling's boundary along mesh edges: a vertex takes the label
/// its faces share, or the smallest label among them where they differ (then a vertex whose
/// neighbours all carry one other label takes theirs: it would hold no face of its own), and each
/// snaxel sits at the end of its edge that lies on the boundary.
class BoundarySnake
{
public:
  /// Throws kerf::Error when `faceLabels` does not have one label per face or the mesh has edges
  /// shared by three or more triangles.
  BoundarySnake(std::shared_ptr<const Surface> surface, const std::vector<int>& faceLabels);

  const Surface& surface() const { return *this->SharedSurface; }

  /// Greedy maximisation of E_snake = E_int * E_ext at each snaxel (Ji et al. 2006, section 5.1):
  /// E_int = theta, the angle in [0, pi] between its two segments projected onto its tangent plane,
  /// E_ext = |k_min| + |k_max| (plus options.curvatureOffset), both interpolated along the edge.
  /// Each sweep slides every movable snaxel to its best position with its neighbours fixed, then
  /// splits the vertex snaxels whose straightening lies on their own side. Throws kerf::Error for
  /// invalid options.
  SnakeStatistics refine(const SnakeOptions& options);

  /// Boundary editing by an override stroke (Ji et al. 2006, section 5.2): the boundary within
  /// `radius` (length units) of the stroke, where the stroke passes beside it rather than beyond its
  /// ends, is replaced by the stroke itself: every vertex of that band takes the label of its side of
  /// the stroke (the side's label being the one of the band's two labels found there more often)
  /// and the snaxels of the edges the stroke crosses sit where it crosses them. Throws kerf::Error
  /// for a stroke with fewer than two points, NaN points, points farther than `maximumDistance`
  /// from the surface (0: no limit), a radius that is not positive, or a band holding a single
  /// label (a stroke away from any boundary).
  void overrideWithStroke(const std::vector<Vector3>& stroke, double radius, double maximumDistance);

  /// The vertices' labels (-1 for points no triangle uses).
  const std::vector<int>& vertexLabels() const { return this->Labels; }
  /// Per face: the label of its vertices, or where the snake crosses it the label holding the
  /// larger part of its area (ties: the smaller label).
  std::vector<int> faceLabels() const;
  /// The snake as curves between labels, in a deterministic order.
  std::vector<SnakeCurve> curves() const;

private:
  struct Chain;
  std::vector<Chain> chains() const;
  /// Adds edges that may have become cut (the cut edges are kept sorted, without the stale ones).
  void noteCutCandidates(const IndexRange& edges) const;
  void updateCutEdges() const;
  Vector3 snaxelPosition(int edge, double t) const;
  Vector3 snaxelPosition(int edge) const;
  bool isCut(int edge) const;
  int faceLabelCount(int face) const;
  bool isFixedSnaxel(int edge) const;
  bool canSplit(int vertex) const;
  double snaxelEnergy(const Vector3& previous, const Vector3& position, const Vector3& next, int edge, double t) const;
  SnakePoint meetingPoint(int face) const;

  std::shared_ptr<const Surface> SharedSurface;
  const TriangleMesh& Mesh;
  std::vector<int> Labels;           ///< per vertex
  std::vector<double> Parameters;    ///< per edge, meaningful where the edge is cut
  mutable std::vector<int> CutEdges; ///< sorted; may hold stale entries until updateCutEdges
  mutable std::vector<int> CutCandidates;
  mutable std::vector<char> Visited;   ///< per edge, all 0 between calls of chains()
  const std::vector<Vector3>& Normals; ///< the surface's cached vertex normals
  std::vector<double> TotalCurvature;  ///< |k_min| + |k_max| per vertex, unit-box scale
  double MeanEdgeLength = 0.0;
  double CurvatureOffset = 1.0; ///< of the refinement running
};

} // namespace kerf
