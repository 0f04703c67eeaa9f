// Connected regions of triangles by a depth-first walk across crossable edges.
#include "Mesh/FaceRegions.h"

namespace kerf
{

int labelFaceRegions(
  const TriangleMesh& mesh, const std::function<bool(int face, int side)>& crossable, std::vector<int>& labels)
{
  labels.assign(static_cast<std::size_t>(mesh.faceCount()), -1);
  std::vector<int> stack;
  int next = 0;
  for (int seed = 0; seed < mesh.faceCount(); ++seed)
  {
    if (labels[static_cast<std::size_t>(seed)] >= 0)
    {
      continue;
    }
    labels[static_cast<std::size_t>(seed)] = next;
    stack.push_back(seed);
    while (!stack.empty())
    {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const int g = mesh.faceNeighbor(f, k);
        if (g >= 0 && labels[static_cast<std::size_t>(g)] < 0 && crossable(f, k))
        {
          labels[static_cast<std::size_t>(g)] = next;
          stack.push_back(g);
        }
      }
    }
    ++next;
  }
  return next;
}

} // namespace kerf
