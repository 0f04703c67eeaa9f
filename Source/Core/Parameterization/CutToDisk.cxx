// cutToDisk: a cut graph of short paths (tree-cotree on the capped chart) and the split along it.
#include "Parameterization/CutToDisk.h"

#include "Error.h"
#include "Mesh/MeshValidation.h"
#include "Mesh/ShortestPaths.h"
#include "Mesh/UnionFind.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

namespace kerf
{
namespace
{

// A graph with weighted undirected edges: the chart's vertices, then one cap vertex per boundary loop.
struct CappedGraph
{
  struct Arc
  {
    int to;
    int edge; // the chart's edge, or E + v for the arc between boundary vertex v and its cap
    double length;
  };
  std::vector<std::vector<Arc>> arcs;
};

// Dijkstra from `root`: distances and the arc each vertex was reached by (tree parent).
void shortestPathTree(const CappedGraph& graph, int root, std::vector<double>& distance, std::vector<int>& parent,
  std::vector<int>& parentEdge)
{
  const std::size_t n = graph.arcs.size();
  distance.assign(n, std::numeric_limits<double>::infinity());
  parent.assign(n, -1);
  parentEdge.assign(n, -1);
  DistanceQueue queue;
  distance[static_cast<std::size_t>(root)] = 0.0;
  queue.push({ 0.0, root });
  searchShortestPaths(
    queue, [&](int v) -> double& { return distance[static_cast<std::size_t>(v)]; },
    [&](int v, double d, const auto& lower) {
      for (const CappedGraph::Arc& arc : graph.arcs[static_cast<std::size_t>(v)])
      {
        if (lower(arc.to, d + arc.length))
        {
          parent[static_cast<std::size_t>(arc.to)] = v;
          parentEdge[static_cast<std::size_t>(arc.to)] = arc.edge;
        }
      }
    });
}

double edgeLength(const TriangleMesh& mesh, int e)
{
  const std::array<int, 2>& ends = mesh.edgeVertices(e);
  return (mesh.point(ends[1]) - mesh.point(ends[0])).norm();
}

} // namespace

EdgePathTree shortestEdgePaths(const TriangleMesh& mesh, const std::vector<int>& sources)
{
  // The sources joined at length 0 to one extra vertex, the root.
  const int n = mesh.vertexCount();
  CappedGraph graph;
  graph.arcs.resize(static_cast<std::size_t>(n) + 1);
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const std::array<int, 2>& ends = mesh.edgeVertices(e);
    const double length = edgeLength(mesh, e);
    graph.arcs[static_cast<std::size_t>(ends[0])].push_back({ ends[1], e, length });
    graph.arcs[static_cast<std::size_t>(ends[1])].push_back({ ends[0], e, length });
  }
  for (int v : sources)
  {
    graph.arcs[static_cast<std::size_t>(n)].push_back({ v, -1, 0.0 });
  }
  EdgePathTree tree;
  std::vector<int> parent;
  shortestPathTree(graph, n, tree.distance, parent, tree.towards);
  tree.distance.pop_back();
  tree.towards.pop_back();
  return tree;
}

EdgeCut splitAlongEdges(const TriangleMesh& mesh, const std::vector<char>& cut)
{
  if (cut.size() != static_cast<std::size_t>(mesh.edgeCount()))
  {
    throw Error(
      "the cut has " + std::to_string(cut.size()) + " edge flags for " + std::to_string(mesh.edgeCount()) + " edges");
  }
  const int faces = mesh.faceCount();
  // Corner 3 f + k holds vertex k of triangle f; corners of one vertex joined across uncut edges.
  UnionFind corners(static_cast<std::size_t>(faces) * 3);
  EdgeCut result;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    if (mesh.edgeFaceCount(e) != 2)
    {
      continue;
    }
    if (cut[static_cast<std::size_t>(e)])
    {
      result.cutEdges.push_back(e);
      result.cutLength += edgeLength(mesh, e);
      continue;
    }
    const std::array<int, 2>& pair = mesh.edgeFaces(e);
    for (int v : mesh.edgeVertices(e))
    {
      int a = -1, b = -1;
      for (int k = 0; k < 3; ++k)
      {
        if (mesh.triangle(pair[0])[static_cast<std::size_t>(k)] == v)
        {
          a = 3 * pair[0] + k;
        }
        if (mesh.triangle(pair[1])[static_cast<std::size_t>(k)] == v)
        {
          b = 3 * pair[1] + k;
        }
      }
      corners.join(a, b);
    }
  }
  // One copy per class of corners, numbered by (input vertex, lowest corner).
  std::vector<std::pair<int, int>> classes; // (vertex, root corner = lowest corner of the class)
  for (int c = 0; c < 3 * faces; ++c)
  {
    if (corners.find(c) == c)
    {
      classes.emplace_back(mesh.triangle(c / 3)[static_cast<std::size_t>(c % 3)], c);
    }
  }
  std::sort(classes.begin(), classes.end());
  std::vector<int> copyOfRoot(static_cast<std::size_t>(faces) * 3, -1);
  std::vector<Vector3> points(classes.size());
  result.originalVertex.resize(classes.size());
  for (std::size_t i = 0; i < classes.size(); ++i)
  {
    copyOfRoot[static_cast<std::size_t>(classes[i].second)] = static_cast<int>(i);
    result.originalVertex[i] = classes[i].first;
    points[i] = mesh.point(classes[i].first);
  }
  std::vector<Triangle> triangles(static_cast<std::size_t>(faces));
  for (int f = 0; f < faces; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      triangles[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)] =
        copyOfRoot[static_cast<std::size_t>(corners.find(3 * f + k))];
    }
  }
  result.mesh = TriangleMesh(std::move(points), std::move(triangles));
  return result;
}

EdgeCut cutToDisk(const TriangleMesh& chart)
{
  if (chart.empty())
  {
    throw Error("the chart has no triangle");
  }
  const MeshReport report = inspectMesh(chart);
  if (report.nonManifoldEdges > 0 || report.nonManifoldVertices > 0 || report.inconsistentEdges > 0 ||
    report.components != 1)
  {
    throw Error("only a connected, manifold, consistently oriented chart can be cut into a disk");
  }
  const int loops = report.boundaryLoops;
  const int genus = (2 - report.eulerCharacteristic - loops) / 2;
  std::vector<char> cut(static_cast<std::size_t>(chart.edgeCount()), 0);
  if (loops == 1 && genus == 0)
  {
    return splitAlongEdges(chart, cut);
  }
  const int n = chart.vertexCount();

  // Boundary loops: boundary vertices joined along boundary edges, numbered by lowest vertex.
  UnionFind boundary(static_cast<std::size_t>(n));
  std::vector<char> onBoundary(static_cast<std::size_t>(n), 0);
  for (int e = 0; e < chart.edgeCount(); ++e)
  {
    if (chart.isBoundaryEdge(e))
    {
      const std::array<int, 2>& ends = chart.edgeVertices(e);
      boundary.join(ends[0], ends[1]);
      onBoundary[static_cast<std::size_t>(ends[0])] = onBoundary[static_cast<std::size_t>(ends[1])] = 1;
    }
  }
  std::vector<int> loopOfRoot(static_cast<std::size_t>(n), -1);
  std::vector<int> loopOfVertex(static_cast<std::size_t>(n), -1);
  int loopCount = 0;
  for (int v = 0; v < n; ++v)
  {
    if (onBoundary[static_cast<std::size_t>(v)])
    {
      int& loop = loopOfRoot[static_cast<std::size_t>(boundary.find(v))];
      if (loop < 0)
      {
        loop = loopCount++;
      }
      loopOfVertex[static_cast<std::size_t>(v)] = loop;
    }
  }

  // The capped graph: the chart's edges (ids 0..E-1), and each loop's cap joined to its vertices
  // at length 0 (the virtual edge of boundary vertex v has id E + v).
  const int edges = chart.edgeCount();
  CappedGraph graph;
  graph.arcs.resize(static_cast<std::size_t>(n + loopCount));
  for (int e = 0; e < edges; ++e)
  {
    const std::array<int, 2>& ends = chart.edgeVertices(e);
    const double length = edgeLength(chart, e);
    graph.arcs[static_cast<std::size_t>(ends[0])].push_back({ ends[1], e, length });
    graph.arcs[static_cast<std::size_t>(ends[1])].push_back({ ends[0], e, length });
  }
  for (int v = 0; v < n; ++v)
  {
    const int loop = loopOfVertex[static_cast<std::size_t>(v)];
    if (loop >= 0)
    {
      graph.arcs[static_cast<std::size_t>(v)].push_back({ n + loop, edges + v, 0.0 });
      graph.arcs[static_cast<std::size_t>(n + loop)].push_back({ v, edges + v, 0.0 });
    }
  }
  std::vector<double> distance;
  std::vector<int> parent, parentEdge;
  // Flags the chart edges on the tree path from graph vertex v up to the root.
  auto flagTreePath = [&](int v) {
    while (parent[static_cast<std::size_t>(v)] >= 0)
    {
      const int e = parentEdge[static_cast<std::size_t>(v)];
      if (e < edges)
      {
        cut[static_cast<std::size_t>(e)] = 1;
      }
      v = parent[static_cast<std::size_t>(v)];
    }
  };

  if (loopCount == 0 && genus == 0)
  {
    // A closed chart of genus 0: the shortest path between two vertices far apart.
    shortestPathTree(graph, 0, distance, parent, parentEdge);
    const int far = static_cast<int>(std::max_element(distance.begin(), distance.end()) - distance.begin());
    shortestPathTree(graph, far, distance, parent, parentEdge);
    flagTreePath(static_cast<int>(std::max_element(distance.begin(), distance.end()) - distance.begin()));
  }
  else
  {
    shortestPathTree(graph, loopCount > 0 ? n : 0, distance, parent, parentEdge);
    std::vector<char> inTree(static_cast<std::size_t>(edges + n), 0);
    for (std::size_t v = 0; v < parentEdge.size(); ++v)
    {
      if (parentEdge[v] >= 0)
      {
        inTree[static_cast<std::size_t>(parentEdge[v])] = 1;
      }
    }
    // The cotree: a maximum spanning tree, over the edges not in T, of the dual graph of the
    // capped mesh, by the length of each edge's loop through T (Erickson and Whittlesey 2005,
    // section 3). Dual nodes: the chart's faces, then one virtual triangle per boundary edge
    // (its cap, its two ends); the virtual edge of vertex v separates the virtual triangles of
    // v's two boundary edges.
    const int faces = chart.faceCount();
    std::vector<int> fanNode(static_cast<std::size_t>(edges), -1);
    std::vector<std::array<int, 2>> vertexFans(static_cast<std::size_t>(n), { { -1, -1 } });
    int nodes = faces;
    for (int e = 0; e < edges; ++e)
    {
      if (chart.isBoundaryEdge(e))
      {
        fanNode[static_cast<std::size_t>(e)] = nodes++;
        for (int v : chart.edgeVertices(e))
        {
          std::array<int, 2>& fans = vertexFans[static_cast<std::size_t>(v)];
          fans[fans[0] < 0 ? 0 : 1] = fanNode[static_cast<std::size_t>(e)];
        }
      }
    }
    auto endsOf = [&](int e) -> std::array<int, 2> {
      if (e >= edges)
      {
        const int v = e - edges;
        return { { v, n + loopOfVertex[static_cast<std::size_t>(v)] } };
      }
      return chart.edgeVertices(e);
    };
    std::vector<std::pair<double, int>> candidates; // (-weight, edge): heaviest first, then by id
    for (int e = 0; e < edges + n; ++e)
    {
      if (inTree[static_cast<std::size_t>(e)] || (e >= edges && loopOfVertex[static_cast<std::size_t>(e - edges)] < 0))
      {
        continue;
      }
      const std::array<int, 2> ends = endsOf(e);
      const double length = e < edges ? edgeLength(chart, e) : 0.0;
      candidates.emplace_back(
        -(distance[static_cast<std::size_t>(ends[0])] + distance[static_cast<std::size_t>(ends[1])] + length), e);
    }
    std::sort(candidates.begin(), candidates.end());
    UnionFind dual(static_cast<std::size_t>(nodes));
    for (const auto& candidate : candidates)
    {
      const int e = candidate.second;
      int a, b;
      if (e >= edges)
      {
        a = vertexFans[static_cast<std::size_t>(e - edges)][0];
        b = vertexFans[static_cast<std::size_t>(e - edges)][1];
      }
      else
      {
        a = chart.edgeFaces(e)[0];
        b = chart.isBoundaryEdge(e) ? fanNode[static_cast<std::size_t>(e)] : chart.edgeFaces(e)[1];
      }
      if (dual.join(a, b))
      {
        continue;
      }
      // Neither in T nor in the cotree: the edge closes one of the 2 g loops that cut the
      // handles; its chart part (the edge if it is an interior one, the tree paths of its ends)
      // is cut.
      if (e < edges)
      {
        cut[static_cast<std::size_t>(e)] = 1;
      }
      for (int v : endsOf(e))
      {
        flagTreePath(v);
      }
    }
    // Every other loop joined to the root's loop by its path in T.
    for (int loop = 1; loop < loopCount; ++loop)
    {
      flagTreePath(n + loop);
    }
    // Loops that share the start of their tree paths leave that start dangling from the rest of
    // the cut: cut ends inside the chart are closed again, one edge at a time.
    std::vector<int> degree(static_cast<std::size_t>(n), 0);
    for (int e = 0; e < edges; ++e)
    {
      if (cut[static_cast<std::size_t>(e)])
      {
        for (int v : chart.edgeVertices(e))
        {
          ++degree[static_cast<std::size_t>(v)];
        }
      }
    }
    std::vector<int> ends;
    for (int v = 0; v < n; ++v)
    {
      if (degree[static_cast<std::size_t>(v)] == 1 && !onBoundary[static_cast<std::size_t>(v)])
      {
        ends.push_back(v);
      }
    }
    while (!ends.empty())
    {
      int v = ends.back();
      ends.pop_back();
      if (degree[static_cast<std::size_t>(v)] != 1)
      {
        continue;
      }
      for (int e : chart.vertexEdges(v))
      {
        if (cut[static_cast<std::size_t>(e)])
        {
          cut[static_cast<std::size_t>(e)] = 0;
          const std::array<int, 2>& pair = chart.edgeVertices(e);
          const int other = pair[0] == v ? pair[1] : pair[0];
          --degree[static_cast<std::size_t>(v)];
          if (--degree[static_cast<std::size_t>(other)] == 1 && !onBoundary[static_cast<std::size_t>(other)])
          {
            ends.push_back(other);
          }
          break;
        }
      }
    }
  }
  EdgeCut result = splitAlongEdges(chart, cut);
  const MeshReport after = inspectMesh(result.mesh);
  if (after.boundaryLoops != 1 || after.eulerCharacteristic != 1 || after.components != 1 ||
    after.nonManifoldVertices != 0)
  {
    throw Error("the chart (" + std::to_string(loops) + " boundary loops, genus " + std::to_string(genus) +
      ") could not be cut into a disk");
  }
  return result;
}

} // namespace kerf
