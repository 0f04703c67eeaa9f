// Boundary refinement: per pair of neighbouring segments, a band around their boundary re-cut by a minimum cut.
#include "Segmentation/BoundaryRefinement.h"

#include "Error.h"
#include "Mesh/MinimumCut.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
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
  // Each label's faces in face order, kept as the cuts move faces, so that a pair's work is
  // proportional to its two segments rather than to the surface; an edge's length is finite only
  // while both its faces are in the pair at hand.
  std::map<int, std::vector<int>> facesOf;
  std::vector<int>* facesOfLabel = &facesOf[labels[0]];
  for (int f = 0; f < n; ++f)
  {
    if (labels[f] != labels[f > 0 ? f - 1 : 0])
    {
      facesOfLabel = &facesOf[labels[f]]; // labels come in runs: a map lookup per run
    }
    facesOfLabel->push_back(f);
  }
  // At most as many segments as the input has labels (they need not be contiguous).
  const int k = static_cast<int>(facesOf.size());
  std::vector<double> lengths(static_cast<std::size_t>(edgeCount), std::numeric_limits<double>::infinity());
  std::vector<int> node(static_cast<std::size_t>(n), -1);
  std::vector<int> pairFaces, insideEdges;
  for (const auto& [a, b] : pairs)
  {
    const auto inPair = [&current, a = a, b = b](int f) { return current[f] == a || current[f] == b; };
    std::vector<int>& facesA = facesOf[a];
    std::vector<int>& facesB = facesOf[b];
    pairFaces.clear();
    std::merge(facesA.begin(), facesA.end(), facesB.begin(), facesB.end(), std::back_inserter(pairFaces));
    // The two segments' areas and the faces on their shared boundary, as earlier cuts left them.
    double areaA = 0.0, areaB = 0.0;
    for (int f : facesA)
    {
      areaA += graph.area(f);
    }
    for (int f : facesB)
    {
      areaB += graph.area(f);
    }
    std::vector<int> boundary;
    insideEdges.clear();
    for (int f : pairFaces)
    {
      for (int e : graph.faceEdges(f))
      {
        const int g = e >= 0 ? graph.opposite(e, f) : -1;
        if (g < f || !inPair(g))
        {
          continue; // each inside edge once, from its smaller face
        }
        lengths[e] = graph.edge(e).centroidPath;
        insideEdges.push_back(e);
        if (current[f] != current[g])
        {
          boundary.push_back(f);
          boundary.push_back(g);
        }
      }
    }
    const auto resetLengths = [&lengths, &insideEdges]() {
      for (int e : insideEdges)
      {
        lengths[e] = std::numeric_limits<double>::infinity();
      }
    };
    if (boundary.empty())
    {
      resetLengths();
      continue; // an earlier cut took their contact away
    }
    std::sort(boundary.begin(), boundary.end());
    boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
    const double width = options.bandWidth * std::sqrt(std::min(areaA, areaB));
    const std::vector<double> distance = dualDijkstra(graph, lengths, boundary, width).distance;

    // Freed faces (within the band) are the cut's nodes; faces of the pair just outside it hold
    // the cut to their side.
    std::vector<int> nodes;
    for (int f : pairFaces)
    {
      if (distance[f] <= width)
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
    resetLengths();
    facesA.clear();
    facesB.clear();
    for (int f : pairFaces)
    {
      (current[f] == a ? facesA : facesB).push_back(f);
    }
  }
  result.labels = finalizeSegments(graph, current, k);
  return result;
}

} // namespace kerf
