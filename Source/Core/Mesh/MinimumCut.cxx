// A minimum s-t cut of an undirected graph with Boost's Boykov-Kolmogorov max-flow.
#include "Mesh/MinimumCut.h"

#include "Error.h"

#include <string>
#include <utility>

// Boost 1.74's edge iterators trip GCC 12's -Wmaybe-uninitialized inside the max-flow code.
#pragma GCC diagnostic push
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

namespace kerf
{
namespace
{
// Boost's max-flow graph: the nodes, then the source and the sink.
using FlowTraits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
using FlowGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS,
  boost::property<boost::vertex_color_t, boost::default_color_type,
    boost::property<boost::vertex_distance_t, long,
      boost::property<boost::vertex_predecessor_t, FlowTraits::edge_descriptor>>>,
  boost::property<boost::edge_capacity_t, double,
    boost::property<boost::edge_residual_capacity_t, double,
      boost::property<boost::edge_reverse_t, FlowTraits::edge_descriptor>>>>;

// The cut with the terminal arcs in the given order (node, capacity); the order decides between
// cuts of equal value, so each caller keeps its own.
MinimumCut cutWithTerminalArcs(int nodeCount, const std::vector<std::array<int, 2>>& edges,
  const std::vector<double>& capacity, const std::vector<std::pair<int, double>>& sourceArcs,
  const std::vector<std::pair<int, double>>& sinkArcs)
{
  if (capacity.size() != edges.size() || nodeCount < 0)
  {
    throw Error("a minimum cut needs a node count that is not negative and one capacity per edge");
  }
  for (double c : capacity)
  {
    if (!(c >= 0.0))
    {
      throw Error("an edge capacity of the minimum cut's graph is negative or not a number");
    }
  }
  const int n = nodeCount;
  FlowGraph graph(static_cast<std::size_t>(n) + 2);
  auto cap = boost::get(boost::edge_capacity, graph);
  auto reverse = boost::get(boost::edge_reverse, graph);
  auto addPair = [&](int a, int b, double forward, double backward) {
    const auto e1 = boost::add_edge(a, b, graph).first;
    const auto e2 = boost::add_edge(b, a, graph).first;
    cap[e1] = forward;
    cap[e2] = backward;
    reverse[e1] = e2;
    reverse[e2] = e1;
  };
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    if (edges[e][0] < 0 || edges[e][0] >= n || edges[e][1] < 0 || edges[e][1] >= n)
    {
      throw Error("an edge of the minimum cut's graph has a node out of range");
    }
    addPair(edges[e][0], edges[e][1], capacity[e], capacity[e]);
  }
  for (const auto* arcs : { &sourceArcs, &sinkArcs })
  {
    for (const auto& [v, c] : *arcs)
    {
      if (v < 0 || v >= n || !(c >= 0.0))
      {
        throw Error("a terminal arc of the minimum cut's graph has a node out of range or a negative capacity");
      }
      arcs == &sourceArcs ? addPair(n, v, c, 0.0) : addPair(v, n + 1, c, 0.0);
    }
  }
  MinimumCut cut;
  cut.flow = boost::boykov_kolmogorov_max_flow(graph, n, n + 1);
  auto color = boost::get(boost::vertex_color, graph);
  cut.sourceSide.resize(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v)
  {
    cut.sourceSide[v] = color[v] == boost::color_traits<boost::default_color_type>::black() ? 1 : 0;
  }
  return cut;
}
} // namespace

MinimumCut minimumCut(int nodeCount, const std::vector<std::array<int, 2>>& edges, const std::vector<double>& capacity,
  const std::vector<int>& sources, const std::vector<int>& sinks, double terminal)
{
  std::vector<std::pair<int, double>> sourceArcs, sinkArcs;
  for (int v : sources)
  {
    sourceArcs.emplace_back(v, terminal);
  }
  for (int v : sinks)
  {
    sinkArcs.emplace_back(v, terminal);
  }
  return cutWithTerminalArcs(nodeCount, edges, capacity, sourceArcs, sinkArcs);
}

MinimumCut minimumCut(int nodeCount, const std::vector<std::array<int, 2>>& edges, const std::vector<double>& capacity,
  const std::vector<double>& sourceCapacity, const std::vector<double>& sinkCapacity)
{
  if (static_cast<int>(sourceCapacity.size()) != nodeCount || static_cast<int>(sinkCapacity.size()) != nodeCount)
  {
    throw Error("a minimum cut needs two terminal capacities per node");
  }
  std::vector<std::pair<int, double>> sourceArcs, sinkArcs;
  for (int v = 0; v < nodeCount; ++v)
  {
    if (!(sourceCapacity[v] >= 0.0 && sinkCapacity[v] >= 0.0))
    {
      throw Error("the terminal capacity of node " + std::to_string(v) + " is negative or not a number");
    }
    if (sourceCapacity[v] > 0.0)
    {
      sourceArcs.emplace_back(v, sourceCapacity[v]);
    }
    if (sinkCapacity[v] > 0.0)
    {
      sinkArcs.emplace_back(v, sinkCapacity[v]);
    }
  }
  return cutWithTerminalArcs(nodeCount, edges, capacity, sourceArcs, sinkArcs);
}

} // namespace kerf

#pragma GCC diagnostic pop
