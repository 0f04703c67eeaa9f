// Multi-source Dijkstra over the edges of a triangle mesh.
#include "Geodesic/GraphDistance.h"

#include "Error.h"

#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace kerf
{

std::vector<double> edgeGraphDistances(const TriangleMesh& mesh, const std::vector<int>& sources)
{
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> distance(mesh.vertexCount(), infinity);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int s : sources)
  {
    if (s < 0 || s >= mesh.vertexCount())
    {
      throw Error("source vertex " + std::to_string(s) + " is not a vertex of the mesh");
    }
    if (distance[s] != 0.0)
    {
      distance[s] = 0.0;
      queue.emplace(0.0, s);
    }
  }
  while (!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v])
    {
      continue;
    }
    const IndexRange neighbors = mesh.vertexNeighbors(v);
    for (int w : neighbors)
    {
      const double candidate = d + (mesh.point(w) - mesh.point(v)).norm();
      if (candidate < distance[w])
      {
        distance[w] = candidate;
        queue.emplace(candidate, w);
      }
    }
  }
  return distance;
}

} // namespace kerf
