// The edge watershed: minima, plateaus drained breadth first, descent, faces to their lowest edge, merging by depth.
#include "Segmentation/WatershedSegmentation.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <string>

namespace kerf
{

namespace
{
// The dual edges that share a face with dual edge e.
template <typename Visit>
void forEachEdgeNeighbour(const FaceGraph& graph, int e, const Visit& visit)
{
  for (int f : graph.edge(e).faces)
  {
    for (int other : graph.faceEdges(f))
    {
      if (other >= 0 && other != e)
      {
        visit(other);
      }
    }
  }
}

// The basin each dual edge drains into (one label per minimum), and how many minima there are.
std::vector<int> drainEdges(const FaceGraph& graph, const std::vector<long long>& level, int& basins)
{
  const int m = graph.edgeCount();
  std::vector<int> downstream(m, -1); // the next edge on the way down; -1 for minima
  // Flat areas: connected edges of equal level.
  std::vector<int> flat(m, -1);
  std::vector<int> members;
  std::vector<int> label(m, -1);
  basins = 0;
  for (int start = 0; start < m; ++start)
  {
    if (flat[start] >= 0)
    {
      continue;
    }
    flat[start] = start;
    members.assign(1, start);
    for (std::size_t i = 0; i < members.size(); ++i)
    {
      forEachEdgeNeighbour(graph, members[i], [&](int o) {
        if (flat[o] < 0 && level[o] == level[start])
        {
          flat[o] = start;
          members.push_back(o);
        }
      });
    }
    // Exits: edges of the area with a lower neighbour; each descends to its lowest one.
    std::vector<int> exits;
    for (int e : members)
    {
      int lowest = -1;
      forEachEdgeNeighbour(graph, e, [&](int o) {
        if (level[o] < level[e] &&
          (lowest < 0 || level[o] < level[lowest] || (level[o] == level[lowest] && o < lowest)))
        {
          lowest = o;
        }
      });
      if (lowest >= 0)
      {
        downstream[e] = lowest;
        exits.push_back(e);
      }
    }
    if (exits.empty())
    {
      for (int e : members)
      {
        label[e] = basins;
      }
      ++basins;
      continue;
    }
    // A plateau: the other edges flow breadth first towards the nearest exit.
    std::vector<int> queue = exits;
    std::vector<char> reached(members.size(), 0);
    for (std::size_t i = 0; i < queue.size(); ++i)
    {
      const int e = queue[i];
      forEachEdgeNeighbour(graph, e, [&](int o) {
        if (flat[o] == start && downstream[o] < 0 && label[o] < 0)
        {
          downstream[o] = e;
          queue.push_back(o);
        }
      });
    }
  }
  // Follow each path down to a labelled edge, labelling the path on the way back.
  std::vector<int> path;
  for (int e = 0; e < m; ++e)
  {
    path.clear();
    int at = e;
    while (label[at] < 0)
    {
      path.push_back(at);
      at = downstream[at];
    }
    for (int p : path)
    {
      label[p] = label[at];
    }
  }
  return label;
}
} // namespace

namespace
{
void checkWatershedOptions(const WatershedOptions& options)
{
  if (!(options.depthThreshold >= 0.0) || !std::isfinite(options.depthThreshold))
  {
    throw Error("the watershed depth threshold must be a finite number >= 0");
  }
  if (!(options.flatTolerance > 0.0) || !std::isfinite(options.flatTolerance))
  {
    throw Error("the flat tolerance must be a finite positive number");
  }
  if (options.segmentCount < 0)
  {
    throw Error("the segment count must be 0 (no limit) or positive");
  }
}

// The watershed's basins merged shallowest first, down to `lowestCount` regions (by count) or while
// shallower than the threshold (lowestCount 0). After the start and after each merge,
// reached(regions, live) is called with the regions left, so that a run down to the lowest count
// passes through every state a run stopping at a higher count ends in. Returns the last state.
template <typename Reached>
WatershedResult mergeBasins(
  const FaceGraph& graph, const WatershedOptions& options, int lowestCount, const Reached& reached)
{
  const int m = graph.edgeCount();
  std::vector<double> height(m);
  std::vector<long long> level(m);
  for (int e = 0; e < m; ++e)
  {
    height[e] = 1.0 - graph.edge(e).normalCosine;
    level[e] = std::llround(height[e] / options.flatTolerance);
  }
  WatershedResult result;
  const std::vector<int> edgeBasin = drainEdges(graph, level, result.basins);

  // Each face joins the basin of its lowest edge; faces without one are basins of their own.
  const int n = graph.faceCount();
  std::vector<int> faceBasin(n);
  std::vector<double> faceMinimum(n, 0.0);
  int extra = result.basins;
  for (int f = 0; f < n; ++f)
  {
    int lowest = -1;
    for (int e : graph.faceEdges(f))
    {
      if (e >= 0 && (lowest < 0 || level[e] < level[lowest] || (level[e] == level[lowest] && e < lowest)))
      {
        lowest = e;
      }
    }
    faceBasin[f] = lowest >= 0 ? edgeBasin[lowest] : extra++;
    faceMinimum[f] = lowest >= 0 ? height[lowest] : 0.0;
  }
  const std::vector<int> pieces = splitIntoConnectedSegments(graph, faceBasin);
  RegionAdjacency regions(graph, pieces, &height);
  std::vector<double> minimum(regions.regionCount(), std::numeric_limits<double>::infinity());
  for (int f = 0; f < n; ++f)
  {
    minimum[pieces[f]] = std::min(minimum[pieces[f]], faceMinimum[f]);
  }
  // Depth of a region: its lowest saddle minus its minimum; the neighbour across that saddle.
  auto depthOf = [&](int r, int& across) {
    double saddle = std::numeric_limits<double>::infinity();
    across = -1;
    for (const auto& [neighbour, boundary] : regions.neighbours(r))
    {
      if (boundary.lowestHeight < saddle)
      {
        saddle = boundary.lowestHeight;
        across = neighbour;
      }
    }
    return saddle - minimum[r];
  };
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for (int r = 0; r < regions.regionCount(); ++r)
  {
    int across = -1;
    const double depth = depthOf(r, across);
    if (across >= 0)
    {
      heap.emplace(depth, r);
    }
  }
  reached(regions, regions.liveCount());
  while (!heap.empty())
  {
    const auto [depth, r] = heap.top();
    heap.pop();
    int across = -1;
    if (!regions.alive(r) || depthOf(r, across) != depth || across < 0)
    {
      continue;
    }
    const bool byCount = lowestCount > 0;
    if (byCount ? regions.liveCount() <= lowestCount : depth >= options.depthThreshold)
    {
      break;
    }
    regions.merge(r, across);
    minimum[across] = std::min(minimum[across], minimum[r]);
    // Only the merged region's depth can change: a neighbour's boundaries with the two regions
    // become one with the lower of their heights, so its lowest saddle, its minimum and its depth
    // stay as they were, and its entry in the heap stays valid.
    int next = -1;
    const double d = depthOf(across, next);
    if (next >= 0)
    {
      heap.emplace(d, across);
    }
    reached(regions, regions.liveCount());
  }
  result.labels = regions.labels();
  result.segmentCount = regions.liveCount();
  return result;
}
} // namespace

WatershedResult segmentByWatershed(const FaceGraph& graph, const WatershedOptions& options)
{
  checkWatershedOptions(options);
  return mergeBasins(graph, options, options.segmentCount, [](const RegionAdjacency&, int) {});
}

std::vector<WatershedResult> segmentByWatershedAtCounts(
  const FaceGraph& graph, const WatershedOptions& options, int lowestCount, int highestCount)
{
  checkWatershedOptions(options);
  if (lowestCount < 1 || highestCount < lowestCount)
  {
    throw Error("the watershed at counts needs 1 <= lowest <= highest, got " + std::to_string(lowestCount) + " and " +
      std::to_string(highestCount));
  }
  std::vector<WatershedResult> results(static_cast<std::size_t>(highestCount - lowestCount + 1));
  // The next count, from the highest down, whose state has not been reached yet.
  int pending = highestCount;
  const WatershedResult last = mergeBasins(graph, options, lowestCount, [&](const RegionAdjacency& regions, int live) {
    for (; pending >= lowestCount && live <= pending; --pending)
    {
      WatershedResult& result = results[static_cast<std::size_t>(pending - lowestCount)];
      result.labels = regions.labels();
      result.segmentCount = live;
    }
  });
  // Counts the merging never got down to (no two regions left to merge) end as it ended.
  for (; pending >= lowestCount; --pending)
  {
    results[static_cast<std::size_t>(pending - lowestCount)] = last;
  }
  for (WatershedResult& result : results)
  {
    result.basins = last.basins;
  }
  return results;
}

} // namespace kerf
