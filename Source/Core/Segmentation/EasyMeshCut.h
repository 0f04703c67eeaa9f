// Easy Mesh Cutting in one call: region growing from labelled strokes, then optionally the boundaries refined as
// snakes.
#pragma once

#include "Segmentation/RegionGrowing.h"
#include "Segmentation/SnakeRefinement.h"

#include <memory>
#include <vector>

namespace kerf
{

/// Parameters of Easy Mesh Cutting (Ji et al. 2006, sections 3, 4.2 and 5.1).
struct EasyMeshCutOptions
{
  RegionGrowingOptions growing;
  /// Refine the grown boundaries as snakes (section 5.1). Default on, as in the paper.
  bool refine = true;
  SnakeOptions snake;
  /// Override strokes (section 5.2), applied in order after the refinement (or to the grown
  /// boundary without it): each replaces the boundary within `overrideRadius` of it by itself
  /// (kerf::BoundarySnake::overrideWithStroke).
  std::vector<std::vector<Vector3>> overrides;
  /// Length units; must be positive when there are overrides.
  double overrideRadius = 0.0;
};

/// One boundary between two labels, as points on the surface.
struct EasyMeshCutBoundary
{
  int leftLabel = -1;
  int rightLabel = -1;
  bool closed = false; ///< a closed boundary does not repeat its first point
  std::vector<Vector3> points;
  double length = 0.0; ///< along the points, closing segment included
};

/// The segmentation of Easy Mesh Cutting.
struct EasyMeshCutResult
{
  /// Per face: the grown labels, or the snakes' labels after refinement; -1 where no stroke reaches.
  std::vector<int> faceLabels;
  /// Per vertex: the metric distance to the nearest stroke (input units); -1 where none reaches.
  std::vector<double> distances;
  /// Without refinement the boundaries along mesh edges, with it the snakes.
  std::vector<EasyMeshCutBoundary> boundaries;
  RegionGrowingResult growing;
  SnakeStatistics snake; ///< all zero without refinement
};

/// The boundaries of a per-face labelling (any segmentation's; -1 is a label too) as snakes
/// (kerf::BoundarySnake): refined when options.refine (section 5.1), then edited by
/// options.overrides (section 5.2, stroke points no farther than options.growing.maximumDistance
/// from the surface; 0: no limit). The result's faceLabels and boundaries are the snakes', its
/// snake statistics the refinement's; distances and growing stay empty. Throws kerf::Error as
/// BoundarySnake and overrideWithStroke do.
EasyMeshCutResult refineBoundaries(
  const std::shared_ptr<const Surface>& surface, const std::vector<int>& faceLabels, const EasyMeshCutOptions& options);

/// Region growing from the strokes (kerf::growRegions), then, with options.refine, the boundaries
/// as snakes (kerf::BoundarySnake::refine), then the override strokes. Throws kerf::Error as
/// growRegions, BoundarySnake and overrideWithStroke do (no stroke, strokes of fewer than two
/// labels, stroke points off the surface, edges shared by three triangles, an override away from
/// every boundary or with a radius that is not positive).
EasyMeshCutResult easyMeshCut(const std::shared_ptr<const Surface>& surface, const std::vector<LabelledStroke>& strokes,
  const EasyMeshCutOptions& options);

} // namespace kerf
