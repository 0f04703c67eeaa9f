// Isolines of a piecewise-linear field: extraction, ROI Scissor's score, and the cut's two sides.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// One connected component of an isoline, as a polyline across faces.
struct Isoline
{
  std::vector<Vector3> points;
  /// faces[i] holds the segment from points[i] to points[i + 1]; for a closed isoline the last
  /// face holds the segment from the last point back to the first.
  std::vector<int> faces;
  bool closed = false;
  double length = 0.0;
};

/// Extracts the isoline f = value as polylines. A vertex whose value equals `value` exactly
/// counts as above it (symbolic perturbation), so each triangle is crossed by at most one
/// segment, flat regions are bounded rather than filled, and components never branch. Crossing
/// points are computed once per edge; points where the isoline passes through a vertex are not
/// repeated. Segments follow the faces' orientation consistently: walking along an isoline, the
/// values above `value` lie on the same side everywhere. Needs an edge-manifold, consistently
/// oriented mesh. Components are ordered by their first face. A crossing within 1e-12 of its
/// edge's length from a vertex is placed on the vertex, so near-ties give no vanishing segments.
std::vector<Isoline> extractIsolines(const TriangleMesh& mesh, const std::vector<double>& field, double value);

/// ROI Scissor's score of a set of polylines (ROI Scissor, section 4.2):
/// S = sum_T |I cap T| / |I| * |grad f_T|, the length-weighted mean gradient magnitude.
double isolineScore(const std::vector<Isoline>& isolines, const std::vector<double>& gradientMagnitudes);

/// The score of every candidate isovalue.
struct IsovalueScore
{
  double value = 0.0;
  double score = 0.0;
  double length = 0.0;
};

/// Scores `count` isovalues sampled uniformly strictly inside the field's range
/// (value_i = min + i (max - min) / (count + 1), i = 1..count) in one pass over the faces,
/// without building polylines. Empty if the field is constant.
std::vector<IsovalueScore> scoreIsovalues(
  const TriangleMesh& mesh, const std::vector<double>& field, const std::vector<double>& gradientMagnitudes, int count);

/// Index of the isoline nearest to a set of points (smallest mean distance from the points to
/// the polyline), or -1 if there is none.
int nearestIsoline(const std::vector<Isoline>& isolines, const std::vector<Vector3>& points);

/// A cut: chosen components of the isoline f = value of one field.
struct FieldCut
{
  const std::vector<double>* field = nullptr;
  double value = 0.0;
  std::vector<const Isoline*> components;
};

/// Per-face segment labels for any number of cuts: for each cut, a face is on its upper side when
/// the mean of its corner values is >= the cut's value; two neighbouring faces are separated when
/// some cut puts them on different sides and one of them holds a segment of that cut's chosen
/// components. Faces are grouped into connected components that are not separated, numbered in
/// order of their first face. Elsewhere both sides of an isoline stay connected.
std::vector<int> labelCuts(const TriangleMesh& mesh, const std::vector<FieldCut>& cuts);

/// A cut made from a stroke, with what the stroke says about it.
struct CutWithStroke
{
  FieldCut cut;
  std::vector<Vector3> stroke; ///< the stroke's points, on or near the surface
  /// The faces of the stroke's constraint points in pairs, one on each side of the stroke
  /// (StrokeConstraintSet's order: the + point, then the - point).
  std::vector<int> sideFaces;
};

/// The segments several strokes intend, each stroke with its own cut (SeamCut's cuts from
/// several strokes). Cutting along every cut's whole isoline over-segments: an isoline goes on
/// past the ends of an open stroke (at a T-junction, where the stroke's boundary meets another)
/// and splits segments no stroke separates. So the regions of labelCuts are merged again, under
/// one rule: the two sides of every stroke stay apart (each pair of constraint points is a
/// must-separate pair). Neighbouring regions are merged in order of how weakly a stroke supports
/// the boundary between them (the fraction of its length where the separating cut runs within
/// `supportDistance` of its own stroke; ties by shorter boundary first), skipping merges that
/// would join the two sides of a stroke. Extensions of an isoline beyond its stroke are
/// unsupported, so the pieces they cut off join the segment they came from before anything
/// else can happen to them. Only strokes their cut follows count (most of the stroke within
/// supportDistance of the isoline), and of those only the pairs of constraint points their cut
/// puts on two sides (round a region smaller than the constraints' offset, both points of a
/// pair fall outside it). Last, each side of each stroke has a home, the segment holding most of its
/// constraint points; a segment that is no side's home (a small piece between cuts crossing
/// near a junction, holding a few points of two strokes) joins the neighbour it shares the
/// longest boundary with. Segments are numbered in order of their first face.
std::vector<int> labelStrokeCuts(
  const TriangleMesh& mesh, const std::vector<CutWithStroke>& cuts, double supportDistance);

/// labelCuts for a single cut, without slivers: a region made only of faces the cut runs through
/// (cut off from both sides where the cut ends on a hole) joins the neighbour it shares the most
/// edges with.
std::vector<int> labelCutSides(
  const TriangleMesh& mesh, const std::vector<double>& field, double value, const std::vector<const Isoline*>& cut);

} // namespace kerf
