// splitAlongFaceLabels: one copy of a vertex per label (or per fan of a label) of the faces around it.
#include "Mesh/SplitAlongFaceLabels.h"

#include "Error.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>

namespace kerf
{
namespace
{
// True if triangles a and b share the vertex `other` besides v (then they share the edge v-other).
bool shareEdgeAt(const Triangle& a, const Triangle& b, int v)
{
  for (int x : a)
  {
    if (x != v && std::find(b.begin(), b.end(), x) != b.end())
    {
      return true;
    }
  }
  return false;
}

// True if the triangles around v all have one label and, for LabelFans::Separate, form one fan
// (TriangleMesh::isSingleFan: across manifold edges only; where this fails the general path
// decides, which also joins triangles across non-manifold edges).
bool isOneFanOfOneLabel(const TriangleMesh& mesh, const std::vector<int>& faceLabels, int v, LabelFans fans)
{
  const IndexRange faces = mesh.vertexFaces(v);
  const int label = faceLabels[static_cast<std::size_t>(faces[0])];
  for (int f : faces)
  {
    if (faceLabels[static_cast<std::size_t>(f)] != label)
    {
      return false;
    }
  }
  if (fans != LabelFans::Separate)
  {
    return true;
  }
  return mesh.isSingleFan(v);
}
} // namespace

SplitMesh splitAlongFaceLabels(const TriangleMesh& mesh, const std::vector<int>& faceLabels, LabelFans fans)
{
  if (static_cast<int>(faceLabels.size()) != mesh.faceCount())
  {
    throw Error("the face labels hold " + std::to_string(faceLabels.size()) + " values for " +
      std::to_string(mesh.faceCount()) + " triangles");
  }
  SplitMesh split;
  std::vector<Vector3> points;
  std::vector<Triangle> triangles = mesh.triangles();
  // At least one copy of every vertex a triangle uses.
  points.reserve(static_cast<std::size_t>(mesh.vertexCount()));
  split.originalPoint.reserve(static_cast<std::size_t>(mesh.vertexCount()));
  // Around each vertex: its faces as (label, group, face), the group the first face of its fan
  // (or of its label), so that sorting numbers the copies by label, then fan.
  std::vector<std::tuple<int, int, int>> around;
  std::vector<std::size_t> group;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const IndexRange faces = mesh.vertexFaces(v);
    const std::size_t count = faces.size();
    if (count > 0 && isOneFanOfOneLabel(mesh, faceLabels, v, fans))
    {
      // One copy for all the triangles (most vertices): the pairs and the sort below give the same.
      points.push_back(mesh.point(v));
      split.originalPoint.push_back(v);
      for (int f : faces)
      {
        for (std::size_t k = 0; k < 3; ++k)
        {
          if (mesh.triangle(f)[k] == v)
          {
            triangles[static_cast<std::size_t>(f)][k] = static_cast<int>(points.size()) - 1;
          }
        }
      }
      continue;
    }
    group.resize(count);
    std::iota(group.begin(), group.end(), 0);
    // Union of faces of one label, through a shared edge at v when fans are separated.
    for (std::size_t i = 0; i < count; ++i)
    {
      for (std::size_t j = 0; j < i; ++j)
      {
        const int fi = faces[i], fj = faces[j];
        if (faceLabels[static_cast<std::size_t>(fi)] != faceLabels[static_cast<std::size_t>(fj)] ||
          (fans == LabelFans::Separate && !shareEdgeAt(mesh.triangle(fi), mesh.triangle(fj), v)))
        {
          continue;
        }
        std::size_t a = i, b = j;
        while (group[a] != a)
        {
          a = group[a];
        }
        while (group[b] != b)
        {
          b = group[b];
        }
        group[std::max(a, b)] = std::min(a, b);
      }
    }
    around.clear();
    for (std::size_t i = 0; i < count; ++i)
    {
      std::size_t root = i;
      while (group[root] != root)
      {
        root = group[root];
      }
      around.emplace_back(faceLabels[static_cast<std::size_t>(faces[i])], faces[root], faces[i]);
    }
    std::sort(around.begin(), around.end());
    for (std::size_t i = 0; i < around.size(); ++i)
    {
      if (i == 0 || std::get<1>(around[i]) != std::get<1>(around[i - 1]) ||
        std::get<0>(around[i]) != std::get<0>(around[i - 1]))
      {
        points.push_back(mesh.point(v));
        split.originalPoint.push_back(v);
      }
      const int f = std::get<2>(around[i]);
      for (std::size_t k = 0; k < 3; ++k)
      {
        if (mesh.triangle(f)[k] == v)
        {
          triangles[static_cast<std::size_t>(f)][k] = static_cast<int>(points.size()) - 1;
        }
      }
    }
  }
  split.mesh = TriangleMesh(std::move(points), std::move(triangles));
  split.faceLabel = faceLabels;
  return split;
}

} // namespace kerf
