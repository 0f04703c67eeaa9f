// Geometry seam carving's preprocessing: regions, harmonic field, contours, edge costs and ring seams.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <functional>
#include <vector>

namespace kerf
{

/// The per-point region values the seams are computed from (painted by the user).
enum class SeamRegion
{
  Fixed = 0,
  Modeling = 1,
  Handle = 2
};

/// How the ring among a sector contour's candidates is found (Dekkers and Kobbelt 2014, 3.2.3).
enum class RingCandidateSearch
{
  /// One max-flow with the handle boundary as source and the fixed boundary as sink first: when
  /// its cut crosses the sector contour L once, at edge e_i, it is a feasible candidate through
  /// e_i and no candidate is cheaper (every candidate separates the two boundaries), so it is the
  /// paper's minimum. Otherwise every candidate is computed as in Exhaustive.
  GlobalCutFirst,
  /// The paper's loop: one max-flow per edge of L (Fig. 3 and 4), the cheapest kept.
  Exhaustive
};

/// Parameters; the defaults are the paper's (Dekkers and Kobbelt 2014, Fig. 2: alpha = gamma = 1,
/// beta = 0.25, 15 rings).
struct GeometrySeamsOptions
{
  int ringCount = 15;       ///< K + 1, the rings wanted (fewer come back when no more fit)
  int isoContourCount = 10; ///< m: iso-contours at H = j / m, j = 0..m
  int sectorCount = 8;      ///< n: sector contours traced from the handle to the fixed region
  double alpha = 1.0;       ///< weight of the saliency term ang(e)
  double beta = 0.25;       ///< weight of the ring-length normalisation mu(e)
  double gamma = 1.0;       ///< weight of the harmonic term h(e)
  RingCandidateSearch search = RingCandidateSearch::GlobalCutFirst;
  /// Called after each ring with the number of rings done (progress reporting); may be empty.
  std::function<void(int)> ringDone;
};

/// A contour of the quad layout on the modeling region (Dekkers and Kobbelt 2014, Fig. 1).
struct SeamContour
{
  enum class Kind
  {
    Iso = 0,
    Sector = 1
  };
  Kind kind = Kind::Iso;
  int index = 0; ///< j of the iso-contour H = j / m, or i of the sector contour
  std::vector<Vector3> points;
  bool closed = false;
  double length = 0.0;
};

/// What the preprocessing computes. Edge arrays are indexed like the mesh's edges.
struct GeometrySeamsResult
{
  std::vector<double> harmonicField; ///< per vertex: 0 on handle, 1 on fixed points
  std::vector<int> sector;           ///< per vertex: sector of a modeling point, else -1
  std::vector<int> faceSector;       ///< per triangle: sector of a modeling triangle, else -1
  std::vector<int> ring;             ///< per triangle: index of its ring seam, else -1
  std::vector<double> ringCost;      ///< per ring: its min-cut value (sum of capacities cut)
  /// Per edge of the modeling region, each term of Eq. 3 normalised to [0, 1]; -1 elsewhere.
  std::vector<double> saliencyTerm, lengthTerm, harmonicTerm;
  /// Per edge: kappa(e) / (alpha + beta + gamma), in [0, 1] on the modeling region; -1 elsewhere.
  std::vector<double> edgeCost;
  /// Per triangle of the modeling region, the mean edgeCost of its edges; -1 elsewhere.
  std::vector<double> faceCost;
  std::vector<SeamContour> contours; ///< iso-contours j = 0..m, then sector contours
  /// The sector contour L the rings are cut through (least integrated saliency), as vertices
  /// from the handle boundary to the fixed boundary.
  std::vector<int> cutContour;
  int maxFlowCount = 0; ///< max-flow problems solved
};

/// Checks that the modeling region (the triangles with a modeling point) is a ring: one
/// connected annulus (Euler characteristic 0) whose two boundary loops are the handle's and the
/// fixed region's boundaries. `region` holds one value per vertex (0 fixed, 1 modeling,
/// 2 handle; points used by no triangle are ignored). Returns the modeling triangles; throws
/// kerf::Error with a sentence naming the problem otherwise (a value that is not 0, 1 or 2, no
/// handle, no fixed region, no modeling region, a handle point next to a fixed point, several
/// parts, a region reaching the surface's border, not an annulus).
std::vector<int> checkSeamRegions(const TriangleMesh& mesh, const std::vector<double>& region);

/// The preprocessing of Dekkers and Kobbelt 2014 (section 3.2): the harmonic field, the
/// iso- and sector contours, the edge costs of Eq. 3 and up to ringCount disjoint ring seams,
/// cheapest first. `normalConeAngle` is ang(v) of Eq. 4 per vertex (SurfaceDescriptors).
/// Throws kerf::Error for bad regions (checkSeamRegions) and bad options.
GeometrySeamsResult computeGeometrySeams(const TriangleMesh& mesh, const std::vector<double>& region,
  const std::vector<double>& normalConeAngle, const GeometrySeamsOptions& options);

} // namespace kerf
