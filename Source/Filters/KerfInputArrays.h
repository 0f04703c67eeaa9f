// A filter's inputs read into Core's terms: selected and named arrays, labels, points, polylines and vertex cells,
// points and lines placed on the surface.
#pragma once

#include "Geodesic/SurfacePoint.h"
#include "KerfSurfaceInput.h"
#include "Mesh/TriangleMesh.h"

#include <vtkType.h>

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkPointSet;
class vtkPolyData;

namespace kerf
{

/// The points of a point set (input 1 of a filter) on the surface, each projected and refused
/// beyond `maximumDistance` (projectOntoSurface), named "<noun> <i>" in errors.
std::vector<SurfacePoint> ProjectPointsOntoSurface(
  const Surface& surface, vtkPointSet* points, double maximumDistance, const std::string& noun);

/// The one-component values of the algorithm's input array `index` (as selected with
/// SetInputArrayToProcess), one per point or cell of its data object. With no array name selected,
/// the active scalars of that association are read. Throws kerf::Error naming the array, its owner
/// ("the surface", "the constraint points") and the input array index for a missing array, another
/// number of components or another number of values than `expected`.
std::vector<double> ReadInputArray(vtkAlgorithm* algorithm, int index, vtkIdType expected, const std::string& owner);

/// Per-triangle labels from the input array `index`, a cell array of `cells` integer labels >= -1
/// (each polygon's label on each of its triangles); throws kerf::Error as ReadInputArray does, and
/// naming the first cell that holds anything else.
std::vector<int> ReadTriangleLabels(
  vtkAlgorithm* algorithm, int index, const SurfaceInput& surface, vtkIdType cells, const std::string& owner);

/// What a filter that changes a labelling reads (vtkSnakeRefinement, vtkBoundaryBandCut): input
/// 0's surface, loaded into `surface` with `requirements`, its per-triangle labels from input
/// array 0 (as ReadTriangleLabels), and the name of that array ("Segment" when it has none).
struct InputLabels
{
  std::vector<int> labels;
  std::string arrayName;
};
InputLabels LoadLabelledSurface(
  vtkAlgorithm* algorithm, SurfaceInput& surface, vtkPolyData* input, const MeshRequirements& requirements);

/// The one-component point array `name` of a point set, one value per point; throws kerf::Error
/// naming it and its owner when it is missing or has another shape. (Arrays of a filter's first
/// input are selected with SetInputArrayToProcess and read with ReadInputArray; arrays of other
/// inputs are named, see vtkHarmonicField.)
std::vector<double> ReadNamedPointArray(vtkPointSet* points, const char* name, const std::string& owner);
/// The one-component cell array `name` of a polydata, one value per cell, as ReadNamedPointArray.
std::vector<double> ReadNamedCellArray(vtkPolyData* cells, const char* name, const std::string& owner);

/// The coordinates of a point set's points.
std::vector<Vector3> ReadPoints(vtkPointSet* points);
/// The polylines of a vtkPolyData's line cells, as point lists; throws for a line naming a point
/// that does not exist.
std::vector<std::vector<Vector3>> ReadPolylines(vtkPolyData* lines, const std::string& owner);
/// The points of each of a vtkPolyData's vertex cells (vertex or poly-vertex), as ReadPolylines.
std::vector<std::vector<Vector3>> ReadVertexCells(vtkPolyData* vertices, const std::string& owner);

/// The polylines of `lines` placed on the surface (kerf::placeCurveOnSurface), each named
/// "<owner> line <i>" in errors; a polyline whose last point repeats its first is closed.
/// Throws when `lines` holds no line.
std::vector<SurfaceCurve> PlaceLinesOnSurface(
  const Surface& surface, vtkPolyData* lines, double maximumDistance, const std::string& owner);

} // namespace kerf
