// Segment spines: the longest path through each segment's innermost faces.
#include "Segmentation/SegmentSpines.h"

#include "Error.h"
#include "Mesh/ShortestPaths.h"

#include <limits>
#include <map>
#include <utility>

namespace kerf
{

std::vector<SegmentSpine> segmentSpines(const TriangleMesh& mesh, const std::vector<int>& labels, double depth)
{
  if (static_cast<int>(labels.size()) != mesh.faceCount())
  {
    throw Error("the segmentation must have one label per face");
  }
  if (!(depth > 0.0 && depth <= 1.0))
  {
    throw Error("the spine's depth must be a fraction in (0, 1]");
  }
  auto centroid = [&mesh](int f) {
    const Triangle& t = mesh.triangle(f);
    return Vector3((mesh.point(t[0]) + mesh.point(t[1]) + mesh.point(t[2])) / 3.0);
  };
  // Distance inside the segment from its border faces (Dijkstra over face neighbours).
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> inside(labels.size(), infinity);
  DistanceQueue queue;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    for (int k = 0; k < 3 && labels[f] >= 0; ++k)
    {
      const int g = mesh.faceNeighbor(f, k);
      if (g >= 0 && labels[g] != labels[f] && inside[f] != 0.0)
      {
        inside[f] = 0.0;
        queue.emplace(0.0, f);
      }
    }
  }
  searchShortestPaths(
    queue, [&](int f) -> double& { return inside[f]; },
    [&](int f, double d, const auto& lower) {
      for (int k = 0; k < 3; ++k)
      {
        const int g = mesh.faceNeighbor(f, k);
        if (g >= 0 && labels[g] == labels[f])
        {
          lower(g, d + (centroid(g) - centroid(f)).norm());
        }
      }
    });
  // The innermost face of each label (a borderless segment: its first face).
  std::map<int, int> innermost;
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    if (labels[f] < 0)
    {
      continue;
    }
    const auto found = innermost.find(labels[f]);
    if (found == innermost.end())
    {
      innermost.emplace(labels[f], f);
    }
    else if (inside[f] != infinity && (inside[found->second] == infinity || inside[f] > inside[found->second]))
    {
      found->second = f;
    }
  }
  // The stroke: the longest path (two sweeps of Dijkstra, centroid to centroid) through the
  // faces of the segment at least `depth` times as far inside as its innermost face, in the part of
  // them that the innermost face reaches.
  std::vector<double> reach(labels.size(), infinity);
  std::vector<int> parent(labels.size(), -1);
  std::vector<int> touched;
  auto sweep = [&](int source, int label, double threshold) {
    for (int f : touched)
    {
      reach[f] = infinity;
      parent[f] = -1;
    }
    touched.assign(1, source);
    reach[source] = 0.0;
    queue.emplace(0.0, source);
    int farthest = source;
    while (!queue.empty())
    {
      const auto [d, f] = queue.top();
      queue.pop();
      if (d > reach[f])
      {
        continue;
      }
      if (d > reach[farthest] || (d == reach[farthest] && f < farthest))
      {
        farthest = f;
      }
      for (int k = 0; k < 3; ++k)
      {
        const int g = mesh.faceNeighbor(f, k);
        if (g >= 0 && labels[g] == label && inside[g] >= threshold)
        {
          const double candidate = d + (centroid(g) - centroid(f)).norm();
          if (candidate < reach[g])
          {
            if (reach[g] == infinity)
            {
              touched.push_back(g);
            }
            reach[g] = candidate;
            parent[g] = f;
            queue.emplace(candidate, g);
          }
        }
      }
    }
    return farthest;
  };
  std::vector<SegmentSpine> spines;
  for (const auto& [label, first] : innermost)
  {
    SegmentSpine spine;
    spine.label = label;
    const double threshold = depth * inside[first];
    if (threshold == infinity)
    {
      spine.faces.push_back(first); // a segment without a border: its first face
    }
    else
    {
      const int end = sweep(sweep(first, label, threshold), label, threshold);
      for (int f = end; f >= 0; f = parent[f])
      {
        spine.faces.push_back(f);
      }
    }
    spines.push_back(std::move(spine));
  }
  return spines;
}

} // namespace kerf
