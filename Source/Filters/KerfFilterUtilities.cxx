// The shared parts of Kerf's filters: the exception border, input arrays and points, output helpers.
#include "KerfFilterUtilities.h"

#include "KerfDrawnInput.h"

#include "Error.h"
#include "Geodesic/SurfaceLocation.h"
#include "Geometry/ClosestPoint.h"
#include "Mesh/MeshValidation.h"
#include "vtkDiscClickAlgorithm.h"
#include "vtkStrokeConstraintAlgorithm.h"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <new>

namespace kerf
{

namespace
{
// The values of a one-component array with `expected` tuples; throws naming it otherwise.
std::vector<double> checkedValues(vtkDataArray* array, const std::string& name, vtkIdType expected, const char* kind)
{
  if (array->GetNumberOfComponents() != 1)
  {
    throw Error(name + " has " + std::to_string(array->GetNumberOfComponents()) + " components; one is needed");
  }
  if (array->GetNumberOfTuples() != expected)
  {
    throw Error(name + " has " + std::to_string(array->GetNumberOfTuples()) + " values for " +
      std::to_string(expected) + " " + kind + "s");
  }
  std::vector<double> values;
  CopyToDoubles(array, 1, values);
  return values;
}

std::string sentence(std::string message)
{
  if (!message.empty() && message.back() != '.')
  {
    message += '.';
  }
  return message;
}
} // namespace

namespace
{
// Runs `body`; false, with the message of whatever it threw, if it threw.
bool runCatching(const std::function<void()>& body, std::string& message)
{
  try
  {
    body();
    return true;
  }
  catch (const std::bad_alloc&)
  {
    message = "out of memory";
  }
  catch (const std::exception& e)
  {
    message = e.what();
  }
  catch (...)
  {
    message = "an unknown failure";
  }
  return false;
}
} // namespace

int RunGuarded(vtkAlgorithm* algorithm, const char* what, const std::function<void()>& body)
{
  std::string message;
  if (runCatching(body, message))
  {
    algorithm->UpdateProgress(1.0);
    return 1;
  }
  vtkErrorWithObjectMacro(algorithm, << what << ": " << sentence(message));
  return 0;
}

void GuardSetter(vtkAlgorithm* algorithm, const char* what, const std::function<void()>& setter)
{
  std::string message;
  if (!runCatching(setter, message))
  {
    vtkErrorWithObjectMacro(algorithm, << what << ": " << sentence(message) << " Nothing was changed.");
  }
}

void LoadSurface(SurfaceInput& surface, vtkPolyData* input, const MeshRequirements& requirements)
{
  std::string error;
  if (!surface.Load(input, requirements, error))
  {
    throw Error(error);
  }
}

void CheckOutputNames(std::initializer_list<const char*> names)
{
  for (const char* name : names)
  {
    if (!name || !*name)
    {
      throw Error("every output array needs a non-empty name");
    }
  }
}

void CheckDifferentNames(const char* a, const char* b, const std::string& what)
{
  if (a && b && std::strcmp(a, b) == 0)
  {
    throw Error(what + " need different names (both are arrays of the same kind)");
  }
}

double Finite(double value, const char* parameter)
{
  if (std::isnan(value))
  {
    throw Error(std::string(parameter) + " must be a number, not NaN");
  }
  return value;
}

double StrokeIsoValue(double value)
{
  if (!std::isfinite(value) || !(value + 1.0 > value) || !(value - 1.0 < value))
  {
    throw Error("IsoValue " + std::to_string(value) + " must be finite, and small enough that IsoValue +- 1 differ from it");
  }
  return value;
}

SoftConstraintFormulation FilterFormulation(int property, const HarmonicCutSession& session)
{
  switch (property)
  {
    case 0:
      return SoftConstraintFormulation::PointValues;
    case 1:
      return SoftConstraintFormulation::LeastSquares;
    default:
      return session.automaticFormulation();
  }
}

double RelativeDistance(double fraction, double diagonal, const char* parameter)
{
  if (!std::isfinite(fraction))
  {
    throw Error(std::string(parameter) + " must be a number (0 for no limit)");
  }
  return fraction > 0.0 ? fraction * diagonal : 0.0;
}

StrokeOptions ReadStrokeOptions(vtkStrokeConstraintAlgorithm* algorithm, double diagonal)
{
  StrokeOptions options;
  options.samplesPerSegment = algorithm->GetSamplesPerSegment();
  options.offset = Finite(algorithm->GetOffset(), "Offset") * diagonal;
  options.offsetLengthFraction = Finite(algorithm->GetOffsetLengthFraction(), "OffsetLengthFraction");
  options.isoValue = algorithm->GetIsoValue();
  options.maximumDistance = RelativeDistance(algorithm->GetMaximumProjectionDistance(), diagonal, "MaximumProjectionDistance");
  return options;
}

double ProjectionLimit(double fraction, const Surface& surface, const char* parameter)
{
  const double limit = RelativeDistance(fraction, surface.mesh().boundingBoxDiagonal(), parameter);
  return limit > 0.0 ? limit : std::numeric_limits<double>::infinity();
}

DiscClicks ReadDiscClicks(
  const Surface& surface, vtkDiscClickAlgorithm* algorithm, const DrawnDiscList& drawn, vtkPointSet* input)
{
  const double diagonal = surface.mesh().boundingBoxDiagonal();
  const double absoluteRadius = algorithm->GetAbsoluteRadius();
  const double radius = Finite(absoluteRadius, "AbsoluteRadius") > 0.0
    ? absoluteRadius
    : RelativeDistance(algorithm->GetRadius(), diagonal, "Radius");
  DiscClicks clicks;
  const double maximumProjection = algorithm->GetMaximumProjectionDistance();
  clicks.tolerance = Finite(maximumProjection, "MaximumProjectionDistance") > 0.0
    ? maximumProjection
    : std::numeric_limits<double>::infinity();
  if (!input && drawn.Count() > 0)
  {
    const std::vector<DrawnDisc> discs = drawn.Discs();
    for (std::size_t i = 0; i < discs.size(); ++i)
    {
      const SurfacePoint click = PanelPointOnSurface(surface, discs[i].centre, "drawn disc " + std::to_string(i));
      (discs[i].subtract ? clicks.subtracted : clicks.added).push_back({ surfacePosition(surface.mesh(), click), discs[i].radius });
    }
    if (clicks.added.empty())
    {
      throw Error("every drawn disc subtracts: draw one that adds (hold Ctrl without Shift and drag outward from a click)");
    }
    return clicks;
  }
  if (!input)
  {
    const double* p = algorithm->GetClickPoint();
    const SurfacePoint click = PanelPointOnSurface(surface, Vector3(p[0], p[1], p[2]), "the click point");
    clicks.added.push_back({ surfacePosition(surface.mesh(), click), radius });
    return clicks;
  }
  const std::vector<Vector3> points = ReadPoints(input);
  // Optional per-click arrays: read when the input has them.
  const auto optional = [&](const char* name) {
    return name && *name && input->GetPointData()->GetAbstractArray(name)
      ? ReadNamedPointArray(input, name, "the clicks")
      : std::vector<double>();
  };
  const std::vector<double> radii = optional(algorithm->GetClickRadiusArrayName());
  const std::vector<double> subtract = optional(algorithm->GetClickSubtractArrayName());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (!radii.empty() && !(std::isfinite(radii[i]) && radii[i] > 0.0))
    {
      throw Error("click " + std::to_string(i) + " has the radius " + std::to_string(radii[i]) +
        "; radii are positive fractions of the diagonal");
    }
    const double r = radii.empty() ? radius : radii[i] * diagonal;
    (!subtract.empty() && subtract[i] != 0.0 ? clicks.subtracted : clicks.added).push_back({ points[i], r });
  }
  if (clicks.added.empty() && !clicks.subtracted.empty())
  {
    throw Error("every click subtracts its disc: at least one click must add one");
  }
  if (clicks.added.empty())
  {
    throw Error("the click input holds no point");
  }
  return clicks;
}

SurfacePoint PanelPointOnSurface(const Surface& surface, const Vector3& point, const std::string& what)
{
  return projectOntoSurface(surface, point, std::numeric_limits<double>::infinity(), what);
}

std::vector<SurfacePoint> ProjectPointsOntoSurface(
  const Surface& surface, vtkPointSet* points, double maximumDistance, const std::string& noun)
{
  const std::vector<Vector3> positions = ReadPoints(points);
  std::vector<SurfacePoint> projected;
  projected.reserve(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    projected.push_back(projectOntoSurface(surface, positions[i], maximumDistance, noun + " " + std::to_string(i)));
  }
  return projected;
}

std::vector<double> ReadInputArray(vtkAlgorithm* algorithm, int index,
  vtkIdType expected, const std::string& owner)
{
  vtkInformation* selection = algorithm->GetInputArrayInformation(index);
  const char* requested = selection && selection->Has(vtkDataObject::FIELD_NAME())
    ? selection->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  const int association = selection && selection->Has(vtkDataObject::FIELD_ASSOCIATION())
    ? selection->Get(vtkDataObject::FIELD_ASSOCIATION())
    : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  const char* kind = association == vtkDataObject::FIELD_ASSOCIATION_CELLS ? "cell" : "point";
  const std::string where = " (input array " + std::to_string(index) + ")";
  vtkDataArray* array = nullptr;
  const int port = selection && selection->Has(vtkAlgorithm::INPUT_PORT()) ? selection->Get(vtkAlgorithm::INPUT_PORT()) : 0;
  const int connection =
    selection && selection->Has(vtkAlgorithm::INPUT_CONNECTION()) ? selection->Get(vtkAlgorithm::INPUT_CONNECTION()) : 0;
  if (auto* data = vtkDataSet::SafeDownCast(algorithm->GetInputDataObject(port, connection)))
  {
    vtkDataSetAttributes* attributes = association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? static_cast<vtkDataSetAttributes*>(data->GetCellData())
      : static_cast<vtkDataSetAttributes*>(data->GetPointData());
    // No name selected: the active scalars, as VTK's own filters do.
    array = requested && *requested ? attributes->GetArray(requested) : attributes->GetScalars();
  }
  if (!array)
  {
    if (!requested || !*requested)
    {
      throw Error("no array is selected for " + owner + " and it has no active " + kind + " scalars" + where);
    }
    throw Error(owner + " has no one-component " + kind + " array named '" + requested + "'" + where);
  }
  return checkedValues(array,
    "the " + std::string(kind) + " array '" + (array->GetName() ? array->GetName() : "") + "' of " + owner + where,
    expected, kind);
}

std::vector<int> ReadTriangleLabels(vtkAlgorithm* algorithm, int index,
  const SurfaceInput& surface, vtkIdType cells, const std::string& owner)
{
  const std::vector<double> perCell = ReadInputArray(algorithm, index, cells, owner);
  std::vector<int> labels(perCell.size());
  for (std::size_t c = 0; c < perCell.size(); ++c)
  {
    const double value = perCell[c];
    if (!std::isfinite(value) || value != std::floor(value) || value < -1.0 ||
      value > std::numeric_limits<int>::max())
    {
      throw Error("cell " + std::to_string(c) + " of " + owner + " holds " + std::to_string(value) +
        ", which is not a label (an integer >= -1)");
    }
    labels[c] = static_cast<int>(value);
  }
  return surface.CellValuesToTriangles(labels);
}

InputLabels LoadLabelledSurface(
  vtkAlgorithm* algorithm, SurfaceInput& surface, vtkPolyData* input, const MeshRequirements& requirements)
{
  LoadSurface(surface, input, requirements);
  InputLabels read;
  read.labels = ReadTriangleLabels(algorithm, 0, surface, input->GetNumberOfCells(), "the surface's labels");
  // The array ReadInputArray read: the selected name, else the active cell scalars.
  vtkInformation* selection = algorithm->GetInputArrayInformation(0);
  const char* requested =
    selection && selection->Has(vtkDataObject::FIELD_NAME()) ? selection->Get(vtkDataObject::FIELD_NAME()) : nullptr;
  vtkDataArray* scalars = input->GetCellData()->GetScalars();
  read.arrayName = requested && *requested ? requested : (scalars && scalars->GetName() ? scalars->GetName() : "Segment");
  return read;
}

void WriteRelabelledSurface(
  const SurfaceInput& surface, vtkPolyData* input, vtkPolyData* output, const InputLabels& read, const std::vector<int>& labels)
{
  surface.MakeOutput(input, output);
  output->GetCellData()->RemoveArray(read.arrayName.c_str());
  output->GetCellData()->AddArray(MakeIntArray(read.arrayName.c_str(), labels));
  output->GetCellData()->SetActiveScalars(read.arrayName.c_str());
}

std::vector<double> ReadNamedPointArray(vtkPointSet* points, const char* name, const std::string& owner)
{
  vtkDataArray* array = name && *name ? points->GetPointData()->GetArray(name) : nullptr;
  if (!array)
  {
    throw Error(owner + " have no one-component point array named '" + (name ? name : "") + "'");
  }
  return checkedValues(array, "the point array '" + std::string(name) + "' of " + owner, points->GetNumberOfPoints(), "point");
}

std::vector<double> ReadNamedCellArray(vtkPolyData* cells, const char* name, const std::string& owner)
{
  vtkDataArray* array = name && *name ? cells->GetCellData()->GetArray(name) : nullptr;
  if (!array)
  {
    throw Error(owner + " have no one-component cell array named '" + (name ? name : "") + "'");
  }
  return checkedValues(array, "the cell array '" + std::string(name) + "' of " + owner, cells->GetNumberOfCells(), "cell");
}

namespace
{
void checkStrokePointCount(long long count)
{
  if (count > StrokePointList::MaximumCount)
  {
    throw Error("a panel holds at most " + std::to_string(StrokePointList::MaximumCount) + " points, not " +
      std::to_string(count));
  }
}
} // namespace

bool StrokePointList::SetCount(int count)
{
  checkStrokePointCount(count);
  if (count < 0 || static_cast<std::size_t>(count) == this->List.size())
  {
    return false;
  }
  this->List.resize(static_cast<std::size_t>(count), Vector3::Zero());
  return true;
}

bool StrokePointList::Set(int index, const Vector3& point)
{
  if (index < 0)
  {
    return false;
  }
  checkStrokePointCount(static_cast<long long>(index) + 1);
  if (static_cast<std::size_t>(index) >= this->List.size())
  {
    this->List.resize(static_cast<std::size_t>(index) + 1, Vector3::Zero());
  }
  if (this->List[static_cast<std::size_t>(index)] == point)
  {
    return false;
  }
  this->List[static_cast<std::size_t>(index)] = point;
  return true;
}

void SetPanelPointCount(vtkAlgorithm* algorithm, StrokePointList& list, int count, const std::string& noun)
{
  GuardSetter(algorithm, ("Cannot set the number of " + noun + " points").c_str(), [&]() {
    if (list.SetCount(count))
    {
      algorithm->Modified();
    }
  });
}

void SetPanelPoint(
  vtkAlgorithm* algorithm, StrokePointList& list, int index, const Vector3& point, const std::string& noun)
{
  GuardSetter(algorithm, ("Cannot set a " + noun + " point").c_str(), [&]() {
    if (list.Set(index, point))
    {
      algorithm->Modified();
    }
  });
}

std::vector<Vector3> PanelPointsOnSurface(const StrokePointList& panel, const Surface& surface, const std::string& noun)
{
  std::vector<Vector3> positions;
  for (const Vector3& point : panel.Points())
  {
    const SurfacePoint placed =
      PanelPointOnSurface(surface, point, noun + " point " + std::to_string(positions.size()));
    positions.push_back(surfacePosition(surface.mesh(), placed));
  }
  return positions;
}

std::vector<Vector3> ReadPoints(vtkPointSet* points)
{
  std::vector<Vector3> coordinates(static_cast<std::size_t>(points ? points->GetNumberOfPoints() : 0));
  for (std::size_t i = 0; i < coordinates.size(); ++i)
  {
    points->GetPoint(static_cast<vtkIdType>(i), coordinates[i].data());
  }
  return coordinates;
}

namespace
{
// The points of each cell of one of a poly data's cell arrays (`kind` names its cells in errors).
std::vector<std::vector<Vector3>> ReadCellPoints(
  vtkPolyData* lines, vtkCellArray* array, const std::string& owner, const std::string& kind)
{
  std::vector<std::vector<Vector3>> polylines;
  if (!array)
  {
    return polylines;
  }
  auto cells = vtk::TakeSmartPointer(array->NewIterator());
  const vtkIdType pointCount = lines->GetNumberOfPoints();
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    std::vector<Vector3> polyline(static_cast<std::size_t>(size));
    for (vtkIdType k = 0; k < size; ++k)
    {
      if (ids[k] < 0 || ids[k] >= pointCount)
      {
        throw Error(kind + " " + std::to_string(cells->GetCurrentCellId()) + " of " + owner + " uses point " +
          std::to_string(ids[k]) + ", but " + owner + " has " + std::to_string(pointCount) + " points");
      }
      lines->GetPoint(ids[k], polyline[static_cast<std::size_t>(k)].data());
    }
    polylines.push_back(std::move(polyline));
  }
  return polylines;
}
} // namespace

std::vector<std::vector<Vector3>> ReadPolylines(vtkPolyData* lines, const std::string& owner)
{
  return lines ? ReadCellPoints(lines, lines->GetLines(), owner, "line") : std::vector<std::vector<Vector3>>();
}

std::vector<std::vector<Vector3>> ReadVertexCells(vtkPolyData* vertices, const std::string& owner)
{
  return vertices ? ReadCellPoints(vertices, vertices->GetVerts(), owner, "vertex cell")
                  : std::vector<std::vector<Vector3>>();
}

std::vector<SurfaceCurve> PlaceLinesOnSurface(
  const Surface& surface, vtkPolyData* lines, double maximumDistance, const std::string& owner)
{
  std::vector<SurfaceCurve> curves;
  std::vector<std::vector<Vector3>> polylines = ReadPolylines(lines, owner);
  for (std::size_t i = 0; i < polylines.size(); ++i)
  {
    std::vector<Vector3>& points = polylines[i];
    const bool closed = points.size() > 2 && points.front() == points.back();
    if (closed)
    {
      points.pop_back();
    }
    curves.push_back(
      placeCurveOnSurface(surface, points, closed, maximumDistance, owner + " line " + std::to_string(i)));
  }
  if (curves.empty())
  {
    throw Error(owner + " holds no line");
  }
  return curves;
}

void CheckFinite(std::initializer_list<const std::vector<double>*> vectors, double scalar, const std::string& message)
{
  bool finite = std::isfinite(scalar);
  for (const std::vector<double>* values : vectors)
  {
    for (double v : *values)
    {
      finite = finite && std::isfinite(v);
    }
  }
  if (!finite)
  {
    throw Error(message);
  }
}

void SegmentSurface(vtkAlgorithm* algorithm, SurfaceInput& surface, vtkPolyData* input, vtkPolyData* output,
  const char* arrayName, const MeshRequirements& requirements,
  const std::function<std::vector<int>(const Surface&, vtkFieldData*)>& segment)
{
  CheckOutputNames({ arrayName });
  LoadSurface(surface, input, requirements);
  algorithm->UpdateProgress(0.1);
  // The figures are kept aside so that a failed segmentation leaves the output empty.
  vtkNew<vtkFieldData> figures;
  const std::vector<int> labels = segment(surface.GetSurface(), figures);
  algorithm->UpdateProgress(0.9);
  surface.MakeOutput(input, output);
  for (int a = 0; a < figures->GetNumberOfArrays(); ++a)
  {
    output->GetFieldData()->AddArray(figures->GetAbstractArray(a));
  }
  std::vector<int> perCell(static_cast<std::size_t>(output->GetNumberOfCells()), -1);
  const std::vector<vtkIdType>& source = surface.SourceCells();
  for (std::size_t t = 0; t < labels.size(); ++t)
  {
    perCell[surface.Rebuilt() ? t : static_cast<std::size_t>(source[t])] = labels[t];
  }
  output->GetCellData()->AddArray(MakeIntArray(arrayName, perCell));
  const int count = labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end()) + 1;
  output->GetFieldData()->AddArray(MakeFieldValue("SegmentCount", count));
}

vtkSmartPointer<vtkAbstractArray> MakeFieldValue(const char* name, double value)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  return array;
}

vtkSmartPointer<vtkAbstractArray> MakeFieldValue(const char* name, const std::string& value)
{
  auto array = vtkSmartPointer<vtkStringArray>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  return array;
}

void WriteSegmentSizes(const std::vector<int>& labels, vtkPolyData* output)
{
  // Labels may be any numbers (a user's stroke labels): counted by label, not by index.
  std::map<int, int> counts;
  for (int label : labels)
  {
    if (label >= 0)
    {
      ++counts[label];
    }
  }
  std::vector<int> sizes;
  for (const auto& [label, count] : counts)
  {
    sizes.push_back(count);
  }
  output->GetFieldData()->AddArray(MakeIntArray("SegmentSizes", sizes));
}

vtkSmartPointer<vtkAbstractArray> MakeIntArray(const char* name, const std::vector<int>& values)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  if (!values.empty())
  {
    std::memcpy(array->GetPointer(0), values.data(), values.size() * sizeof(int));
  }
  return array;
}

void WritePolylines(const std::vector<PolylineToWrite>& polylines, vtkPolyData* lines)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  std::vector<double> lengths;
  std::vector<unsigned char> closed;
  for (const PolylineToWrite& line : polylines)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    const vtkIdType count = static_cast<vtkIdType>(line.points->size());
    for (const Vector3& p : *line.points)
    {
      points->InsertNextPoint(p.data());
    }
    cells->InsertNextCell(count + (line.closed ? 1 : 0));
    for (vtkIdType k = 0; k < count; ++k)
    {
      cells->InsertCellPoint(first + k);
    }
    if (line.closed)
    {
      cells->InsertCellPoint(first);
    }
    lengths.push_back(line.length);
    closed.push_back(line.closed ? 1 : 0);
  }
  lines->SetPoints(points);
  lines->SetLines(cells);
  lines->GetCellData()->AddArray(MakeArray("Length", lengths));
  lines->GetCellData()->AddArray(MakeArray("Closed", closed));
}

void WriteCutLines(const CutResult& cut, vtkPolyData* lines)
{
  std::vector<PolylineToWrite> polylines;
  for (const Isoline& line : cut.isolines)
  {
    polylines.push_back({ &line.points, line.closed, line.length });
  }
  WritePolylines(polylines, lines);
  lines->GetCellData()->AddArray(MakeArray("IsoValue", std::vector<double>(cut.isolines.size(), cut.value)));
  lines->GetCellData()->AddArray(MakeArray("Score", cut.scores));
}

std::string ClampedFieldName(const char* name)
{
  return std::string(name) + "Clamped";
}

void WriteField(const SurfaceInput& surface, const HarmonicFieldSolution& solution,
  const FieldConstraints& constraints, const char* name, vtkPolyData* output)
{
  output->GetPointData()->AddArray(MakeArray(name, surface.ToInputPoints(solution.field)));
  output->GetPointData()->AddArray(MakeArray(ClampedFieldName(name).c_str(),
    surface.ToInputPoints(clampToConstraintRange(solution.field, constraints))));
  output->GetFieldData()->AddArray(MakeFieldValue("RelativeResidual", solution.relativeResidual));
  output->GetFieldData()->AddArray(MakeFieldValue("SolverWork", SolverWorkName(solution.work)));
}

std::string SolverWorkName(HarmonicFieldSolution::Work work)
{
  switch (work)
  {
    case HarmonicFieldSolution::Work::Factorization:
      return "factorization";
    case HarmonicFieldSolution::Work::Update:
      return "update";
    default:
      return "back-substitution";
  }
}

int FillSurfaceAndOptionalPointsPorts(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

} // namespace kerf
