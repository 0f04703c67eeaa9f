// The border between vtkPolyData and kerf::Surface that every Kerf filter uses.
#pragma once

#include "Mesh/MeshValidation.h"
#include "Mesh/TriangleMesh.h"
#include "Surface/Surface.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <memory>
#include <string>
#include <vector>

class vtkDataArray;
class vtkDoubleArray;
class vtkPolyData;
class vtkUnsignedCharArray;

namespace kerf
{

struct ConvertedSurface;

/// Converts a filter's vtkPolyData input into a validated kerf::Surface and builds the filter's
/// output surface from it.
///
/// Polygons are triangulated (ear clipping) and triangle strips split; vertices and lines are
/// not part of the surface. Points with identical coordinates are welded for the computation
/// (readers split OBJ files at texture seams and STL files at every facet), so the Core mesh's
/// triangles use one representative per position; per-point results are copied back to every
/// input point with ToInputPoints. When the input holds only triangles, the output has the
/// input's structure; otherwise the output is the triangulated surface with the input's point
/// data and with each triangle carrying the cell data of the polygon it came from.
///
/// The caching rule of every filter: a conversion is shared by every filter whose input has the
/// same geometry (the same point and cell arrays, unmodified, and the same coordinates, compared
/// bit for bit so that points edited in place are noticed), so a pipeline of Kerf filters converts
/// and validates its surface once, and the data derived from it (kerf::Surface: locator,
/// normals, descriptors, Laplacian weights) is computed once. A filter keeps its algorithm's
/// session (its solver state) with SessionFor, which makes a new one when the surface changes.
class SurfaceInput
{
public:
  SurfaceInput();
  ~SurfaceInput();

  /// Converts and validates the input (or reuses the conversion of the same geometry). Returns
  /// false and sets `error` to a sentence naming the problem.
  bool Load(vtkPolyData* input, const MeshRequirements& requirements, std::string& error);

  const std::shared_ptr<const Surface>& SharedSurface() const;
  const Surface& GetSurface() const { return *this->SharedSurface(); }
  const TriangleMesh& Mesh() const { return this->SharedSurface()->mesh(); }
  const MeshReport& Report() const;
  /// Input cell id of each triangle.
  const std::vector<vtkIdType>& SourceCells() const;
  /// Number of input points that were welded onto an earlier point with the same coordinates.
  int WeldedPointCount() const;
  /// The Core vertex that stands for input point `point` (itself unless welded).
  int Representative(int point) const;
  /// True when the output cannot share the input's cells (polygons, strips, verts or lines).
  bool Rebuilt() const;

  /// Per-input-point values from per-vertex values: each representative's value copied to the
  /// input points welded onto it.
  template <typename T>
  std::vector<T> ToInputPoints(std::vector<T> values) const
  {
    const int points = this->Mesh().vertexCount();
    for (int i = 0; i < points && i < static_cast<int>(values.size()); ++i)
    {
      values[static_cast<std::size_t>(i)] = values[static_cast<std::size_t>(this->Representative(i))];
    }
    return values;
  }

  /// Fills `output` with the surface (see the class comment) and the input's data arrays.
  void MakeOutput(vtkPolyData* input, vtkPolyData* output) const;

  /// Per-triangle values from per-input-cell values (a polygon's value on each of its
  /// triangles).
  template <typename T>
  std::vector<T> CellValuesToTriangles(const std::vector<T>& perCell) const
  {
    const std::vector<vtkIdType>& source = this->SourceCells();
    std::vector<T> values(source.size());
    for (std::size_t t = 0; t < source.size(); ++t)
    {
      values[t] = perCell[static_cast<std::size_t>(source[t])];
    }
    return values;
  }

  /// The filter's session bound to the current surface: `holder`'s session while it is bound to
  /// it, else a new Session(SharedSurface()).
  template <typename Session>
  Session& SessionFor(std::unique_ptr<Session>& holder) const
  {
    if (!holder || &holder->surface() != this->SharedSurface().get())
    {
      holder.reset(new Session(this->SharedSurface()));
    }
    return *holder;
  }

private:
  std::shared_ptr<const ConvertedSurface> Current;
};

/// Copies a tuple-per-point or tuple-per-cell array into doubles; false if the component count
/// differs from `components`. NaN values are copied as they are.
bool CopyToDoubles(vtkDataArray* array, int components, std::vector<double>& values);

/// A named double array holding `values` (one component).
vtkSmartPointer<vtkDoubleArray> MakeArray(const char* name, const std::vector<double>& values);
/// A named three-component double array holding `vectors`.
vtkSmartPointer<vtkDoubleArray> MakeArray(const char* name, const std::vector<Vector3>& vectors);
/// A named unsigned char array holding `flags`.
vtkSmartPointer<vtkUnsignedCharArray> MakeArray(const char* name, const std::vector<unsigned char>& flags);

} // namespace kerf
