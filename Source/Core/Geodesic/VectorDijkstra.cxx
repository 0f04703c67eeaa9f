// Short-Term Vector Dijkstra: Dijkstra whose updates measure straight chords along the predecessor chain.
#include "Geodesic/VectorDijkstra.h"

#include "Error.h"
#include "Mesh/ShortestPaths.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace kerf
{

namespace
{
Vector3 closestOnSegment(const Vector3& p, const Vector3& a, const Vector3& b)
{
  const Vector3 d = b - a;
  const double squared = d.squaredNorm();
  const double s = squared > 0.0 ? std::clamp((p - a).dot(d) / squared, 0.0, 1.0) : 0.0;
  return a + s * d;
}
} // namespace

VectorDijkstraResult shortTermVectorDijkstra(const TriangleMesh& mesh, const AnisotropicMetric& metric,
  const GeodesicSource& source, const VectorDijkstraOptions& options)
{
  checkGeodesicSource(mesh, source);
  if (options.depth < 1)
  {
    throw Error("the vector Dijkstra depth must be at least 1, got " + std::to_string(options.depth));
  }
  const int n = mesh.vertexCount();
  if (!metric.isotropic && static_cast<int>(metric.tensors.size()) != n)
  {
    throw Error("the anisotropic metric does not belong to this mesh (wrong number of vertices)");
  }
  for (int v : options.targets)
  {
    if (v < 0 || v >= n)
    {
      throw Error("target vertex " + std::to_string(v) + " is not a vertex of the mesh");
    }
  }
  const double infinity = std::numeric_limits<double>::infinity();
  VectorDijkstraResult result;
  result.distance.assign(n, infinity);
  result.predecessor.assign(n, -1);
  std::vector<Vector3> origin(n, Vector3::Zero()); // where a chain that reaches the source ends
  std::vector<char> settled(n, 0);

  DistanceQueue queue;
  auto seed = [&](int v, const Vector3& from, const Eigen::Matrix3d& tensor) {
    const Vector3 d = mesh.point(v) - from;
    const double length = metric.isotropic ? d.norm() : std::sqrt(std::max(d.dot(tensor * d), 0.0));
    if (length < result.distance[v])
    {
      result.distance[v] = length;
      origin[v] = from;
      queue.emplace(length, v);
    }
  };
  for (int v : source.vertices)
  {
    seed(v, mesh.point(v), Eigen::Matrix3d::Identity());
  }
  for (const SurfacePoint& p : source.points)
  {
    const Vector3 x = surfacePosition(mesh, p);
    const Eigen::Matrix3d tensor = metric.tensorAt(mesh, p.face, p.barycentric);
    for (int c : mesh.triangle(p.face))
    {
      seed(c, x, tensor);
    }
  }
  for (const SurfaceCurve& curve : source.curves)
  {
    const int segments = segmentCount(curve);
    for (int i = 0; i < segments; ++i)
    {
      const Vector3& a = curve.points[i];
      const Vector3& b = curve.points[(i + 1) % curve.points.size()];
      for (int c : mesh.triangle(curve.faces[i]))
      {
        const Vector3 q = closestOnSegment(mesh.point(c), a, b);
        const Eigen::Matrix3d tensor = metric.isotropic ? Eigen::Matrix3d::Identity() : metric.tensors[c];
        seed(c, q, tensor);
      }
    }
  }

  // The stop once every target is settled.
  double meanEdge = 0.0;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const std::array<int, 2>& ev = mesh.edgeVertices(e);
    meanEdge += (mesh.point(ev[1]) - mesh.point(ev[0])).norm();
  }
  meanEdge /= std::max(mesh.edgeCount(), 1);
  const double stretch =
    metric.isotropic ? 1.0 : std::sqrt(*std::max_element(metric.lambda1.begin(), metric.lambda1.end()));
  int targetsLeft = 0;
  std::vector<char> isTarget(n, 0);
  for (int v : options.targets)
  {
    if (!isTarget[v])
    {
      isTarget[v] = 1;
      ++targetsLeft;
    }
  }
  double stop = infinity;
  double farthestTarget = 0.0;

  // A vertex is settled when it leaves the queue; the search stops at the first distance past
  // `stop`. Arcs to settled vertices are not relaxed, so a chain never runs through a later vertex.
  searchShortestPaths(
    queue, [&](int v) -> double& { return result.distance[v]; },
    [&](int v, double, const auto& lower) {
      const Vector3& pv = mesh.point(v);
      for (int w : mesh.vertexNeighbors(v))
      {
        if (settled[w])
        {
          continue;
        }
        const Vector3& pw = mesh.point(w);
        Vector3 chord = pw - pv;
        int u = v;
        double best = infinity;
        for (int j = 0; j < options.depth; ++j)
        {
          const double candidate = result.distance[u] + metric.length(chord, u, w);
          best = std::min(best, candidate);
          const int previous = result.predecessor[u];
          if (previous < 0)
          {
            // The chain reaches the source: end it at the source point.
            const Vector3 fromOrigin = chord + (mesh.point(u) - origin[u]);
            const double direct = metric.length(fromOrigin, u, w);
            best = std::min(best, direct);
            break;
          }
          chord += mesh.point(u) - mesh.point(previous);
          u = previous;
        }
        if (lower(w, best))
        {
          result.predecessor[w] = v;
        }
      }
    },
    [&](int v, double d) {
      if (d > stop)
      {
        return true;
      }
      settled[v] = 1;
      if (isTarget[v])
      {
        farthestTarget = std::max(farthestTarget, d);
        if (--targetsLeft == 0)
        {
          stop = (1.0 + options.targetMargin) * farthestTarget + 3.0 * meanEdge * stretch;
        }
      }
      return false;
    });
  for (int v = 0; v < n; ++v)
  {
    if (!settled[v])
    {
      result.distance[v] = infinity;
      result.predecessor[v] = -1;
    }
  }
  return result;
}

} // namespace kerf
