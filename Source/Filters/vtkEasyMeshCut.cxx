// vtkEasyMeshCut: labelled strokes of input 1 grown over the surface under the isophotic metric, boundaries refined as snakes (kerf::easyMeshCut).
#include "vtkEasyMeshCut.h"

#include "Error.h"
#include "KerfFilterUtilities.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/EasyMeshCut.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <string>

vtkStandardNewMacro(vtkEasyMeshCut);

struct vtkEasyMeshCut::Internals
{
  kerf::SurfaceInput surface;
  kerf::StrokePointList foreground;
  kerf::StrokePointList background;
};

namespace
{
// The polylines of `input` with the labels of their cells (a line's cell id follows the verts).
std::vector<kerf::LabelledStroke> readLabelledStrokes(vtkPolyData* input, const char* labelArray)
{
  const std::vector<std::vector<kerf::Vector3>> lines = kerf::ReadPolylines(input, "the strokes");
  if (lines.empty())
  {
    throw kerf::Error("the strokes hold no line");
  }
  const std::vector<double> labels = kerf::ReadNamedCellArray(input, labelArray, "the strokes");
  const vtkIdType first = input->GetNumberOfVerts();
  std::vector<kerf::LabelledStroke> strokes;
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    const double label = labels[static_cast<std::size_t>(first) + i];
    if (!(label >= 0.0 && label <= 1e9 && label == std::floor(label)))
    {
      throw kerf::Error("stroke " + std::to_string(i) + " has the label " + std::to_string(label) +
        "; labels are non-negative integers (background 0, foreground 1)");
    }
    strokes.push_back({ static_cast<int>(label), lines[i] });
  }
  return strokes;
}
} // namespace

vtkEasyMeshCut::vtkEasyMeshCut()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(2);
  this->SetStrokeLabelArrayName("Label");
  this->SetSegmentArrayName("Segment");
}

vtkEasyMeshCut::~vtkEasyMeshCut()
{
  this->SetStrokeLabelArrayName(nullptr);
  this->SetSegmentArrayName(nullptr);
}

void vtkEasyMeshCut::SetNumberOfForegroundPoints(int count)
{
  kerf::SetPanelPointCount(this, this->State->foreground, count, "foreground");
}

int vtkEasyMeshCut::GetNumberOfForegroundPoints() const
{
  return this->State->foreground.Count();
}

void vtkEasyMeshCut::SetForegroundPoint(int index, double x, double y, double z)
{
  kerf::SetPanelPoint(this, this->State->foreground, index, kerf::Vector3(x, y, z), "foreground");
}

void vtkEasyMeshCut::SetNumberOfBackgroundPoints(int count)
{
  kerf::SetPanelPointCount(this, this->State->background, count, "background");
}

int vtkEasyMeshCut::GetNumberOfBackgroundPoints() const
{
  return this->State->background.Count();
}

void vtkEasyMeshCut::SetBackgroundPoint(int index, double x, double y, double z)
{
  kerf::SetPanelPoint(this, this->State->background, index, kerf::Vector3(x, y, z), "background");
}

vtkPolyData* vtkEasyMeshCut::GetBoundary()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkEasyMeshCut::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port >= 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1); // so that a missing stroke input is an error of ours
  }
  return 1;
}

int vtkEasyMeshCut::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot cut the mesh from the strokes", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->SegmentArrayName });
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    const kerf::SurfaceInput& surface = this->State->surface;
    std::vector<kerf::LabelledStroke> strokes;
    if (vtkPolyData* strokeInput = vtkPolyData::GetData(inputVector[1], 0))
    {
      strokes = readLabelledStrokes(strokeInput, this->StrokeLabelArrayName);
    }
    else if (this->State->foreground.Count() > 0 && this->State->background.Count() > 0)
    {
      strokes.push_back({ 1, kerf::PanelPointsOnSurface(this->State->foreground, surface.GetSurface(), "foreground") });
      strokes.push_back({ 0, kerf::PanelPointsOnSurface(this->State->background, surface.GetSurface(), "background") });
    }
    else
    {
      throw kerf::Error("there are no strokes: connect labelled polylines to input 1, or place foreground and "
                        "background points (in ParaView: point at the surface and press P, Ctrl+P to add more)");
    }

    kerf::EasyMeshCutOptions options;
    kerf::IsophoticMetricOptions& metric = options.growing.metric;
    metric.normalWeight = kerf::Finite(this->NormalWeight, "NormalWeight");
    metric.curvatureWeight = kerf::Finite(this->CurvatureWeight, "CurvatureWeight");
    metric.augmentation = static_cast<kerf::CurvatureAugmentation>(this->CurvatureAugmentation);
    metric.curvaturePerEdge = this->CurvaturePerEdge;
    options.growing.maximumDistance = kerf::RelativeDistance(
      this->MaximumProjectionDistance, surface.Mesh().boundingBoxDiagonal(), "MaximumProjectionDistance");
    options.refine = this->Refine;
    options.snake.iterations = this->SnakeIterations;
    options.snake.convergence = kerf::Finite(this->SnakeConvergence, "SnakeConvergence");
    options.snake.curvatureOffset = kerf::Finite(this->SnakeCurvatureOffset, "SnakeCurvatureOffset");
    options.snake.slideSamples = this->SnakeSlideSamples;
    if (vtkPolyData* overrides = vtkPolyData::GetData(inputVector[2], 0))
    {
      options.overrides = kerf::ReadPolylines(overrides, "the override strokes");
      options.overrideRadius = kerf::Finite(this->OverrideRadius, "OverrideRadius") * surface.Mesh().boundingBoxDiagonal();
    }
    this->UpdateProgress(0.1);
    const kerf::EasyMeshCutResult result = kerf::easyMeshCut(surface.SharedSurface(), strokes, options);
    this->UpdateProgress(0.9);

    surface.MakeOutput(input, output);
    output->GetCellData()->AddArray(kerf::MakeIntArray(this->SegmentArrayName, result.faceLabels));
    output->GetCellData()->SetActiveScalars(this->SegmentArrayName);
    output->GetPointData()->AddArray(kerf::MakeArray("IsophoticDistance", surface.ToInputPoints(result.distances)));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("SnakeSweeps", static_cast<double>(result.snake.sweeps)));

    std::vector<kerf::PolylineToWrite> polylines;
    std::vector<int> leftLabels, rightLabels;
    for (const kerf::EasyMeshCutBoundary& boundary : result.boundaries)
    {
      polylines.push_back({ &boundary.points, boundary.closed, boundary.length });
      leftLabels.push_back(boundary.leftLabel);
      rightLabels.push_back(boundary.rightLabel);
    }
    vtkPolyData* lines = vtkPolyData::GetData(outputVector, 1);
    kerf::WritePolylines(polylines, lines);
    lines->GetCellData()->AddArray(kerf::MakeIntArray("LeftLabel", leftLabels));
    lines->GetCellData()->AddArray(kerf::MakeIntArray("RightLabel", rightLabels));
  });
}

void vtkEasyMeshCut::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NormalWeight: " << this->NormalWeight << "\n";
  os << indent << "CurvatureWeight: " << this->CurvatureWeight << "\n";
  os << indent << "CurvatureAugmentation: " << this->CurvatureAugmentation << "\n";
  os << indent << "CurvaturePerEdge: " << this->CurvaturePerEdge << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "Refine: " << this->Refine << "\n";
  os << indent << "SnakeIterations: " << this->SnakeIterations << "\n";
  os << indent << "SnakeConvergence: " << this->SnakeConvergence << "\n";
  os << indent << "SnakeCurvatureOffset: " << this->SnakeCurvatureOffset << "\n";
  os << indent << "SnakeSlideSamples: " << this->SnakeSlideSamples << "\n";
  os << indent << "OverrideRadius: " << this->OverrideRadius << "\n";
  os << indent << "ForegroundPoints: " << this->State->foreground.Count() << "\n";
  os << indent << "BackgroundPoints: " << this->State->background.Count() << "\n";
  os << indent << "StrokeLabelArrayName: " << (this->StrokeLabelArrayName ? this->StrokeLabelArrayName : "(none)") << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
