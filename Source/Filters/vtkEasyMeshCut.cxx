// vtkEasyMeshCut: labelled strokes of input 1 grown over the surface under the isophotic metric, boundaries refined as
// snakes (kerf::easyMeshCut).
#include "vtkEasyMeshCut.h"

#include "Error.h"
#include "KerfDrawnInput.h"
#include "KerfEasyMeshCutting.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfPanelPoints.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/EasyMeshCut.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
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

vtkEasyMeshCut::vtkEasyMeshCut()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(3); // input 2: override strokes
}

vtkEasyMeshCut::~vtkEasyMeshCut() = default;

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

int vtkEasyMeshCut::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot cut the mesh from the strokes", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->SegmentArrayName });
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    const kerf::SurfaceInput& surface = this->State->surface;
    vtkPolyData* overrideInput = vtkPolyData::GetData(inputVector[2], 0);
    const kerf::PanelLabelledStrokes strokes =
      kerf::ReadGrowingStrokes(vtkPolyData::GetData(inputVector[1], 0), this->StrokeLabelArrayName, *this->DrawnStrokes,
        { { 1, &this->State->foreground }, { 0, &this->State->background } }, surface.GetSurface());

    kerf::EasyMeshCutOptions options;
    options.growing = kerf::ReadGrowingOptions(this, surface.Mesh().boundingBoxDiagonal());
    options.refine = this->Refine;
    options.snake = kerf::SnakeOptionsFrom(
      this->SnakeIterations, this->SnakeConvergence, this->SnakeCurvatureOffset, this->SnakeSlideSamples);
    options.overrides = overrideInput ? kerf::ReadPolylines(overrideInput, "the override strokes") : strokes.overrides;
    if (!options.overrides.empty())
    {
      options.overrideRadius =
        kerf::Finite(this->OverrideRadius, "OverrideRadius") * surface.Mesh().boundingBoxDiagonal();
    }
    this->UpdateProgress(0.1);
    const kerf::EasyMeshCutResult result = kerf::easyMeshCut(surface.SharedSurface(), strokes.strokes, options);
    this->UpdateProgress(0.9);

    surface.MakeOutput(input, output);
    output->GetCellData()->AddArray(kerf::MakeIntArray(this->SegmentArrayName, result.faceLabels));
    kerf::WriteSegmentSizes(result.faceLabels, output);
    output->GetCellData()->SetActiveScalars(this->SegmentArrayName);
    output->GetPointData()->AddArray(kerf::MakeArray("IsophoticDistance", surface.ToInputPoints(result.distances)));
    if (!result.growing.probabilities.empty())
    {
      output->GetPointData()->AddArray(
        kerf::MakeArray("Probability", surface.ToInputPoints(result.growing.probabilities)));
    }
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("SnakeSweeps", static_cast<double>(result.snake.sweeps)));

    kerf::WriteLabelBoundaries(result.boundaries, vtkPolyData::GetData(outputVector, 1));
  });
}

void vtkEasyMeshCut::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Refine: " << this->Refine << "\n";
  this->PrintSnakeParameters(os, indent);
  os << indent << "ForegroundPoints: " << this->State->foreground.Count() << "\n";
  os << indent << "BackgroundPoints: " << this->State->background.Count() << "\n";
}
