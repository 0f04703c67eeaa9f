// Watershed segmentation on the mesh edges with the height 1 - cos(dihedral angle) (Kouhestani 2013, section 3.2).
#pragma once

#include "Segmentation/FaceGraph.h"

#include <vector>

namespace kerf
{

struct WatershedOptions
{
  /// Regions whose watershed depth (lowest saddle to a neighbour minus the region's minimum
  /// height) is below this are merged into that neighbour, shallowest first. Heights lie in
  /// [0, 2]; default 0.05 (the depth of a crease of about 18 degrees).
  double depthThreshold = 0.05;
  /// When positive, merging ignores the threshold and goes on until this many regions remain.
  /// Default 0.
  int segmentCount = 0;
  /// Heights closer than this are equal (plateaus are found on heights rounded to multiples of
  /// it). Default 1e-6.
  double flatTolerance = 1e-6;
};

struct WatershedResult
{
  std::vector<int> labels; ///< per face, numbered by first face
  int basins = 0;          ///< catchment basins (minima) before merging
  int segmentCount = 0;
};

/// The watershed on the edges (Kouhestani 2013, section 3.2): h = 1 - cos(alpha) on every
/// manifold edge, alpha the angle between its faces' normals (flat regions are minima with
/// h = 0); edges are neighbours when they share a face. Minima are flat areas (connected edges of
/// equal height) with no lower neighbour, one basin each. A plateau (a flat area with a lower
/// neighbour) drains through its exits: each plateau edge follows the breadth-first path inside
/// the plateau to the nearest exit, and each exit edge, like every other edge, descends to its
/// lowest neighbour, until a minimum is reached. Each face joins the basin of its lowest edge;
/// pieces of a basin that fall apart become regions of their own. Then the shallowest region is
/// merged into the neighbour across its lowest saddle while its depth is below the threshold (or
/// until segmentCount regions remain). Deterministic. Throws kerf::Error for a negative or NaN
/// threshold or a non-positive tolerance.
WatershedResult segmentByWatershed(const FaceGraph& graph, const WatershedOptions& options);

/// segmentByWatershed by count at every count from lowestCount to highestCount (options.segmentCount
/// ignored), in that order: the merging is run once, down to lowestCount, and each count takes the
/// regions of the moment the merging reached it, so that each result equals segmentByWatershed with
/// that segmentCount. Throws kerf::Error for lowestCount < 1, highestCount < lowestCount, and what
/// segmentByWatershed refuses.
std::vector<WatershedResult> segmentByWatershedAtCounts(
  const FaceGraph& graph, const WatershedOptions& options, int lowestCount, int highestCount);

} // namespace kerf
