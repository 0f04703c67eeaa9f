// The minimum cut: a chain's weakest link, a grid's narrowest column, data terms, and bad graphs.
#include "Error.h"
#include "Mesh/MinimumCut.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

using namespace kerf;

TEST(MinimumCut, AChainIsCutAtItsWeakestLink)
{
  // 0 - 1 - 2 - 3 - 4 with capacities 5, 2, 0.5, 3: the cut is the 0.5 link, between 2 and 3.
  const std::vector<std::array<int, 2>> edges{ { { 0, 1 } }, { { 1, 2 } }, { { 2, 3 } }, { { 3, 4 } } };
  const MinimumCut cut =
    minimumCut(5, edges, { 5.0, 2.0, 0.5, 3.0 }, std::vector<int>{ 0 }, std::vector<int>{ 4 }, 1e9);
  EXPECT_DOUBLE_EQ(cut.flow, 0.5);
  EXPECT_EQ(cut.sourceSide, (std::vector<char>{ 1, 1, 1, 0, 0 }));
}

TEST(MinimumCut, AGridIsCutWhereItsColumnIsCheapest)
{
  // A 6 x 4 grid, column 0 tied to the source and column 5 to the sink; the horizontal edges
  // between columns 3 and 4 cost 0.25, every other edge 1: the cut is those four edges.
  const int width = 6, height = 4;
  std::vector<std::array<int, 2>> edges;
  std::vector<double> capacity;
  std::vector<int> sources, sinks;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const int v = y * width + x;
      if (x + 1 < width)
      {
        edges.push_back({ { v, v + 1 } });
        capacity.push_back(x == 3 ? 0.25 : 1.0);
      }
      if (y + 1 < height)
      {
        edges.push_back({ { v, v + width } });
        capacity.push_back(1.0);
      }
    }
    sources.push_back(y * width);
    sinks.push_back(y * width + width - 1);
  }
  const MinimumCut cut = minimumCut(width * height, edges, capacity, sources, sinks, 1e9);
  EXPECT_DOUBLE_EQ(cut.flow, 1.0);
  for (int v = 0; v < width * height; ++v)
  {
    EXPECT_EQ(cut.sourceSide[v], v % width <= 3 ? 1 : 0) << "node " << v;
  }
}

TEST(MinimumCut, DataTermsDecideFreeNodes)
{
  // Two free nodes joined by an edge of capacity 1: node 0 prefers the source (costs 3 on the
  // sink side), node 1 the sink (costs 2 on the source side). Cutting the edge (1) is cheaper
  // than either node's move (2 or 3); with the edge at 4, node 1 follows node 0 (cost 2).
  const std::vector<std::array<int, 2>> edges{ { { 0, 1 } } };
  MinimumCut cut = minimumCut(2, edges, { 1.0 }, std::vector<double>{ 3.0, 0.0 }, std::vector<double>{ 0.0, 2.0 });
  EXPECT_DOUBLE_EQ(cut.flow, 1.0);
  EXPECT_EQ(cut.sourceSide, (std::vector<char>{ 1, 0 }));
  cut = minimumCut(2, edges, { 4.0 }, std::vector<double>{ 3.0, 0.0 }, std::vector<double>{ 0.0, 2.0 });
  EXPECT_DOUBLE_EQ(cut.flow, 2.0);
  EXPECT_EQ(cut.sourceSide, (std::vector<char>{ 1, 1 }));
}

TEST(MinimumCut, RefusesBadGraphs)
{
  const std::vector<std::array<int, 2>> edges{ { { 0, 1 } } };
  EXPECT_THROW(minimumCut(2, edges, {}, std::vector<int>{ 0 }, std::vector<int>{ 1 }, 1.0), Error);
  EXPECT_THROW(minimumCut(2, edges, { -1.0 }, std::vector<int>{ 0 }, std::vector<int>{ 1 }, 1.0), Error);
  EXPECT_THROW(minimumCut(-1, {}, {}, std::vector<int>{}, std::vector<int>{}, 1.0), Error);
  EXPECT_THROW(minimumCut(2, { { { 0, 2 } } }, { 1.0 }, std::vector<int>{ 0 }, std::vector<int>{ 1 }, 1.0), Error);
  EXPECT_THROW(minimumCut(2, edges, { 1.0 }, std::vector<int>{ 5 }, std::vector<int>{ 1 }, 1.0), Error);
  EXPECT_THROW(minimumCut(2, edges, { 1.0 }, std::vector<double>{ 1.0 }, std::vector<double>{ 0.0, 1.0 }), Error);
  EXPECT_THROW(minimumCut(2, edges, { 1.0 }, std::vector<double>{ -1.0, 0.0 }, std::vector<double>{ 0.0, 1.0 }), Error);
}
