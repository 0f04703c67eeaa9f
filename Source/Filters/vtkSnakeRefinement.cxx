// vtkSnakeRefinement: the boundaries of a per-triangle labelling refined as snakes and edited by override strokes
// (kerf::refineBoundaries).
#include "vtkSnakeRefinement.h"

#include "Error.h"
#include "KerfDrawnInput.h"
#include "KerfEasyMeshCutting.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <string>

vtkStandardNewMacro(vtkSnakeRefinement);

struct vtkSnakeRefinement::Internals
{
  kerf::SurfaceInput surface;
};

vtkSnakeRefinement::vtkSnakeRefinement()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Segment");
}

vtkSnakeRefinement::~vtkSnakeRefinement() = default;

vtkPolyData* vtkSnakeRefinement::GetBoundary()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkSnakeRefinement::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkSnakeRefinement::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot refine the boundaries", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    const kerf::InputLabels read =
      kerf::LoadLabelledSurface(this, this->State->surface, input, kerf::MeshRequirements());
    const kerf::SurfaceInput& surface = this->State->surface;

    kerf::EasyMeshCutOptions options;
    options.refine = this->SnakeIterations > 0;
    options.snake = kerf::SnakeOptionsFrom(
      this->SnakeIterations, this->SnakeConvergence, this->SnakeCurvatureOffset, this->SnakeSlideSamples);
    options.growing.maximumDistance = kerf::RelativeDistance(
      this->MaximumProjectionDistance, surface.Mesh().boundingBoxDiagonal(), "MaximumProjectionDistance");
    if (vtkPolyData* overrides = vtkPolyData::GetData(inputVector[1], 0))
    {
      options.overrides = kerf::ReadPolylines(overrides, "the override strokes");
    }
    else
    {
      options.overrides = kerf::PanelOverrideStrokes(*this->DrawnStrokes, surface.GetSurface(), true);
    }
    if (!options.overrides.empty())
    {
      options.overrideRadius =
        kerf::Finite(this->OverrideRadius, "OverrideRadius") * surface.Mesh().boundingBoxDiagonal();
    }
    this->UpdateProgress(0.1);
    const kerf::EasyMeshCutResult result = kerf::refineBoundaries(surface.SharedSurface(), read.labels, options);
    this->UpdateProgress(0.9);

    kerf::WriteRelabelledSurface(surface, input, output, read, result.faceLabels);
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("SnakeSweeps", static_cast<double>(result.snake.sweeps)));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("SnakeSlides", static_cast<double>(result.snake.slides)));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("SnakeSplits", static_cast<double>(result.snake.splits)));
    kerf::WriteLabelBoundaries(result.boundaries, vtkPolyData::GetData(outputVector, 1));
  });
}

void vtkSnakeRefinement::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->PrintSnakeParameters(os, indent);
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
}
