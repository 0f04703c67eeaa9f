// Simulated ROI Scissor clicks made from a segmentation, and the segmentation their regions make.
#pragma once

#include "Geodesic/ROIScissor.h"

#include <memory>
#include <vector>

namespace kerf
{

class Surface;

/// The order in which the simulated user selects the pieces.
enum class SimulatedClickOrder
{
  Extremities,  ///< the pieces with the fewest unselected neighbours first, then the smallest
  SmallestFirst ///< the smallest area first
};

/// Where in a part the simulated user clicks to add a disc.
enum class SimulatedClickPlacement
{
  SpineMiddle, ///< the middle face of the part's spine (kerf::segmentSpines)
  Innermost    ///< the face farthest from the part's border
};

/// How the simulated user clicks.
struct SimulatedClickOptions
{
  SimulatedClickOrder order = SimulatedClickOrder::Extremities;
  SimulatedClickPlacement placement = SimulatedClickPlacement::SpineMiddle;
  /// The spine's depth (kerf::segmentSpines) for SpineMiddle.
  double spineDepth = 0.2;
  /// The first click selects the piece together with the regions selected before that hang
  /// from it (joined to it through claimed faces), so that the region's boundary need only part
  /// the piece from what is still unselected.
  bool includeClaimed = true;
  /// An adding click's radius: this times the largest geodesic distance from the click to the
  /// vertices of the faces it should hold (so the disc holds them and a margin past them).
  double radiusMargin = 1.2;
  /// At most this many clicks per piece: the first, then corrections while the region is wrong.
  int clicksPerPiece = 4;
  /// A piece is corrected while its region is wrong (faces in one and not the other) by more than
  /// this fraction of the piece's area ...
  double correctionThreshold = 0.1;
  /// ... and by more than this fraction of the whole surface's area.
  double surfaceThreshold = 0.017;
  ROIScissorOptions scissor;
};

/// One click of the simulated user, as ROI Scissor takes it.
struct SimulatedClick
{
  int piece = -1;        ///< the piece it selects (see ClickedSegmentation::pieceLabels)
  ROIClick click;        ///< a point on the surface (a face's centroid) and a radius
  bool subtract = false; ///< subtracts its disc instead of adding it
  bool kept = true;      ///< false when the user undid it (the region got no better)
  double error = 1.0;    ///< the piece's error (as ClickedSegmentation::pieceErrors) with this click
};

/// What the simulated user selected.
struct ClickedSegmentation
{
  std::vector<int> labels;            ///< per face: the intended label of the region that claimed it
  std::vector<SimulatedClick> clicks; ///< every click made, in order (undone ones included)
  std::vector<int> pieceLabels;       ///< per piece: its intended label (-1: unlabelled faces)
  std::vector<int> order;             ///< the pieces in the order they were selected (not the rest)
  /// Per piece: the area its region got wrong (its faces outside the region, and the region's faces
  /// outside it that no region claimed before), over the area of its faces no region claimed
  /// before; 1 where it got no region, 0 for the rest.
  std::vector<double> pieceErrors;
  std::vector<double> pieceMissed; ///< per piece: the part of that error inside the piece
  int restPiece = -1;              ///< the piece nobody clicks: what the regions leave
  int refused = 0;                 ///< ROI Scissor runs refused (kerf::Error): no region from them
};

/// ROI Scissor (one feature region per run, repeated clicks uniting and subtracting discs: ROI
/// Scissor, sections 4.1 and 5.2) driven by a simulated user who sees `intended` (per face; -1
/// faces are never clicked) and selects it piece by piece, as the paper's users segmented whole
/// benchmark models (section 5.3). A piece is a connected set of faces of one label. The largest
/// piece is not clicked: it is the rest, what the regions leave. The others are selected one after
/// the other, extremities first (SimulatedClickOrder). For each, the target is its faces no earlier
/// region claimed; the first click adds a disc at the middle of the spine (or the innermost face)
/// of the target and the claimed regions hanging from it, with radiusMargin times the farthest
/// geodesic distance from the click to them (capped halfway to the surface's farthest vertex, so
/// that the disc never covers it). The region ROI Scissor selects, less the faces claimed already,
/// is compared with the target; while it is wrong by more than both thresholds and
/// clicksPerPiece allows, one more click corrects the larger error: an adding click in the
/// largest connected part of the target the region missed (placed and sized as above, for that
/// part), or a subtracting click at the innermost face of the largest part it took beyond the
/// target, with the radius that stops the disc at the target. A correction that does not make
/// the region better is undone (it still counts as a click) and not made again; a region worse
/// than none (error 1 or more) is undone. The region then claims its faces for the piece's label:
/// a face claimed once stays with the first piece that claimed it; the faces no region claimed
/// get the rest's label. Deterministic: ties go to the lower face index. Throws kerf::Error for a
/// labelling of the wrong size or options out of range.
ClickedSegmentation selectByClicks(const std::shared_ptr<const Surface>& surface, const std::vector<int>& intended,
  const SimulatedClickOptions& options = SimulatedClickOptions());

} // namespace kerf
