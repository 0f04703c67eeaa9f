// A surface as a mesh file holds it: points, cells of each kind and the arrays that come with them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace kerf
{

/// Cells of one kind: cell i uses indices[offsets[i] .. offsets[i + 1]).
struct CellList
{
  std::vector<std::int64_t> offsets{ 0 };
  std::vector<std::int64_t> indices;

  std::size_t size() const { return this->offsets.size() - 1; }
  void close() { this->offsets.push_back(static_cast<std::int64_t>(this->indices.size())); }
};

/// A named array of values per point or per polygon, with the role a VTK reader gives it.
struct MeshFileArray
{
  enum class Role
  {
    Plain,
    Normals,            ///< three components
    TextureCoordinates, ///< two components
    Colors              ///< 3 or 4 components in 0..255 (stored as unsigned char in VTK)
  };
  std::string name;
  Role role = Role::Plain;
  int components = 1;
  std::vector<double> values; ///< components values per tuple
};

/// What the readers of Kerf's own formats (PLY, STL, OBJ) return. Every index is already checked
/// to name an existing point.
struct MeshFileData
{
  std::vector<double> points;   ///< x, y, z per point
  bool singlePrecision = false; ///< the file stores coordinates as 32-bit floats
  CellList vertices;            ///< point cells (OBJ "p")
  CellList lines;               ///< polylines (OBJ "l")
  CellList polygons;
  std::vector<MeshFileArray> pointArrays;
  std::vector<MeshFileArray> polygonArrays; ///< only for files whose cells are all polygons

  std::size_t pointCount() const { return this->points.size() / 3; }
};

} // namespace kerf
