// Region growing from labelled strokes under the improved isophotic metric (Easy Mesh Cutting, section 4.2).
#pragma once

#include "Mesh/TriangleMesh.h"
#include "Numerics/LaplacianWeights.h"
#include "Segmentation/IsophoticMetric.h"

#include <string>
#include <vector>

namespace kerf
{

class ClosestPointLocator;
class Surface;

/// A stroke the user drew on the surface, with the label of the part it marks. A single point is
/// a stroke too.
struct LabelledStroke
{
  int label = 0; ///< non-negative (-1 marks vertices no stroke reaches)
  std::vector<Vector3> points;
};

/// The vertices strokes mark, with their labels.
struct StrokeSeeds
{
  std::vector<int> vertices; ///< distinct, in the order the strokes reach them
  std::vector<int> labels;   ///< the label of each seed vertex
  /// Vertices reached by strokes of two different labels: they keep the label of the first
  /// stroke (in input order) that reached them.
  int contested = 0;
};

/// Snaps strokes to vertices: each stroke point to the vertex nearest to its closest surface point
/// (kerf::snapToVertex), and each segment between consecutive points sampled every half mean
/// edge length, each sample snapped the same way, so that the vertices the segment crosses are
/// marked too (where two consecutive ones are not neighbours, also their common neighbour nearest
/// to their midpoint, so that a stroke marks a chain of vertices wherever one exists). Throws kerf::Error for no
/// stroke, a stroke without points, NaN coordinates, a negative label, or a point farther than `maximumDistance`
/// (length units; 0: no limit) from the surface.
StrokeSeeds snapStrokes(const TriangleMesh& mesh, const ClosestPointLocator& locator,
  const std::vector<LabelledStroke>& strokes, double maximumDistance);

/// Parameters of cut placement (kerf::placeCuts).
struct CutPlacementOptions
{
  /// The band between two labels in which a minimum cut places their boundary, as the ratio of a
  /// vertex's distance to its nearest label over its distance to the second nearest (in [0, 1);
  /// 0 keeps the boundary where the fronts meet, the paper's rule). With random walks the
  /// distance to a label is 1 minus its probability, and 0 keeps the walks' boundary.
  double band = 0.3;
  /// The dihedral term's factor on convex edges (concave ones count whole).
  double convexWeight = 0.05;
  /// The weight of the data term (what giving a vertex its farther label costs) against the
  /// boundary's length; without it a short stroke's part can lose all but a rim-bounded piece
  /// (the armadillo's face without the rest of its head).
  double dataWeight = 0.1;
};

/// Where region growing puts the boundaries between labels.
enum class BoundaryPlacement
{
  /// Where the fronts of the labels meet under the metric: the paper's rule (Ji et al. 2006,
  /// section 4.2).
  Fronts,
  /// The fronts, then a minimum cut through the band where they meet (kerf::placeCuts; a band
  /// of 0 keeps the fronts).
  MinimumCut,
  /// Random walks from the strokes on the concavity-aware Laplacian (kerf::randomWalkLabels; Lai
  /// et al. 2009, section 3, with the weights of Au et al. 2011, Eq. 2-3): every vertex and face takes the label a walk
  /// from it most likely reaches first, and walks rarely cross concave creases. An addition to
  /// the paper: a part is not bounded halfway between strokes but where the surface bends inwards,
  /// even when another stroke is nearer. Then, as for MinimumCut, a minimum cut through the band
  /// where each vertex's two most probable labels are close (distances 1 - p; a band of 0 keeps
  /// the walks' boundary): the boundary takes the short, concave way where the walks hesitate. A
  /// vertex the cut gives its second label trades its two labels (the cut's label takes the
  /// larger probability) and the faces around it are labelled again by their corners' two labels.
  RandomWalks
};

/// The placement's name as the benchmark runner spells it: "fronts", "minimum-cut",
/// "random-walks".
std::string boundaryPlacementName(BoundaryPlacement placement);
/// The placement a name spells; throws kerf::Error listing the names for any other text.
BoundaryPlacement parseBoundaryPlacement(const std::string& name);

/// Parameters of region growing.
struct RegionGrowingOptions
{
  IsophoticMetricOptions metric;
  /// Stroke points farther than this from the surface are refused (length units; 0: no limit).
  double maximumDistance = 0.0;
  /// Where the boundaries go (the fronts are grown in every case: they give the distances and
  /// the vertices no stroke reaches).
  BoundaryPlacement placement = BoundaryPlacement::RandomWalks;
  /// The minimum cut's parameters (MinimumCut and RandomWalks).
  CutPlacementOptions cutPlacement;
  /// RandomWalks' edge weights: the concavity-aware weights with the paper's values (Au et al.
  /// 2011, Eq. 2-3: beta = 0.01 at concave vertices).
  LaplacianWeightOptions walkWeights = { LaplacianWeighting::ConcavityAware };
};

/// A grown segmentation.
struct RegionGrowingResult
{
  /// The label of the nearest stroke under the metric (Fronts), moved by the minimum cut
  /// (MinimumCut), or the most probable label, moved to the second where the cut through the
  /// walks' band says so (RandomWalks); -1 where no stroke reaches (a component without strokes,
  /// or a point no triangle uses).
  std::vector<int> vertexLabels;
  /// The metric distance to the nearest stroke (input units); -1 where no stroke reaches. With
  /// random walks, the distance to the nearest stroke of any label.
  std::vector<double> distances;
  /// With random walks, the probability of each vertex's label (kerf::RandomWalkLabelling; where
  /// the cut gave a vertex its second label, the larger of its two probabilities); empty with the
  /// other placements.
  std::vector<double> probabilities;
  /// Per face: from its corners (faceLabelsFromVertices), or with random walks the label of
  /// largest corner probabilities (around vertices the cut moved, over each corner's two labels,
  /// a face that would share its label with no neighbour taking theirs).
  std::vector<int> faceLabels;
  StrokeSeeds seeds;
  /// Vertices used by triangles that no stroke reaches (labelled -1).
  int unreachableVertices = 0;
  /// The distinct labels of the strokes, ascending.
  std::vector<int> labels;
};

/// Multi-source growing (Ji et al. 2006, section 4.2): the seeds start at distance 0, and the
/// unlabelled vertex nearest to a labelled one is taken next (a priority queue ordered by
/// distance, then vertex index), so every vertex reachable from a seed gets the label of its
/// nearest seed along edges of the given lengths; a vertex at equal distance from two labels keeps
/// the one that reached it first. `labels` and `distances` are resized to the vertex count.
void growFromSeeds(const TriangleMesh& mesh, const std::vector<double>& edgeLengths, const StrokeSeeds& seeds,
  std::vector<int>& labels, std::vector<double>& distances);

/// The two nearest labels of every vertex under edge lengths (a Dijkstra search that settles each
/// vertex once per label, at most twice): `first`/`second` are indices into `labels` (-1 where
/// fewer labels reach), `firstDistance`/`secondDistance` their distances (infinity where none).
struct NearestLabels
{
  std::vector<int> labels; ///< the distinct seed labels, ascending
  std::vector<int> first, second;
  std::vector<double> firstDistance, secondDistance;
};
NearestLabels nearestTwoLabels(
  const TriangleMesh& mesh, const std::vector<double>& edgeLengths, const StrokeSeeds& seeds);

/// Cut placement, an addition to the paper's growing (and, with 1 - p as the distance, the last
/// step of the random walks): where the fronts of two labels meet, the
/// boundary lies halfway between their strokes whatever the shape. Every vertex whose distance to
/// its nearest label is more than `band` times its distance to the second nearest is freed, and
/// the freed vertices of each pair of labels are given to one or the other by a minimum cut
/// (Boykov and Kolmogorov 2004) of an energy with two terms, each made dimensionless:
/// - the boundary: per edge cut, the length of its dual (centroid to edge midpoint to centroid)
///   over the mean edge length, divided by 1 + its dihedral term over the mesh's mean (Katz and
///   Tal 2003: 1 - cos of the dihedral angle, times `convexWeight` where the edge is convex), so
///   the boundary takes the shortest and most concave way through the band;
/// - the data: per freed vertex given its farther label, `dataWeight` times its area over the
///   mean vertex area times |d_a - d_b| / (d_a + d_b), so the cut does not stray from the
///   fronts for a small saving of length.
/// Vertices outside the band keep their labels and are the cut's terminals; the pairs are taken
/// in label order, and a vertex freed for another pair is a terminal with its label at that
/// moment (grown, or placed by an earlier pair's cut); a freed vertex the cut leaves undecided
/// (no flow reaches it) takes the larger label of its pair. `nearest` is
/// nearestTwoLabels of the strokes' seeds; `labels` and `distances` are the growing's
/// (growFromSeeds, or `nearest`'s first labels); a relabelled vertex takes the distance to its
/// new label. Throws kerf::Error for a band outside [0, 1), negative weights or arrays of
/// another mesh.
void placeCuts(const TriangleMesh& mesh, const NearestLabels& nearest, const CutPlacementOptions& options,
  std::vector<int>& labels, std::vector<double>& distances);

/// Face labels from vertex labels: the label two or three corners share; a face whose three
/// corners differ takes the label of the corner nearest to its stroke (smallest distance, then
/// smallest label).
std::vector<int> faceLabelsFromVertices(
  const TriangleMesh& mesh, const std::vector<int>& vertexLabels, const std::vector<double>& distances);

/// Region growing on a surface (its descriptors, metric lengths and Laplacian weights are cached
/// there), its boundaries placed as `options.placement` says. Throws
/// kerf::Error for the stroke problems of snapStrokes and for strokes of fewer than two labels.
RegionGrowingResult growRegions(
  const Surface& surface, const std::vector<LabelledStroke>& strokes, const RegionGrowingOptions& options);

/// A boundary between two labels: a chain of mesh edges, each between a face of `leftLabel` and
/// one of `rightLabel`, with leftLabel < rightLabel and the leftLabel face on the left of the
/// chain's direction seen from outside (the side where the edge follows its face's orientation).
struct LabelBoundary
{
  int leftLabel = -1;
  int rightLabel = -1;
  std::vector<int> vertices; ///< a closed chain does not repeat its first vertex
  bool closed = false;
};

/// The boundaries of a per-face labelling: the edges between differently labelled faces, joined
/// into chains that end where three or more labels meet, where the chain meets the mesh's border or
/// itself (a vertex with more than two such edges) or where the label pair changes; the others are
/// closed loops. Chains come in order of their first vertex, so the result is deterministic.
std::vector<LabelBoundary> labelBoundaries(const TriangleMesh& mesh, const std::vector<int>& faceLabels);

} // namespace kerf
