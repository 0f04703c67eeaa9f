// vtkIsolineScoring: keeps the surface between runs, extracts, scores and labels the cut.
#include "vtkIsolineScoring.h"

#include "Harmonic/FieldGradient.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/Isolines.h"
#include "KerfSurfaceInput.h"
#include "Mesh/MeshValidation.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTable.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkIsolineScoring);

struct vtkIsolineScoring::Internals
{
  kerf::SurfaceInput surface;
};

vtkIsolineScoring::vtkIsolineScoring()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(3);
  this->SetSegmentArrayName("Segment");
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "HarmonicField");
}

vtkIsolineScoring::~vtkIsolineScoring()
{
  this->SetSegmentArrayName(nullptr);
}

vtkPolyData* vtkIsolineScoring::GetLabelledSurface()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

vtkTable* vtkIsolineScoring::GetCandidates()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(2));
}

int vtkIsolineScoring::FillInputPortInformation(int port, vtkInformation* info)
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

int vtkIsolineScoring::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 2 ? "vtkTable" : "vtkPolyData");
  return 1;
}

int vtkIsolineScoring::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPointSet* stroke = vtkPointSet::GetData(inputVector[1], 0);
  vtkPolyData* lines = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* labelled = vtkPolyData::GetData(outputVector, 1);
  vtkTable* candidates = vtkTable::GetData(outputVector, 2);
  Internals& state = *this->State;

  if (!this->SegmentArrayName || !*this->SegmentArrayName)
  {
    vtkErrorMacro("The segment array needs a non-empty name.");
    return 0;
  }
  kerf::MeshRequirements requirements;
  bool reused = false;
  std::string error;
  if (!state.surface.LoadIfChanged(input, requirements, error, reused))
  {
    vtkErrorMacro("Cannot extract isolines: " << error);
    return 0;
  }
  const kerf::TriangleMesh& mesh = state.surface.Mesh();

  vtkDataArray* array = this->GetInputArrayToProcess(0, inputVector);
  if (!array || array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkErrorMacro("The field must be a one-component point array of the surface (select it with "
                  "SetInputArrayToProcess; default \"HarmonicField\").");
    return 0;
  }
  std::vector<double> field(static_cast<std::size_t>(mesh.vertexCount()));
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    field[v] = array->GetComponent(v, 0);
    if (mesh.vertexFaces(v).empty())
    {
      continue;
    }
    if (!std::isfinite(field[v]))
    {
      vtkErrorMacro("The field has a NaN or infinite value at point " << v << ".");
      return 0;
    }
    lowest = std::min(lowest, field[v]);
    highest = std::max(highest, field[v]);
  }
  if (!std::isfinite(highest - lowest))
  {
    vtkErrorMacro("The field's range [" << lowest << ", " << highest
                                        << "] overflows double precision; rescale the field.");
    return 0;
  }
  if (this->Mode != BEST_SCORE && !std::isfinite(this->IsoValue))
  {
    vtkErrorMacro("IsoValue must be finite.");
    return 0;
  }
  if (this->Mode == NEAR_STROKE && (!stroke || stroke->GetNumberOfPoints() == 0))
  {
    vtkErrorMacro("NEAR_STROKE needs a stroke on input 1.");
    return 0;
  }
  if (this->Mode == NEAR_STROKE)
  {
    for (vtkIdType i = 0; i < stroke->GetNumberOfPoints(); ++i)
    {
      kerf::Vector3 p;
      stroke->GetPoint(i, p.data());
      if (!p.allFinite() || p.cwiseAbs().maxCoeff() > kerf::CoordinateLimit)
      {
        vtkErrorMacro("Stroke point " << i << " has a NaN, infinite or huge coordinate.");
        return 0;
      }
    }
  }

  // Gradient magnitudes: every face's to score candidates, else only those the cut crosses.
  std::vector<double> magnitudes(static_cast<std::size_t>(mesh.faceCount()), 0.0);
  if (this->Mode == BEST_SCORE)
  {
    for (int f = 0; f < mesh.faceCount(); ++f)
    {
      magnitudes[f] = kerf::faceGradient(mesh, field, f).norm();
    }
  }

  double value = this->IsoValue;
  if (this->Mode == BEST_SCORE)
  {
    const std::vector<kerf::IsovalueScore> scores =
      kerf::scoreIsovalues(mesh, field, magnitudes, this->NumberOfCandidates);
    if (scores.empty())
    {
      vtkErrorMacro("The field is constant: there is no isoline to score.");
      return 0;
    }
    vtkNew<vtkDoubleArray> values, scoreColumn, lengths;
    values->SetName("IsoValue");
    scoreColumn->SetName("Score");
    lengths->SetName("Length");
    std::size_t best = 0;
    for (std::size_t i = 0; i < scores.size(); ++i)
    {
      values->InsertNextValue(scores[i].value);
      scoreColumn->InsertNextValue(scores[i].score);
      lengths->InsertNextValue(scores[i].length);
      best = scores[i].score > scores[best].score ? i : best;
    }
    candidates->AddColumn(values);
    candidates->AddColumn(scoreColumn);
    candidates->AddColumn(lengths);
    value = scores[best].value;
  }
  this->UpdateProgress(0.4);

  std::vector<kerf::Isoline> isolines = kerf::extractIsolines(mesh, field, value);
  if (this->Mode == NEAR_STROKE && !isolines.empty())
  {
    std::vector<kerf::Vector3> points(static_cast<std::size_t>(stroke->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < stroke->GetNumberOfPoints(); ++i)
    {
      stroke->GetPoint(i, points[static_cast<std::size_t>(i)].data());
    }
    const int nearest = kerf::nearestIsoline(isolines, points);
    isolines = { isolines[static_cast<std::size_t>(nearest)] };
  }
  std::vector<const kerf::Isoline*> cut;
  for (const kerf::Isoline& line : isolines)
  {
    cut.push_back(&line);
    if (this->Mode != BEST_SCORE)
    {
      for (int f : line.faces)
      {
        magnitudes[f] = kerf::faceGradient(mesh, field, f).norm();
      }
    }
  }
  const std::vector<int> labels = kerf::labelCutSides(mesh, field, value, cut);
  this->UpdateProgress(0.8);

  // Output 0: the polylines.
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polylines;
  vtkNew<vtkDoubleArray> isoValues, scoreValues, lengthValues;
  vtkNew<vtkUnsignedCharArray> closedValues;
  isoValues->SetName("IsoValue");
  scoreValues->SetName("Score");
  lengthValues->SetName("Length");
  closedValues->SetName("Closed");
  for (const kerf::Isoline& line : isolines)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    const vtkIdType count = static_cast<vtkIdType>(line.points.size());
    for (const kerf::Vector3& p : line.points)
    {
      points->InsertNextPoint(p.data());
    }
    polylines->InsertNextCell(count + (line.closed ? 1 : 0));
    for (vtkIdType k = 0; k < count; ++k)
    {
      polylines->InsertCellPoint(first + k);
    }
    if (line.closed)
    {
      polylines->InsertCellPoint(first);
    }
    isoValues->InsertNextValue(value);
    scoreValues->InsertNextValue(kerf::isolineScore({ line }, magnitudes));
    lengthValues->InsertNextValue(line.length);
    closedValues->InsertNextValue(line.closed ? 1 : 0);
  }
  lines->SetPoints(points);
  lines->SetLines(polylines);
  lines->GetCellData()->AddArray(isoValues);
  lines->GetCellData()->AddArray(scoreValues);
  lines->GetCellData()->AddArray(lengthValues);
  lines->GetCellData()->AddArray(closedValues);

  // Output 1: the labelled surface.
  state.surface.MakeOutput(input, labelled);
  vtkNew<vtkIntArray> segments;
  segments->SetName(this->SegmentArrayName);
  segments->SetNumberOfValues(static_cast<vtkIdType>(labels.size()));
  for (std::size_t f = 0; f < labels.size(); ++f)
  {
    segments->SetValue(static_cast<vtkIdType>(f), labels[f]);
  }
  labelled->GetCellData()->AddArray(segments);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkIsolineScoring::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "NumberOfCandidates: " << this->NumberOfCandidates << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
