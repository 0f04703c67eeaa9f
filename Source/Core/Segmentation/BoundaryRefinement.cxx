// Boundary refinement: per pair of neighbouring segments, a band around their boundary re-cut by a minimum cut.
#include "Segmentation/BoundaryRefinement.h"

#include "Error.h"
#include "Mesh/MinimumCut.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace kerf
{

void checkBoundaryRefinementOptions(const BoundaryRefinementOptions& options)
{
  if (!(options.bandWidth >= 0.0) || !std::isfinite(options.bandWidth) || !(options.convexWeight >= 0.0) ||
    !std::isfinite(options.convexWeight))
  {
    throw Error("the boundary band and the convex weight must be finite and non-negative");
  }
}

BoundaryRefinementResult refineSegmentBoundaries(
  const FaceGraph& graph, const std::vector<int>& labels, const BoundaryRefinementOptions& options)
{
  const int n = graph.faceCount();
  if (static_cast<int>(labels.size()) != n)
  {
    throw Error("the labels to refine are not one per face");
  }
  checkBoundaryRefinementOptions(options);
  if (std::any_of(labels.begin(), labels.end(), [](int label) { return label < 0; }))
  {
    throw Error("a face to refine has a negative label");
  }
  BoundaryRefinementResult result;
  result.labels = labels;
  if (n == 0 || options.bandWidth == 0.0)
  {
    return result;
  }
  // At most as many segments as the input has labels (they need not be contiguous).
  const int k = static_cast<int>(std::set<int>(labels.begin(), labels.end()).size());

  // Katz and Tal 2003: a dual edge's angular distance, eta (1 - cos alpha), eta < 1 where convex;
  // the cut's capacity falls with it, so boundaries take concave creases.
  const int edgeCount = graph.edgeCount();
  std::vector<double> angular(static_cast<std::size_t>(edgeCount));
  double lengthSum = 0.0, angularSum = 0.0;
  for (int e = 0; e < edgeCount; ++e)
  {
    const DualEdge& edge = graph.edge(e);
    angular[e] = (1.0 - edge.normalCosine) * (edge.bend > 0.0 ? options.convexWeight : 1.0);
    angularSum += angular[e];
    lengthSum += edge.length;
  }
  const double meanLength = edgeCount > 0 && lengthSum > 0.0 ? lengthSum / edgeCount : 1.0;
  const double meanAngular = edgeCount > 0 ? angularSum / edgeCount : 0.0;
  std::vector<double> capacity(static_cast<std::size_t>(edgeCount));
  for (int e = 0; e < edgeCount; ++e)
  {
    capacity[e] = graph.edge(e).length / meanLength / (meanAngular > 0.0 ? 1.0 + angular[e] / meanAngular : 1.0);
  }

  std::set<std::pair<int, int>> pairs;
  for (const DualEdge& edge : graph.edges())
  {
    const int a = labels[edge.faces[0]], b = labels[edge.faces[1]];
    if (a != b)
    {
      pairs.insert({ std::min(a, b), std::max(a, b) });
    }
  }

  std::vector<int>& current = result.labels;
  const double infinite = std::numeric_limits<double>::max() / 4.0;
  std::vector<double> lengths(static_cast<std::size_t>(edgeCount));
  std::vector<int> node(static_cast<std::size_t>(n), -1);
  for (const auto& [a, b] : pairs)
  {
    const auto inPair = [&current, a = a, b = b](int f) { return current[f] == a || current[f] == b; };
    // The two segments' areas and the faces on their shared boundary, as earlier cuts left them.
    double areaA = 0.0, areaB = 0.0;
    for (int f = 0; f < n; ++f)
    {
      areaA += current[f] == a ? graph.area(f) : 0.0;
      areaB += current[f] == b ? graph.area(f) : 0.0;
    }
    std::vector<int> boundary;
    for (int e = 0; e < edgeCount; ++e)
    {
      const DualEdge& edge = graph.edge(e);
      const bool inside = inPair(edge.faces[0]) && inPair(edge.faces[1]);
      lengths[e] = inside ? edge.centroidPath : std::numeric_limits<double>::infinity();
      if (inside && current[edge.faces[0]] != current[edge.faces[1]])
      {
        boundary.push_back(edge.faces[0]);
        boundary.push_back(edge.faces[1]);
      }
    }
    if (boundary.empty())
    {
      continue; // an earlier cut took their contact away
    }
    std::sort(boundary.begin(), boundary.end());
    boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
    const double width = options.bandWidth * std::sqrt(std::min(areaA, areaB));
    const std::vector<double> distance = dualDijkstra(graph, lengths, boundary, width).distance;

    // Freed faces (within the band) are the cut's nodes; faces of the pair just outside it hold
    // the cut to their side.
    std::vector<int> nodes;
    for (int f = 0; f < n; ++f)
    {
      if (inPair(f) && distance[f] <= width)
      {
        node[f] = static_cast<int>(nodes.size());
        nodes.push_back(f);
      }
    }
    const std::size_t freed = nodes.size();
    std::vector<double> sourceCapacity(freed, 0.0), sinkCapacity(freed, 0.0);
    std::vector<std::array<int, 2>> edges;
    std::vector<double> edgeCapacity;
    bool anySource = false, anySink = false;
    for (std::size_t i = 0; i < freed; ++i)
    {
      const int f = nodes[i];
      for (int e : graph.faceEdges(f))
      {
        if (e < 0 || !(lengths[e] < std::numeric_limits<double>::infinity()))
        {
          continue;
        }
        const int g = graph.opposite(e, f);
        if (node[g] >= 0 && static_cast<std::size_t>(node[g]) < freed && g < f)
        {
          continue; // an edge between freed faces is added from its smaller face
        }
        if (node[g] < 0)
        {
          node[g] = static_cast<int>(nodes.size());
          nodes.push_back(g);
          const bool isA = current[g] == a;
          sourceCapacity.push_back(isA ? infinite : 0.0);
          sinkCapacity.push_back(isA ? 0.0 : infinite);
          anySource = anySource || isA;
          anySink = anySink || !isA;
        }
        edges.push_back({ node[f], node[g] });
        edgeCapacity.push_back(capacity[e]);
      }
    }
    if (anySource && anySink)
    {
      const MinimumCut cut =
        minimumCut(static_cast<int>(nodes.size()), edges, edgeCapacity, sourceCapacity, sinkCapacity);
      for (std::size_t i = 0; i < freed; ++i)
      {
        const int f = nodes[i];
        const int chosen = cut.sourceSide[i] ? a : b;
        result.movedFaces += chosen != current[f] ? 1 : 0;
        current[f] = chosen;
      }
      ++result.boundaries;
    }
    for (int f : nodes)
    {
      node[f] = -1;
    }
  }
  result.labels = finalizeSegments(graph, current, k);
  return result;
}

} // namespace kerf
