// A minimum s-t cut of an undirected graph with Boost's Boykov-Kolmogorov max-flow.
#pragma once

#include <array>
#include <vector>

namespace kerf
{

/// A minimum cut: the flow's value and, per node, whether it lies on the source side.
struct MinimumCut
{
  double flow = 0.0;
  std::vector<char> sourceSide;
};

/// A minimum cut (Boykov and Kolmogorov 2004) of the graph of `nodeCount` nodes whose undirected
/// edges `edges` have the capacities `capacity` (one per edge, non-negative), each node tied to
/// the source with `sourceCapacity` (what putting it on the sink side costs) and to the sink with
/// `sinkCapacity` (one per node each; 0: no arc). The source side is what the residual graph
/// reaches from the source.
MinimumCut minimumCut(int nodeCount, const std::vector<std::array<int, 2>>& edges, const std::vector<double>& capacity,
  const std::vector<double>& sourceCapacity, const std::vector<double>& sinkCapacity);

/// The same with `sources` and `sinks` tied to the terminals with capacity `terminal` and the
/// other nodes free.
MinimumCut minimumCut(int nodeCount, const std::vector<std::array<int, 2>>& edges, const std::vector<double>& capacity,
  const std::vector<int>& sources, const std::vector<int>& sinks, double terminal);

} // namespace kerf
