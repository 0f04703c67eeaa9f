// SeamCut's strokes to constraints (SeamCut, section 2.1.1): paired +/- points on both sides of a stroke.
#pragma once

#include "Geometry/ClosestPoint.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// Parameters of the stroke-to-constraint translation.
struct StrokeOptions
{
  /// Samples per stroke segment (N_S; the paper uses 4).
  int samplesPerSegment = 4;
  /// Offset eps_C from the stroke to each constraint point, in length units (the paper: 1% of
  /// the bounding-box diagonal).
  double offset = 0.0;
  /// When positive, a stroke's offset is at most this fraction of its length, so that the
  /// constraints of a short stroke (a loop round a small part) stay beside it.
  double offsetLengthFraction = 0.05;
  /// The iso-value I the cut should follow: constraints get I + 1 on one side and I - 1 on the
  /// other (0 for a new cut; the current value to refine a cut).
  double isoValue = 0.0;
  /// Stroke points farther than this from the surface are refused, and segments whose chord
  /// strays farther are followed along the surface (length units; 0: no limit, chords kept).
  double maximumDistance = 0.0;
};

/// The constraints made from strokes.
struct StrokeConstraintSet
{
  std::vector<SoftConstraint> constraints; ///< pairs: I + 1 (left of the stroke) then I - 1
  std::vector<Vector3> positions;          ///< each constraint's point on the surface
  std::vector<Vector3> strokeSamples;      ///< the stroke samples projected onto the surface
};

/// For each stroke (a polyline of at least two points), places samplesPerSegment samples on
/// each segment (at the segment's (k + 1/2) / N_S), projects each onto the surface, offsets it by
/// +/- offset along n x t (n the interpolated vertex normal, t the stroke direction: tangent to
/// the surface and orthogonal to the stroke), projects both points onto the surface again and
/// gives them I + 1 and I - 1. Samples where the stroke runs along the normal are skipped.
/// A stroke drawn on the surface stays on it: where a segment's chord strays farther than
/// maximumDistance from the surface (sparse points round a curved part), its samples are placed
/// at the same fractions of its length along the surface instead, the chord's midpoint moved to
/// the nearest surface point and each half followed in turn until it stays within half of
/// maximumDistance.
/// Throws kerf::Error for a stroke point farther than maximumDistance from the surface, a stroke
/// with fewer than two distinct points, NaN coordinates, or no constraint at all.
StrokeConstraintSet strokeConstraints(const TriangleMesh& mesh, const ClosestPointLocator& locator,
  const std::vector<Vector3>& vertexNormals, const std::vector<std::vector<Vector3>>& strokes,
  const StrokeOptions& options);

} // namespace kerf
