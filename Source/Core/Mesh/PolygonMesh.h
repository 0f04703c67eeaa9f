// A polygon mesh as read from a file or a vtkPolyData, before triangulation.
#pragma once

#include "Mesh/TriangleMesh.h"

#include <vector>

namespace kerf
{

/// A polygon mesh: polygon i uses polygonIndices[polygonOffsets[i] .. polygonOffsets[i + 1]).
struct PolygonMesh
{
  std::vector<Vector3> points;
  std::vector<int> polygonOffsets{ 0 };
  std::vector<int> polygonIndices;

  int polygonCount() const { return static_cast<int>(this->polygonOffsets.size()) - 1; }
};

} // namespace kerf
