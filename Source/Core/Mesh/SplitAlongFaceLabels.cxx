// splitAlongFaceLabels: one copy of a vertex per label of the faces around it.
#include "Mesh/SplitAlongFaceLabels.h"

#include "Error.h"

#include <algorithm>
#include <string>
#include <utility>

namespace kerf
{

SplitMesh splitAlongFaceLabels(const TriangleMesh& mesh, const std::vector<int>& faceLabels)
{
  if (static_cast<int>(faceLabels.size()) != mesh.faceCount())
  {
    throw Error("the face labels hold " + std::to_string(faceLabels.size()) + " values for " +
      std::to_string(mesh.faceCount()) + " triangles");
  }
  SplitMesh split;
  std::vector<Vector3> points;
  // For each input vertex its copies as (label, new vertex), sorted by label.
  std::vector<int> copyOffsets(static_cast<std::size_t>(mesh.vertexCount()) + 1, 0);
  std::vector<std::pair<int, int>> copies;
  std::vector<int> labels;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    labels.clear();
    for (int f : mesh.vertexFaces(v))
    {
      labels.push_back(faceLabels[static_cast<std::size_t>(f)]);
    }
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
    for (int label : labels)
    {
      copies.emplace_back(label, static_cast<int>(points.size()));
      points.push_back(mesh.point(v));
      split.originalPoint.push_back(v);
    }
    copyOffsets[static_cast<std::size_t>(v) + 1] = static_cast<int>(copies.size());
  }
  std::vector<Triangle> triangles(static_cast<std::size_t>(mesh.faceCount()));
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const int label = faceLabels[static_cast<std::size_t>(f)];
    for (int k = 0; k < 3; ++k)
    {
      const int v = mesh.triangle(f)[static_cast<std::size_t>(k)];
      const auto first = copies.begin() + copyOffsets[static_cast<std::size_t>(v)];
      const auto last = copies.begin() + copyOffsets[static_cast<std::size_t>(v) + 1];
      const auto copy = std::lower_bound(first, last, std::make_pair(label, -1));
      triangles[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)] = copy->second;
    }
  }
  split.mesh = TriangleMesh(std::move(points), std::move(triangles));
  split.faceLabel = faceLabels;
  return split;
}

} // namespace kerf
