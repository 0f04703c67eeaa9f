// What every Kerf filter's RequestData shares: the exception border, input arrays and points, output helpers.
#pragma once

#include "Harmonic/HarmonicCutSession.h"
#include "Geodesic/RoiScissor.h"
#include "Geodesic/SurfacePoint.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "KerfSurfaceInput.h"
#include "Mesh/TriangleMesh.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

class vtkAbstractArray;
class vtkAlgorithm;
class vtkDataArray;
class vtkDiscClickAlgorithm;
class vtkFieldData;
class vtkInformation;
class vtkInformationVector;
class vtkPointSet;
class vtkPolyData;
class vtkStrokeConstraintAlgorithm;

namespace kerf
{

class DrawnDiscList;

/// The border every RequestData runs inside: `body` does the work and throws kerf::Error (or
/// anything else) on failure. Every exception stops here: it is reported with vtkErrorMacro as
/// "<what>: <message>." and RunGuarded returns 0 (VTK's failure); otherwise the progress is set
/// to 1 and it returns 1.
int RunGuarded(vtkAlgorithm* algorithm, const char* what, const std::function<void()>& body);

/// Calls `setter` and stops every exception at the border of a filter's setter (an impossible
/// size, an allocation failure): reported with vtkErrorMacro, nothing changes.
void GuardSetter(vtkAlgorithm* algorithm, const char* what, const std::function<void()>& setter);

/// Loads `input` into `surface` (converting and validating it, or reusing the conversion of the
/// same geometry); throws kerf::Error with the reason it is refused.
void LoadSurface(SurfaceInput& surface, vtkPolyData* input, const MeshRequirements& requirements);

/// Throws unless every output array name is non-empty.
void CheckOutputNames(std::initializer_list<const char*> names);
/// Throws if two output arrays of the same kind would get the same name.
void CheckDifferentNames(const char* a, const char* b, const std::string& what);

/// `value` if it is a number; throws naming the parameter for NaN.
double Finite(double value, const char* parameter);
/// A stroke's iso-value I: finite, and small enough that I + 1 and I - 1 differ from it (the
/// values of its two sides); throws otherwise.
double StrokeIsoValue(double value);
/// The soft-constraint formulation a Formulation property names: 0 point values, 1 least
/// squares, 2 automatic (the session's kerf::automaticFormulation: least squares on coarse
/// meshes, point values where the mean edge is at most 1/180 of the diagonal).
SoftConstraintFormulation FilterFormulation(int property, const HarmonicCutSession& session);
/// A distance given as a fraction of the bounding-box diagonal, in length units; 0 stays 0 (no
/// limit). Throws for NaN.
double RelativeDistance(double fraction, double diagonal, const char* parameter);

/// MaximumProjectionDistance as a length: `fraction` of the surface's bounding-box diagonal, or
/// infinity for 0 (no limit). Throws naming `parameter` for NaN.
double ProjectionLimit(double fraction, const Surface& surface, const char* parameter);

/// A point set in a filter's panel (ParaView's handle and polyline widgets) on the surface: the
/// nearest surface point, whatever its distance, because the widgets' points start at the input's
/// bounds, not on the surface (pressing P puts them there). Throws naming `what` for NaN,
/// infinite or huge coordinates.
SurfacePoint PanelPointOnSurface(const Surface& surface, const Vector3& point, const std::string& what);

/// The clicks of a filter with geodesic discs (vtkGeodesicDisc, vtkROIScissor) and how far from
/// the surface they may be.
struct DiscClicks
{
  std::vector<RoiClick> added;
  std::vector<RoiClick> subtracted;
  /// The farthest a click of the click input may be from the surface, as a fraction of the
  /// bounding-box diagonal (infinity: no limit).
  double tolerance = 0.0;
};

/// The clicks of a filter with geodesic discs (its properties, see vtkDiscClickAlgorithm): each
/// point of `clickInput` (input 1), with its own radius (the point array ClickRadiusArrayName, a
/// fraction of the diagonal) when the input has that array, and subtracting its disc where the
/// point array ClickSubtractArrayName is non-zero; without a click input, the `drawn` discs where
/// there are any, else ClickPoint; both moved to the nearest surface point. Throws naming the
/// parameter or the click for NaN parameters, a radius that is not positive, no click and only
/// subtracting clicks.
DiscClicks ReadDiscClicks(
  const Surface& surface, vtkDiscClickAlgorithm* algorithm, const DrawnDiscList& drawn, vtkPointSet* clickInput);

/// The points of a point set (input 1 of a filter) on the surface, each projected and refused
/// beyond `maximumDistance` (projectOntoSurface), named "<noun> <i>" in errors.
std::vector<SurfacePoint> ProjectPointsOntoSurface(
  const Surface& surface, vtkPointSet* points, double maximumDistance, const std::string& noun);

/// The one-component values of the algorithm's input array `index` (as selected with
/// SetInputArrayToProcess), one per point or cell of its data object. With no array name selected,
/// the active scalars of that association are read. Throws kerf::Error naming the array, its owner
/// ("the surface", "the constraint points") and the input array index for a missing array, another
/// number of components or another number of values than `expected`.
std::vector<double> ReadInputArray(vtkAlgorithm* algorithm, int index,
  vtkIdType expected, const std::string& owner);

/// Per-triangle labels from the input array `index`, a cell array of `cells` integer labels >= -1
/// (each polygon's label on each of its triangles); throws kerf::Error as ReadInputArray does, and
/// naming the first cell that holds anything else.
std::vector<int> ReadTriangleLabels(vtkAlgorithm* algorithm, int index,
  const SurfaceInput& surface, vtkIdType cells, const std::string& owner);

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

/// The output of such a filter: the surface (SurfaceInput::MakeOutput) with its labels replaced by
/// `labels` under the input array's name, the active cell scalars.
void WriteRelabelledSurface(
  const SurfaceInput& surface, vtkPolyData* input, vtkPolyData* output, const InputLabels& read, const std::vector<int>& labels);

/// The one-component point array `name` of a point set, one value per point; throws kerf::Error
/// naming it and its owner when it is missing or has another shape. (Arrays of a filter's first
/// input are selected with SetInputArrayToProcess and read with ReadInputArray; arrays of other
/// inputs are named, see vtkHarmonicField.)
std::vector<double> ReadNamedPointArray(vtkPointSet* points, const char* name, const std::string& owner);
/// The one-component cell array `name` of a polydata, one value per cell, as ReadNamedPointArray.
std::vector<double> ReadNamedCellArray(vtkPolyData* cells, const char* name, const std::string& owner);

/// The points a filter's panel sets (ParaView's interactive polyline): a stroke, a path. A count
/// or an index beyond MaximumCount is refused before anything is allocated.
class StrokePointList
{
public:
  static constexpr int MaximumCount = 10000000;
  /// These set the list; true when it changed. Throw kerf::Error for an absurd count or index.
  bool SetCount(int count);
  bool Set(int index, const Vector3& point);
  int Count() const { return static_cast<int>(this->List.size()); }
  const std::vector<Vector3>& Points() const { return this->List; }

private:
  std::vector<Vector3> List;
};

/// The setters of a filter's panel points (SetNumberOf<Noun>Points, Set<Noun>Point): `list` is
/// changed inside GuardSetter (an absurd count or index is reported and nothing changes) and
/// `algorithm` marked modified when it changed. `noun` names the points in errors ("stroke").
void SetPanelPointCount(vtkAlgorithm* algorithm, StrokePointList& list, int count, const std::string& noun);
void SetPanelPoint(
  vtkAlgorithm* algorithm, StrokePointList& list, int index, const Vector3& point, const std::string& noun);

/// The panel's points moved to the nearest points of the surface, whatever their distance (the
/// panel's first points come from the input's bounds); throws naming "<noun> point <i>" for NaN,
/// infinite or huge coordinates.
std::vector<Vector3> PanelPointsOnSurface(const StrokePointList& panel, const Surface& surface, const std::string& noun);

/// The sampling of a vtkStrokeConstraintAlgorithm's strokes into constraints: samples per segment,
/// offset (Offset times `diagonal`), its cap, the iso-value and the projection limit
/// (MaximumProjectionDistance times `diagonal`); throws naming the parameter for NaN.
StrokeOptions ReadStrokeOptions(vtkStrokeConstraintAlgorithm* algorithm, double diagonal);

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

/// Throws `message` unless every value of the vectors and `scalar` is finite.
void CheckFinite(std::initializer_list<const std::vector<double>*> vectors, double scalar, const std::string& message);

/// A one-tuple field-data array holding a number or a word.
vtkSmartPointer<vtkAbstractArray> MakeFieldValue(const char* name, double value);
vtkSmartPointer<vtkAbstractArray> MakeFieldValue(const char* name, const std::string& value);
/// A named int array holding `values`.
vtkSmartPointer<vtkAbstractArray> MakeIntArray(const char* name, const std::vector<int>& values);

/// The field array SegmentSizes of `output`: per label of `labels` (one per output cell) that some
/// cell has, in increasing order of label, the number of cells that have it (cells labelled -1 are
/// not counted). What the
/// Information panel shows of a segmentation, and what its tests read.
void WriteSegmentSizes(const std::vector<int>& labels, vtkPolyData* output);

/// The body of an automatic-segmentation filter: checks `arrayName`, loads `input` into `surface`
/// (validated against `requirements`), copies it to `output` with its arrays, runs `segment` (which
/// returns one label per triangle and may add its figures to the output's field data) and writes
/// the labels as the int cell array `arrayName` and their count as the field value SegmentCount.
void SegmentSurface(vtkAlgorithm* algorithm, SurfaceInput& surface, vtkPolyData* input, vtkPolyData* output,
  const char* arrayName, const MeshRequirements& requirements,
  const std::function<std::vector<int>(const Surface&, vtkFieldData*)>& segment);

/// One polyline to write: its points, whether it closes, its length.
struct PolylineToWrite
{
  const std::vector<Vector3>* points;
  bool closed;
  double length;
};
/// Polylines as the line cells of `lines` (a closed one repeats its first point), with the cell
/// arrays Length and Closed.
void WritePolylines(const std::vector<PolylineToWrite>& polylines, vtkPolyData* lines);

/// A cut's chosen isoline components as polylines (closed ones closed) with the cell arrays
/// IsoValue, Score, Length and Closed.
void WriteCutLines(const CutResult& cut, vtkPolyData* lines);

/// A solved field on the output: the point array `name`, the point array `name`Clamped (the
/// field clamped to the range of its constraint values, kerf::clampToConstraintRange: what a
/// colour map shows readably) and the field data RelativeResidual and SolverWork. Sets no active
/// scalars: the caller says what ParaView colours by.
void WriteField(const SurfaceInput& surface, const HarmonicFieldSolution& solution,
  const FieldConstraints& constraints, const char* name, vtkPolyData* output);

/// The name of the clamped copy WriteField writes beside the field `name`.
std::string ClampedFieldName(const char* name);

/// "factorization", "update" or "back-substitution".
std::string SolverWorkName(HarmonicFieldSolution::Work work);

/// Input port information of a filter with a surface on port 0 and optional points (any
/// vtkPointSet) on port 1.
int FillSurfaceAndOptionalPointsPorts(int port, vtkInformation* info);

} // namespace kerf
