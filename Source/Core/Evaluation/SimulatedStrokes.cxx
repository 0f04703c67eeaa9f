// Simulated strokes: boundary chains between segments walked and resampled, and strokes through each segment's
// innermost faces.
#include "Evaluation/SimulatedStrokes.h"

#include "Error.h"
#include "Segmentation/SegmentSpines.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>

namespace kerf
{

namespace
{
// Walks a chain of the unused `edges` (indices into mesh edges) through edge `startEdge`, from
// an end, marking the edges it takes; returns the vertex sequence. Where the chain branches the
// walk takes one way; the edges it leaves make chains of their own in later walks.
std::vector<int> walkChain(const TriangleMesh& mesh, const std::vector<int>& edges,
  const std::map<int, std::vector<int>>& incident, std::vector<char>& used, int startEdge)
{
  auto unusedAt = [&](int v) {
    int count = 0;
    for (int e : incident.at(v))
    {
      count += used[e] ? 0 : 1;
    }
    return count;
  };
  // An end: a vertex with one unused chain edge, in the unused part connected to startEdge.
  std::vector<int> component{ startEdge };
  std::vector<char> seen(edges.size(), 0);
  seen[startEdge] = 1;
  for (std::size_t i = 0; i < component.size(); ++i)
  {
    for (int v : mesh.edgeVertices(edges[component[i]]))
    {
      for (int other : incident.at(v))
      {
        if (!seen[other] && !used[other])
        {
          seen[other] = 1;
          component.push_back(other);
        }
      }
    }
  }
  int startVertex = -1;
  for (int e : component)
  {
    for (int v : mesh.edgeVertices(edges[e]))
    {
      if (unusedAt(v) == 1 && (startVertex < 0 || v < startVertex))
      {
        startVertex = v;
      }
    }
  }
  if (startVertex < 0)
  {
    startVertex = mesh.edgeVertices(edges[startEdge])[0]; // a loop: any vertex
  }
  std::vector<int> path{ startVertex };
  int current = startVertex;
  while (true)
  {
    int next = -1;
    for (int e : incident.at(current))
    {
      if (!used[e])
      {
        used[e] = 1;
        const std::array<int, 2>& ev = mesh.edgeVertices(edges[e]);
        next = ev[0] == current ? ev[1] : ev[0];
        break;
      }
    }
    if (next < 0)
    {
      break;
    }
    path.push_back(next);
    current = next;
  }
  return path;
}

std::vector<Vector3> resample(const TriangleMesh& mesh, const std::vector<int>& path, double spacing)
{
  std::vector<double> arc{ 0.0 };
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    arc.push_back(arc.back() + (mesh.point(path[i]) - mesh.point(path[i - 1])).norm());
  }
  const double length = arc.back();
  const int count = std::clamp(static_cast<int>(std::round(length / spacing)) + 1, 4, 64);
  std::vector<Vector3> points;
  std::size_t segment = 1;
  for (int k = 0; k < count; ++k)
  {
    const double s = length * k / (count - 1);
    while (segment + 1 < arc.size() && arc[segment] < s)
    {
      ++segment;
    }
    const double span = arc[segment] - arc[segment - 1];
    const double t = span > 0.0 ? std::clamp((s - arc[segment - 1]) / span, 0.0, 1.0) : 0.0;
    points.push_back(mesh.point(path[segment - 1]) + t * (mesh.point(path[segment]) - mesh.point(path[segment - 1])));
  }
  return points;
}
} // namespace

std::vector<BoundaryStroke> boundaryStrokes(const TriangleMesh& mesh, const std::vector<int>& labels, double spacing)
{
  if (static_cast<int>(labels.size()) != mesh.faceCount())
  {
    throw Error("the segmentation must have one label per face");
  }
  if (!(spacing > 0.0))
  {
    throw Error("the stroke spacing must be positive");
  }
  // Boundary edges grouped by label pair.
  std::map<std::pair<int, int>, std::vector<int>> byPair;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    if (mesh.edgeFaceCount(e) != 2)
    {
      continue;
    }
    const int a = labels[mesh.edgeFaces(e)[0]];
    const int b = labels[mesh.edgeFaces(e)[1]];
    if (a >= 0 && b >= 0 && a != b)
    {
      byPair[{ std::min(a, b), std::max(a, b) }].push_back(e);
    }
  }
  std::vector<BoundaryStroke> strokes;
  for (const auto& entry : byPair)
  {
    const std::vector<int>& edges = entry.second;
    std::map<int, std::vector<int>> incident; // vertex -> positions in `edges`
    for (std::size_t i = 0; i < edges.size(); ++i)
    {
      for (int v : mesh.edgeVertices(edges[i]))
      {
        incident[v].push_back(static_cast<int>(i));
      }
    }
    std::vector<char> used(edges.size(), 0);
    for (std::size_t i = 0; i < edges.size(); ++i)
    {
      if (used[i])
      {
        continue;
      }
      const std::vector<int> path = walkChain(mesh, edges, incident, used, static_cast<int>(i));
      double length = 0.0;
      for (std::size_t k = 1; k < path.size(); ++k)
      {
        length += (mesh.point(path[k]) - mesh.point(path[k - 1])).norm();
      }
      if (length >= 0.25 * spacing)
      {
        strokes.push_back({ entry.first.first, entry.first.second, resample(mesh, path, spacing) });
      }
    }
  }
  return strokes;
}

std::vector<SegmentStroke> innermostStrokes(const TriangleMesh& mesh, const std::vector<int>& labels, double depth)
{
  std::vector<SegmentStroke> strokes;
  for (const SegmentSpine& spine : segmentSpines(mesh, labels, depth))
  {
    SegmentStroke stroke;
    stroke.label = spine.label;
    for (int f : spine.faces)
    {
      const Triangle& t = mesh.triangle(f);
      stroke.points.push_back((mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0);
    }
    strokes.push_back(std::move(stroke));
  }
  return strokes;
}

} // namespace kerf
