// Conversion between kerf::TriangleMesh and OpenMesh.
#include "Mesh/OpenMeshAdapter.h"

#include "Error.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <string>

namespace kerf
{

EditableMesh toEditableMesh(const TriangleMesh& mesh)
{
  EditableMesh out;
  out.reserve(mesh.vertexCount(), mesh.edgeCount(), mesh.faceCount());
  std::vector<EditableMesh::VertexHandle> handles(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const Vector3& p = mesh.point(v);
    handles[v] = out.add_vertex(EditableMesh::Point(p.x(), p.y(), p.z()));
  }
  // OpenMesh reports refused faces on its error stream; Core never prints, so it is muted here
  // and the refusal becomes an exception.
  const bool wasEnabled = omerr().is_enabled();
  omerr().disable();
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const Triangle& t = mesh.triangle(f);
    const EditableMesh::FaceHandle face = out.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
    if (!face.is_valid())
    {
      if (wasEnabled)
      {
        omerr().enable();
      }
      throw Error("triangle " + std::to_string(f) + " makes the mesh non-manifold or inconsistently oriented");
    }
  }
  if (wasEnabled)
  {
    omerr().enable();
  }
  return out;
}

TriangleMesh fromEditableMesh(const EditableMesh& mesh)
{
  std::vector<Vector3> points;
  std::vector<int> index(mesh.n_vertices(), -1);
  for (const auto vh : mesh.vertices())
  {
    const EditableMesh::Point& p = mesh.point(vh);
    index[vh.idx()] = static_cast<int>(points.size());
    points.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<Triangle> triangles;
  triangles.reserve(mesh.n_faces());
  for (const auto fh : mesh.faces())
  {
    Triangle t{};
    int k = 0;
    for (const auto vh : mesh.fv_range(fh))
    {
      if (k < 3)
      {
        t[k] = index[vh.idx()];
      }
      ++k;
    }
    if (k != 3)
    {
      throw Error("OpenMesh face " + std::to_string(fh.idx()) + " is not a triangle");
    }
    triangles.push_back(t);
  }
  return TriangleMesh(std::move(points), std::move(triangles));
}

} // namespace kerf
