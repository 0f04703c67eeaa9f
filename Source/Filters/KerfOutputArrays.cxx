// What filters write to their outputs: field values, label arrays and segment sizes, polylines and cut lines, solved
// fields, relabelled surfaces.
#include "KerfOutputArrays.h"

#include "KerfFilterBorder.h"
#include "KerfParameterChecks.h"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cstring>
#include <map>

namespace kerf
{

void WriteRelabelledSurface(const SurfaceInput& surface, vtkPolyData* input, vtkPolyData* output,
  const InputLabels& read, const std::vector<int>& labels)
{
  surface.MakeOutput(input, output);
  output->GetCellData()->RemoveArray(read.arrayName.c_str());
  output->GetCellData()->AddArray(MakeIntArray(read.arrayName.c_str(), labels));
  output->GetCellData()->SetActiveScalars(read.arrayName.c_str());
}

void WriteTriangleArray(
  const SurfaceInput& surface, vtkPolyData* output, const char* name, const std::vector<int>& values)
{
  std::vector<int> perCell(static_cast<std::size_t>(output->GetNumberOfCells()), -1);
  const std::vector<vtkIdType>& source = surface.SourceCells();
  for (std::size_t t = 0; t < values.size(); ++t)
  {
    perCell[surface.Rebuilt() ? t : static_cast<std::size_t>(source[t])] = values[t];
  }
  output->GetCellData()->AddArray(MakeIntArray(name, perCell));
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
  WriteTriangleArray(surface, output, arrayName, labels);
  // Active, so that ParaView colours the new output by its segments.
  output->GetCellData()->SetActiveScalars(arrayName);
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

void WriteField(const SurfaceInput& surface, const HarmonicFieldSolution& solution, const FieldConstraints& constraints,
  const char* name, vtkPolyData* output)
{
  output->GetPointData()->AddArray(MakeArray(name, surface.ToInputPoints(solution.field)));
  output->GetPointData()->AddArray(MakeArray(
    ClampedFieldName(name).c_str(), surface.ToInputPoints(clampToConstraintRange(solution.field, constraints))));
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

} // namespace kerf
