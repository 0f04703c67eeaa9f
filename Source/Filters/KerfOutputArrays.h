// What filters write to their outputs: field values, label arrays and segment sizes, polylines and cut lines, solved
// fields, relabelled surfaces.
#pragma once

#include "Harmonic/HarmonicCutSession.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "KerfInputArrays.h"
#include "KerfSurfaceInput.h"
#include "Mesh/TriangleMesh.h"

#include <vtkSmartPointer.h>

#include <functional>
#include <string>
#include <vector>

class vtkAbstractArray;
class vtkAlgorithm;
class vtkFieldData;
class vtkPolyData;

namespace kerf
{

/// The output of such a filter: the surface (SurfaceInput::MakeOutput) with its labels replaced by
/// `labels` under the input array's name, the active cell scalars.
void WriteRelabelledSurface(const SurfaceInput& surface, vtkPolyData* input, vtkPolyData* output,
  const InputLabels& read, const std::vector<int>& labels);

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

/// One int per triangle of `surface` as the int cell array `name` of `output` (made by
/// surface.MakeOutput): each value on the output cell its triangle came from; other cells get -1.
void WriteTriangleArray(
  const SurfaceInput& surface, vtkPolyData* output, const char* name, const std::vector<int>& values);

/// The body of an automatic-segmentation filter: checks `arrayName`, loads `input` into `surface`
/// (validated against `requirements`), copies it to `output` with its arrays, runs `segment` (which
/// returns one label per triangle and may add its figures to the output's field data) and writes
/// the labels as the int cell array `arrayName` (the active cell scalars) and their count as the
/// field value SegmentCount.
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
void WriteField(const SurfaceInput& surface, const HarmonicFieldSolution& solution, const FieldConstraints& constraints,
  const char* name, vtkPolyData* output);

/// The name of the clamped copy WriteField writes beside the field `name`.
std::string ClampedFieldName(const char* name);

/// "factorization", "update" or "back-substitution".
std::string SolverWorkName(HarmonicFieldSolution::Work work);

} // namespace kerf
