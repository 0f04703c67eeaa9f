// Segmentation by feature points and core extraction (Katz, Leifman and Tal 2005; Kouhestani 2013, section 3.6).
#pragma once

#include "Segmentation/BoundaryRefinement.h"
#include "Segmentation/FaceGraph.h"

#include <vector>

namespace kerf
{

struct CoreExtractionOptions
{
  /// Faces kept by the coarsening (farthest-point samples per component; each face joins its
  /// nearest sample). Default 300, at least 10.
  int coarseSize = 300;
  /// A feature point is the largest sum of geodesic distances within this radius, a fraction of the
  /// component's geodesic diameter. Default 0.2 (the best of 0.1 to 0.3 on psb-dev), in (0, 1].
  double featureRadius = 0.2;
  /// Points this close to a convex hull (a fraction of the mirror's radius) count as on it. Default
  /// 0 (the hull's vertices and the points on its faces; 0.01 to 0.05 scored worse on psb-dev), in
  /// [0, 1).
  double hullTolerance = 0.0;
  /// The core grows ring by ring until the feature points lie in different pieces; it stops (and
  /// goes back to where the last feature point was separated) when a ring brings the core closer
  /// to the feature points outside the initial core than this fraction of the initial core's
  /// distance to them. Default 0.5 (the survey's constant), in (0, 1).
  double extensionFactor = 0.5;
  /// A piece holding a feature point becomes a segment when its area is at least this fraction of
  /// its component's; smaller pieces join the core. Default 0.01, in [0, 1).
  double minimumSegmentArea = 0.01;
  /// The boundaries are then moved by minimum cuts (refineSegmentBoundaries); a band of 0 keeps
  /// the coarse boundaries.
  BoundaryRefinementOptions refinement;
};

struct CoreExtractionResult
{
  std::vector<int> labels;       ///< per face, numbered by first face
  std::vector<char> core;        ///< per face, 1 where the extracted core lay (before the cuts)
  std::vector<int> featureFaces; ///< the samples that are prominent feature points, in order
  int featurePoints = 0;
  int coreExtensions = 0; ///< rings added to the cores, summed over the components
  int segmentCount = 0;
};

/// Throws kerf::Error unless every option lies in the range its comment gives.
void checkCoreExtractionOptions(const CoreExtractionOptions& options);

/// Katz, Leifman and Tal 2005 (the survey's section 3.6), one level of their hierarchy, on each
/// dual-graph component: (1) coarsening by farthest-point sampling over centroid paths, each face
/// joining its nearest sample, samples joined where their cells touch, by the shortest path through
/// the two cells; (2) geodesic distances between samples on that graph and a pose-invariant
/// embedding in 3D by classical multidimensional scaling (Torgerson's double centring, the three
/// largest eigenvalues; the paper's non-metric stress iterations are not run); (3) feature points:
/// samples on the embedding's convex hull whose sum of geodesic distances is the largest within
/// featureRadius (equation 1); (4) the core: samples on the convex hull of the embedding mirrored in
/// its bounding sphere (v' = v + 2 (R - |v - C|) (v - C) / |v - C|), grown ring by ring until the
/// feature points are separated (with the paper's backtracking); (5) each piece outside the core
/// holding a feature point is a segment, other pieces join the core; (6) minimum-cut refinement of
/// the boundaries on the full mesh. A component without feature points, or too small to embed, is
/// one segment; so is a flat embedding (a planar patch). Deterministic. Throws kerf::Error for
/// options out of range.
CoreExtractionResult segmentByCoreExtraction(const FaceGraph& graph, const CoreExtractionOptions& options);

} // namespace kerf
