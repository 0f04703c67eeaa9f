// A mesh made of some triangles of another, and the edge joining two vertices.
#include "Mesh/Submesh.h"

namespace kerf
{

Submesh extractSubmesh(const TriangleMesh& mesh, const std::vector<int>& faces)
{
  Submesh sub;
  sub.localVertex.assign(mesh.vertexCount(), -1);
  std::vector<char> used(mesh.vertexCount(), 0);
  for (int f : faces)
  {
    for (int v : mesh.triangle(f))
    {
      used[v] = 1;
    }
  }
  std::vector<Vector3> points;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (used[v])
    {
      sub.localVertex[v] = static_cast<int>(sub.globalVertex.size());
      sub.globalVertex.push_back(v);
      points.push_back(mesh.point(v));
    }
  }
  std::vector<Triangle> triangles;
  for (int f : faces)
  {
    const Triangle& t = mesh.triangle(f);
    triangles.push_back({ sub.localVertex[t[0]], sub.localVertex[t[1]], sub.localVertex[t[2]] });
    sub.globalFace.push_back(f);
  }
  sub.mesh = TriangleMesh(std::move(points), std::move(triangles));
  return sub;
}

int edgeBetween(const TriangleMesh& mesh, int a, int b)
{
  const IndexRange neighbors = mesh.vertexNeighbors(a);
  for (std::size_t i = 0; i < neighbors.size(); ++i)
  {
    if (neighbors[i] == b)
    {
      return mesh.vertexEdges(a)[i];
    }
  }
  return -1;
}

} // namespace kerf
