// Geodesic paths: streamlines of a distance field's descent direction, shortest paths and closed loops.
#pragma once

#include "Geodesic/AnisotropicMetric.h"
#include "Geodesic/HeatGeodesics.h"
#include "Geodesic/SurfacePoint.h"

#include <string>
#include <utility>
#include <vector>

namespace kerf
{

class Surface;

/// A path on the surface with its length under the metric it was traced in.
struct SurfacePath
{
  SurfaceCurve curve;
  double length = 0.0;
};

/// The direction in which the distance falls fastest under the metric, per vertex:
/// v*_i = -M_i^-1 g_i (SeamCut, Eq. 2), g_i the area-weighted mean of the gradients of the
/// triangles around i (triangles with an infinite corner left out).
std::vector<Vector3> descentDirections(
  const TriangleMesh& mesh, const std::vector<Vector3>& faceGradients, const AnisotropicMetric& metric);

/// The streamline of `directions` from `start` to the source, integrated with Euler steps of a
/// third of each triangle's size, the field interpolated linearly in each triangle (SeamCut,
/// section 2.2), and crossing edges exactly. Where the field converges onto an edge from both
/// sides the path slides along it, and at a vertex it leaves through the triangle whose corner
/// holds the vertex's direction. It ends exactly on the source: at a source vertex from any
/// triangle around it, at a source point from its triangle or straight across an edge into it,
/// at the nearest point of a source curve from a triangle that holds a segment of it. The path
/// runs from `start` to the source; its length is measured under `metric`. Throws kerf::Error
/// if the streamline stops at a critical point or does not reach the source within a bound of
/// steps.
SurfacePath traceToSource(const TriangleMesh& mesh, const std::vector<Vector3>& directions, const SurfacePoint& start,
  const GeodesicSource& source, const AnisotropicMetric& metric);

/// Length of each segment of a curve under the metric (the tensor interpolated at the segment's
/// midpoint), in the curve's order.
std::vector<double> segmentLengths(
  const TriangleMesh& mesh, const SurfaceCurve& curve, const AnisotropicMetric& metric);

/// Length of a curve under the metric: the sum of its segmentLengths.
double curveLength(const TriangleMesh& mesh, const SurfaceCurve& curve, const AnisotropicMetric& metric);

/// Number of pairs of segments of a curve that cross inside a triangle (segments that share an
/// end point are not counted).
int countSelfCrossings(const TriangleMesh& mesh, const SurfaceCurve& curve);

struct GeodesicPathOptions
{
  /// gamma = 0: isotropic distances by the heat method; otherwise Short-Term Vector Dijkstra
  /// under this metric.
  AnisotropicMetricOptions metric;
  int depth = 3; ///< Short-Term Vector Dijkstra's depth k
  /// Short-Term Vector Dijkstra also for gamma = 0 (isotropic paths as seams trace them).
  bool vectorDijkstra = false;
  HeatGeodesicOptions heat;
};

/// The metric of a surface for these options, cached on it (Surface::derived).
const AnisotropicMetric& anisotropicMetric(const Surface& surface, const AnisotropicMetricOptions& options);

/// The distance from a source under the options' metric, with its gradient per triangle: the
/// heat method (set-up cached on the surface) for gamma = 0 unless `vectorDijkstra`, else
/// Short-Term Vector Dijkstra (the metric cached on the surface), which stops once `targets` are
/// settled (VectorDijkstraOptions::targets; empty: the whole component). Throws kerf::Error for
/// a bad source (checkGeodesicSource), a depth below 1 and a negative or NaN gamma.
GeodesicDistance geodesicDistance(const Surface& surface, const GeodesicSource& source,
  const GeodesicPathOptions& options, const std::vector<int>& targets = {});

/// The shortest path from `from` to `to` under the options' metric: the distance field from
/// `from`, then the streamline traced back from `to`, reversed so that it runs from `from` to
/// `to` and ends exactly on both. Throws kerf::Error for points off the surface or on different
/// connected components.
SurfacePath shortestPath(
  const Surface& surface, const SurfacePoint& from, const SurfacePoint& to, const GeodesicPathOptions& options);

/// A curve through points in order, made of the shortest paths from each point to the next.
struct GeodesicPolyline
{
  SurfacePath path;
  /// Per curve point, the length under the metric from the first point along the curve (a closed
  /// curve returns to its first point at path.length).
  std::vector<double> arcLength;
  /// Per given point, the index of the curve point it became.
  std::vector<int> waypoints;
  /// Where the curve crosses itself (countSelfCrossings); 0 for a simple curve.
  int selfCrossings = 0;
};

/// The legs of geodesicPolyline kept between calls, so that moving one point recomputes only the
/// two legs that end on it. A leg is reused when its two points (face and barycentric
/// coordinates, compared exactly), the options and the surface are the same; after each call only
/// that call's legs are kept.
class GeodesicLegCache
{
public:
  /// Legs traced and legs reused by the last call.
  int computed() const { return this->Computed; }
  int reused() const { return this->Reused; }

private:
  friend GeodesicPolyline geodesicPolyline(
    const Surface&, const std::vector<SurfacePoint>&, bool, const GeodesicPathOptions&, GeodesicLegCache*);
  const Surface* Owner = nullptr;
  std::vector<std::pair<std::string, SurfacePath>> Legs;
  int Computed = 0;
  int Reused = 0;
};

/// The shortest paths from each point to the next (with `closed`, also from the last back to the
/// first), joined into one curve that passes exactly through every point. Throws kerf::Error
/// naming the points for fewer than 2 points (3 when closed), points off the surface
/// (checkSurfacePoint), two consecutive points at the same place, and points on another
/// connected component than the first; otherwise as shortestPath. With a cache, legs whose points
/// did not change since the last call with it are reused (the same result, bit for bit).
GeodesicPolyline geodesicPolyline(const Surface& surface, const std::vector<SurfacePoint>& points, bool closed,
  const GeodesicPathOptions& options, GeodesicLegCache* cache = nullptr);

/// A closed curve through the points in order: geodesicPolyline with `closed`. `selfCrossings`
/// counts where it crosses itself (0 for a simple loop; shortest paths between points given in a
/// bad order can cross). Throws as geodesicPolyline.
struct GeodesicLoop
{
  SurfacePath path;
  int selfCrossings = 0;
};
GeodesicLoop geodesicLoop(
  const Surface& surface, const std::vector<SurfacePoint>& points, const GeodesicPathOptions& options);

} // namespace kerf
