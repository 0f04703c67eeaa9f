// searchShortestPaths: Dijkstra's loop against distances known by hand, its stop and the parents it
// lets the caller record.
#include "Mesh/ShortestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
using kerf::DistanceQueue;

struct Arc
{
  int to;
  double length;
};

// 0 -1- 1 -1- 2, 0 -5- 2, 2 -2- 3, and 4 alone.
std::vector<std::vector<Arc>> smallGraph()
{
  std::vector<std::vector<Arc>> arcs(5);
  auto join = [&](int a, int b, double length) {
    arcs[a].push_back({ b, length });
    arcs[b].push_back({ a, length });
  };
  join(0, 1, 1.0);
  join(1, 2, 1.0);
  join(0, 2, 5.0);
  join(2, 3, 2.0);
  return arcs;
}
} // namespace

TEST(ShortestPaths, DistancesAndParentsOfASmallGraph)
{
  const auto arcs = smallGraph();
  std::vector<double> distance(5, std::numeric_limits<double>::infinity());
  std::vector<int> parent(5, -1);
  DistanceQueue queue;
  distance[0] = 0.0;
  queue.emplace(0.0, 0);
  kerf::searchShortestPaths(
    queue, [&](int v) -> double& { return distance[v]; },
    [&](int v, double d, const auto& lower) {
      for (const Arc& arc : arcs[v])
      {
        if (lower(arc.to, d + arc.length))
        {
          parent[arc.to] = v;
        }
      }
    });
  EXPECT_EQ(distance[0], 0.0);
  EXPECT_EQ(distance[1], 1.0);
  EXPECT_EQ(distance[2], 2.0); // through 1, not the direct arc of 5
  EXPECT_EQ(distance[3], 4.0);
  EXPECT_TRUE(std::isinf(distance[4]));
  EXPECT_EQ(parent[1], 0);
  EXPECT_EQ(parent[2], 1);
  EXPECT_EQ(parent[3], 2);
  EXPECT_EQ(parent[4], -1);
  EXPECT_TRUE(queue.empty());
}

TEST(ShortestPaths, StopsWhereTheTargetIsSettled)
{
  const auto arcs = smallGraph();
  std::vector<double> distance(5, std::numeric_limits<double>::infinity());
  DistanceQueue queue;
  distance[0] = 0.0;
  queue.emplace(0.0, 0);
  std::vector<int> settled;
  const bool reached = kerf::searchShortestPaths(
    queue, [&](int v) -> double& { return distance[v]; },
    [&](int v, double d, const auto& lower) {
      for (const Arc& arc : arcs[v])
      {
        lower(arc.to, d + arc.length);
      }
    },
    [&](int v, double) {
      settled.push_back(v);
      return v == 2;
    });
  EXPECT_TRUE(reached);
  EXPECT_EQ(settled, (std::vector<int>{ 0, 1, 2 }));
  EXPECT_EQ(distance[2], 2.0);
  EXPECT_TRUE(std::isinf(distance[3])); // never relaxed: the search stopped at 2
  // A target no path reaches: the search runs out and says so.
  std::fill(distance.begin(), distance.end(), std::numeric_limits<double>::infinity());
  distance[0] = 0.0;
  queue = DistanceQueue();
  queue.emplace(0.0, 0);
  EXPECT_FALSE(kerf::searchShortestPaths(
    queue, [&](int v) -> double& { return distance[v]; },
    [&](int v, double d, const auto& lower) {
      for (const Arc& arc : arcs[v])
      {
        lower(arc.to, d + arc.length);
      }
    },
    [](int v, double) { return v == 4; }));
}

TEST(ShortestPaths, SeveralSourcesAndEqualDistancesTakeTheSmallerNodeFirst)
{
  // Two sources at 0 and 3 on the path 0-1-2-3 of unit arcs: 1 and 2 are each one away from one.
  std::vector<std::vector<Arc>> arcs(4);
  for (int v = 0; v < 3; ++v)
  {
    arcs[v].push_back({ v + 1, 1.0 });
    arcs[v + 1].push_back({ v, 1.0 });
  }
  std::vector<double> distance(4, std::numeric_limits<double>::infinity());
  std::vector<int> source(4, -1);
  DistanceQueue queue;
  for (int s : { 3, 0 })
  {
    distance[s] = 0.0;
    source[s] = s;
    queue.emplace(0.0, s);
  }
  std::vector<int> order;
  kerf::searchShortestPaths(
    queue, [&](int v) -> double& { return distance[v]; },
    [&](int v, double d, const auto& lower) {
      for (const Arc& arc : arcs[v])
      {
        if (lower(arc.to, d + arc.length))
        {
          source[arc.to] = source[v];
        }
      }
    },
    [&](int v, double) {
      order.push_back(v);
      return false;
    });
  EXPECT_EQ(order, (std::vector<int>{ 0, 3, 1, 2 }));
  EXPECT_EQ(distance, (std::vector<double>{ 0.0, 1.0, 1.0, 0.0 }));
  EXPECT_EQ(source, (std::vector<int>{ 0, 0, 3, 3 }));
}
