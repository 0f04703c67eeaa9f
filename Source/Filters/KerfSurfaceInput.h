// The border between vtkPolyData and kerf::TriangleMesh that every Kerf filter uses.
#pragma once

#include "Mesh/MeshValidation.h"
#include "Mesh/TriangleMesh.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <string>
#include <vector>

class vtkDataArray;
class vtkDoubleArray;
class vtkPolyData;
class vtkUnsignedCharArray;

namespace kerf
{

/// Converts a filter's vtkPolyData input into a validated kerf::TriangleMesh, once per run, and
/// builds the filter's output surface from it.
///
/// Polygons are triangulated (ear clipping) and triangle strips split; vertices and lines are
/// not part of the surface. Points with identical coordinates are welded for the computation
/// (readers split OBJ files at texture seams and STL files at every facet), so the Core mesh's
/// triangles use one representative per position; per-point results are copied back to every
/// input point with ExpandToInputPoints. When the input holds only triangles, the output has the input's
/// structure; otherwise the output is the triangulated surface with the input's point data and
/// with each triangle carrying the cell data of the polygon it came from.
class SurfaceInput
{
public:
  /// Converts and validates. Returns false and sets `error` to a sentence naming the problem.
  bool Load(vtkPolyData* input, const MeshRequirements& requirements, std::string& error);

  /// As Load, but keeps the current mesh while the input's geometry is the one loaded last time:
  /// the same point array and cell arrays, none modified since. Only the geometry counts, so a
  /// filter re-executing for a parameter change, or downstream of a filter that only adds data
  /// arrays to a shared structure, does not convert its mesh again. `reused` tells which happened.
  bool LoadIfChanged(vtkPolyData* input, const MeshRequirements& requirements, std::string& error,
    bool& reused);

  const TriangleMesh& Mesh() const { return this->Surface; }
  const MeshReport& Report() const { return this->Inspection; }
  /// Input cell id of each triangle.
  const std::vector<vtkIdType>& SourceCells() const { return this->Source; }
  /// Number of input points that were welded onto an earlier point with the same coordinates.
  int WeldedPointCount() const { return this->Welded; }

  /// The Core vertex that stands for input point `point` (itself unless welded).
  int Representative(int point) const { return this->Representatives[static_cast<std::size_t>(point)]; }

  /// Copies each representative's value to the input points welded onto it.
  template <typename T>
  void ExpandToInputPoints(std::vector<T>& values) const
  {
    for (std::size_t i = 0; i < this->Representatives.size() && i < values.size(); ++i)
    {
      values[i] = values[static_cast<std::size_t>(this->Representatives[i])];
    }
  }

  /// True when the output cannot share the input's cells (polygons, strips, verts or lines).
  bool Rebuilt() const { return this->Rebuild; }

  /// Fills `output` with the surface (see the class comment) and the input's data arrays.
  void MakeOutput(vtkPolyData* input, vtkPolyData* output) const;

private:
  TriangleMesh Surface;
  MeshReport Inspection;
  std::vector<vtkIdType> Source;
  std::vector<int> Representatives;
  int Welded = 0;
  bool Rebuild = false;
  /// Whether the input's coordinates are, bit for bit, those of the loaded mesh.
  bool SamePoints(vtkPolyData* input) const;

  // The geometry LoadIfChanged loaded last: objects and modification times of the point array and
  // the four cell arrays (the coordinates are compared as well).
  std::vector<std::pair<const void*, vtkMTimeType>> LoadedGeometry;
  bool Loaded = false;
};

/// Copies a tuple-per-point or tuple-per-cell array into doubles; false if the component count
/// differs from `components`. NaN values are copied as they are.
bool CopyToDoubles(vtkDataArray* array, int components, std::vector<double>& values);

/// A named double array holding `values` (one component).
vtkSmartPointer<vtkDoubleArray> MakeArray(const char* name, const std::vector<double>& values);
/// A named three-component double array holding `vectors`.
vtkSmartPointer<vtkDoubleArray> MakeArray(const char* name, const std::vector<Vector3>& vectors);
/// A named unsigned char array holding `flags`.
vtkSmartPointer<vtkUnsignedCharArray> MakeArray(
  const char* name, const std::vector<unsigned char>& flags);

} // namespace kerf
