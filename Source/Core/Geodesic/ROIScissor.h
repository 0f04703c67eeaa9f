// ROI Scissor: a feature region from clicks, by geodesic discs, a concavity-aware field and a geodesic boundary.
#pragma once

#include "Geodesic/GeodesicPaths.h"
#include "Harmonic/Isolines.h"
#include "Numerics/LaplacianWeights.h"

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace kerf
{

class Surface;

/// A click: a point in space (projected onto the surface) and the geodesic radius r of its
/// candidate disc C(r).
struct ROIClick
{
  Vector3 position = Vector3::Zero();
  double radius = 0.0;
};

struct ROIScissorOptions
{
  /// Vertices nearer than this fraction of r to a click get the value 1 (ROI Scissor, 4.1).
  double innerFraction = 0.1;
  /// Isolines sampled uniformly to choose the boundary from (section 4.2).
  int isolineCount = 50;
  /// The isoline is split into this fraction of the triangles it crosses (section 4.3), at
  /// least 3 parts.
  double segmentFraction = 0.1;
  /// The concavity-aware weights of section 3.1.
  LaplacianWeightOptions weights{ LaplacianWeighting::SmoothConcavity };
  /// The anisotropic geodesics joining the feature points (section 3.2).
  GeodesicPathOptions paths{ AnisotropicMetricOptions{ 1.0, AnisotropyMeasure::Normalized, 0.05 }, 3, false,
    HeatGeodesicOptions() };
  /// A click farther than this fraction of the bounding-box diagonal from the surface is refused.
  double clickTolerance = 1e-3;
};

/// Distance fields from click points by the heat method, kept per point and heat options, so
/// that a selection that gains a click (or changes a radius) computes only the new click's
/// field. A session for filters (SurfaceInput::SessionFor); keeps the last MaximumFields
/// fields. Not thread-safe.
class ClickDistances
{
public:
  explicit ClickDistances(std::shared_ptr<const Surface> surface);

  const Surface& surface() const { return *this->SurfacePointer; }
  /// The distance from `point` per vertex, computed unless kept.
  std::shared_ptr<const std::vector<double>> from(const SurfacePoint& point, const HeatGeodesicOptions& options);
  /// Fields computed so far.
  int computations() const { return this->Computations; }

  static constexpr std::size_t MaximumFields = 16;

private:
  struct Field
  {
    SurfacePoint point;
    std::string options;
    std::shared_ptr<const std::vector<double>> distance;
  };
  std::shared_ptr<const Surface> SurfacePointer;
  std::deque<Field> Fields; // oldest first
  int Computations = 0;
};

/// The union of the geodesic discs of adding clicks, less the discs of subtracting clicks (ROI
/// Scissor, section 4.1): what the geodesic disc filter shows and ROI Scissor's candidate region.
struct GeodesicDiscs
{
  std::vector<SurfacePoint> clicks; ///< the clicks on the surface (added, then subtracted)
  std::vector<double> radii;        ///< their radii
  /// Per click, the geodesic distance from it per vertex (+infinity off its component).
  std::vector<std::shared_ptr<const std::vector<double>>> distances;
  std::vector<char> vertices;       ///< per vertex: inside an added disc and outside every subtracted one
  std::vector<char> faces;          ///< per face: the same rule at its centroid (distances interpolated)
  std::vector<double> nearestAdded; ///< per vertex: the distance to the nearest added click
  std::size_t addedCount = 0;       ///< the first addedCount clicks add their discs
  double area = 0.0;                ///< the area of the faces inside
  double surfaceArea = 0.0;         ///< the area of the whole surface
};

/// The discs C(r) = {i | d_g(i, s) < r} (ROI Scissor, section 4.1) of `added` united, minus those
/// of `subtracted`, with distances by the heat method (`heat`) from each click's surface point,
/// through `distances` when given. Throws kerf::Error for no added click, a click farther than
/// clickTolerance times the bounding-box diagonal from the surface, a radius that is not
/// positive and finite, clicks on different connected components, a region holding no vertex
/// (radius below the distance to the nearest vertex, or every added click inside a subtracted
/// disc) and a region that covers its whole component (radius larger than the mesh).
GeodesicDiscs geodesicDiscs(const Surface& surface, const std::vector<ROIClick>& added,
  const std::vector<ROIClick>& subtracted, double clickTolerance,
  const HeatGeodesicOptions& heat = HeatGeodesicOptions(), ClickDistances* distances = nullptr);

/// ROI Scissor's candidate region (section 4.1) and its boundary constraints.
struct GeodesicDiscRegion
{
  std::vector<SurfacePoint> clicks; ///< the clicks on the surface (added, then subtracted)
  std::vector<char> candidate;      ///< per vertex: inside the union minus the difference of discs
  std::vector<char> candidateFaces; ///< per face: the same rule at its centroid (distances interpolated)
  std::vector<int> oneVertices;     ///< constraints 1 (near an added click)
  std::vector<int> zeroVertices;    ///< constraints 0 (ends of edges crossing the region's border)
};

/// The candidate region of geodesicDiscs (options.clickTolerance, options.paths.heat) and the
/// constraints of section 4.1: vertices within innerFraction r of an added click get 1 (at least
/// the corner nearest to it), both ends of every edge crossing the region's border get 0. Throws
/// kerf::Error for geodesicDiscs' errors, an inner fraction outside (0, 1), inner vertices that
/// meet the border (radius too small) and no inner vertex inside the region (every added click
/// inside a subtracted disc).
GeodesicDiscRegion geodesicDiscRegion(const Surface& surface, const std::vector<ROIClick>& added,
  const std::vector<ROIClick>& subtracted, const ROIScissorOptions& options = ROIScissorOptions(),
  ClickDistances* distances = nullptr);

/// What one ROI Scissor selection produced.
struct ROIScissorResult
{
  std::vector<SurfacePoint> clicks;                     ///< the clicks on the surface (added, then subtracted)
  std::vector<char> candidate;                          ///< per vertex: inside the union minus the difference of discs
  std::vector<int> oneVertices;                         ///< constraints 1 (near an added click)
  std::vector<int> zeroVertices;                        ///< constraints 0 (ends of edges crossing the region's border)
  std::vector<int> regionFaces;                         ///< the faces the field was solved on (the submesh)
  std::vector<double> field;                            ///< per vertex; NaN outside the submesh
  double isovalue = 0.0;                                ///< the best-scored isovalue
  double score = 0.0;                                   ///< its score
  std::vector<SurfaceCurve> isolines;                   ///< the best isoline's closed components (faces of the mesh)
  std::vector<std::vector<SurfacePoint>> featurePoints; ///< per component, section 4.3
  std::vector<GeodesicLoop> boundaries;                 ///< per component, the closed anisotropic geodesic
  std::vector<int> faceLabels;                          ///< per face: 1 inside the region, 0 outside
  /// False when the boundary loops did not separate the click from the rest of the surface (the
  /// labels then follow the best isoline: its side holding the click, within the region).
  bool boundaryEncloses = true;
};

/// ROI Scissor (sections 4.1-4.3). The candidate region and its constraints are those of
/// geodesicDiscRegion (click distances through `distances` when given). The concavity-aware harmonic field is solved on
/// the submesh of the faces touching the region, with weights computed on the whole surface (their curvature is not cut
/// short at the submesh's border). The isoline with the highest score among isolineCount uniform
/// samples is split into k parts of equal length, k = segmentFraction of the triangles it
/// crosses; in each part the crossed triangle whose centroid is most concave (highest mean
/// curvature measured positive on concave regions, as section 3.1 measures H) gives a feature
/// point; the feature points are joined by anisotropic geodesics into a closed loop. Faces are
/// labelled by the side of the loops they are on, the first added click's face inside; when that
/// side reaches past the candidate region (loops that do not separate), by the side of the best
/// isoline instead (boundaryEncloses false).
///
/// Throws kerf::Error for geodesicDiscRegion's errors, options out of range, and a field without
/// a closed isoline.
ROIScissorResult roiScissor(const Surface& surface, const std::vector<ROIClick>& added,
  const std::vector<ROIClick>& subtracted = {}, const ROIScissorOptions& options = ROIScissorOptions(),
  ClickDistances* distances = nullptr);

/// The surface point nearest to `position`; throws kerf::Error if it is farther than
/// tolerance times the bounding-box diagonal.
SurfacePoint projectClick(const Surface& surface, const Vector3& position, double tolerance);

/// Per-face side labels of closed curves on the mesh: faces are joined across each edge, and
/// the label flips when the path between the two faces' centroids (through the edge's midpoint)
/// crosses a curve an odd number of times. `seedFace` gets 1; faces it does not reach get 0.
std::vector<int> labelCurveSides(const TriangleMesh& mesh, const std::vector<SurfaceCurve>& curves, int seedFace);

} // namespace kerf
