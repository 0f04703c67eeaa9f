// Multi-source Dijkstra over the edges of a triangle mesh.
#include "Geodesic/GraphDistance.h"

#include "Error.h"
#include "Mesh/ShortestPaths.h"

#include <limits>

namespace kerf
{

namespace
{
// Dijkstra from the entries already queued, relaxing only where a value gets smaller.
void relax(const TriangleMesh& mesh, DistanceQueue& queue, std::vector<double>& distance)
{
  searchShortestPaths(
    queue, [&](int v) -> double& { return distance[v]; },
    [&](int v, double d, const auto& lower) {
      for (int w : mesh.vertexNeighbors(v))
      {
        lower(w, d + (mesh.point(w) - mesh.point(v)).norm());
      }
    });
}

void checkSource(const TriangleMesh& mesh, int s)
{
  if (s < 0 || s >= mesh.vertexCount())
  {
    throw Error("source vertex " + std::to_string(s) + " is not a vertex of the mesh");
  }
}
} // namespace

std::vector<double> edgeGraphDistances(const TriangleMesh& mesh, const std::vector<int>& sources)
{
  std::vector<double> distance(mesh.vertexCount(), std::numeric_limits<double>::infinity());
  DistanceQueue queue;
  for (int s : sources)
  {
    checkSource(mesh, s);
    if (distance[s] != 0.0)
    {
      distance[s] = 0.0;
      queue.emplace(0.0, s);
    }
  }
  relax(mesh, queue, distance);
  return distance;
}

void lowerEdgeGraphDistances(const TriangleMesh& mesh, int source, std::vector<double>& distance)
{
  checkSource(mesh, source);
  if (distance.size() != static_cast<std::size_t>(mesh.vertexCount()))
  {
    throw Error("the distances to lower need one value per vertex");
  }
  // A vertex whose value the new source cannot lower is not expanded: every path through it is
  // at least as long from the new source as from the old ones (the old values satisfy
  // distance[w] <= distance[v] + |vw| as rounded, and rounding is monotonic).
  DistanceQueue queue;
  if (distance[source] != 0.0)
  {
    distance[source] = 0.0;
    queue.emplace(0.0, source);
  }
  relax(mesh, queue, distance);
}

} // namespace kerf
