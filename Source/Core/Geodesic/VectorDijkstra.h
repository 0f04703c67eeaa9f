// Anisotropic geodesic distance by Short-Term Vector Dijkstra (Campen et al. 2013).
#pragma once

#include "Geodesic/AnisotropicMetric.h"
#include "Geodesic/SurfacePoint.h"

#include <limits>
#include <vector>

namespace kerf
{

struct VectorDijkstraOptions
{
  /// How many edges back along the predecessor chain a distance update may reach (k of Campen
  /// et al. 2013; SeamCut, section 2.2 uses 3). 1 is plain Dijkstra.
  int depth = 3;
  /// Vertices at which the propagation may stop: once all are settled, it goes on only to
  /// `targetMargin` times their largest distance plus three mean edge lengths (stretched by the
  /// largest lambda1), enough to trace a path back from them. Empty: the whole component.
  std::vector<int> targets;
  double targetMargin = 0.1;
};

/// Distance from the source under the metric: Dijkstra over the mesh edges where a vertex w
/// reached from v is offered, for each of the last `depth` vertices u_j on v's predecessor chain
/// (u_1 = v), d(u_j) + |p_w - p_{u_j}|_M, the metric length of the chain's vector sum measured
/// with the mean tensor of u_j and w (Campen et al. 2013). Paths thus run straight across up to
/// `depth` edges, which removes most of plain Dijkstra's zig-zag excess without needing
/// triangle inequalities in the metric (SeamCut, section 2.2). A chain that reaches the source
/// ends at the source point itself (a point inside a face, or the nearest point of a curve
/// segment), so distances near the source are straight-line distances.
///
/// The result holds only settled vertices: others (other components, or past the stop when
/// targets are given) are +infinity, and so their faces get a zero gradient. Deterministic:
/// ties are broken by vertex index. Throws kerf::Error for a bad source, a depth < 1, or a
/// metric of another mesh.
struct VectorDijkstraResult
{
  std::vector<double> distance;
  /// The vertex each one was reached from (-1 at the source).
  std::vector<int> predecessor;
};

VectorDijkstraResult shortTermVectorDijkstra(const TriangleMesh& mesh, const AnisotropicMetric& metric,
  const GeodesicSource& source, const VectorDijkstraOptions& options = VectorDijkstraOptions());

} // namespace kerf
