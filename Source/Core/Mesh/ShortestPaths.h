// Dijkstra's loop, once for the graphs Kerf searches: mesh edges (edge-graph distances, region
// growing, curve export, Short-Term Vector Dijkstra's chains), face graphs (segment spines, the
// dual Dijkstra of the segmentations, with its tie rule in the arcs), patch graphs (spectral
// segmentation) and the cut graph of CutToDisk. Region growing's two nearest labels keep a loop of
// their own: their nodes are (vertex, label) pairs holding two distances per vertex.
#pragma once

#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace kerf
{

/// A queue of (distance, node), the nearest on top, ties by the smaller node.
using DistanceEntry = std::pair<double, int>;
using DistanceQueue = std::priority_queue<DistanceEntry, std::vector<DistanceEntry>, std::greater<DistanceEntry>>;

/// Dijkstra's loop from the nodes already in `queue` (Dijkstra 1959), with lazy deletion: an
/// entry whose distance is no longer its node's is skipped. `distance(v)` is a reference to v's
/// current value. For each node taken off the queue at distance d, `settle(v, d)` may return true
/// to stop the search there (a target reached); otherwise `arcs(v, d, lower)` calls
/// `lower(w, candidate)` for each arc from v, with the candidate distance it computes: `lower`
/// sets w's value to the candidate where that is smaller, queues w and returns true (so that the
/// caller can record how w was reached), and returns false otherwise. Returns true when `settle`
/// stopped the search. The order of the queue and of the arcs fixes the result bit for bit.
template <typename Distance, typename Arcs, typename Settle>
bool searchShortestPaths(DistanceQueue& queue, Distance&& distance, Arcs&& arcs, Settle&& settle)
{
  while (!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance(v))
    {
      continue;
    }
    if (settle(v, d))
    {
      return true;
    }
    arcs(v, d, [&](int w, double candidate) {
      double& current = distance(w);
      if (candidate < current)
      {
        current = candidate;
        queue.emplace(candidate, w);
        return true;
      }
      return false;
    });
  }
  return false;
}

/// searchShortestPaths without a stop.
template <typename Distance, typename Arcs>
void searchShortestPaths(DistanceQueue& queue, Distance&& distance, Arcs&& arcs)
{
  searchShortestPaths(queue, distance, arcs, [](int, double) { return false; });
}

} // namespace kerf
