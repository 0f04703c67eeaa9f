// vtkConsensusCutSegmentation: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkConsensusCutSegmentation.h"

#include "Segmentation/ConsensusCutSegmentation.h"
#include "Error.h"
#include "KerfFilterUtilities.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkConsensusCutSegmentation);

struct vtkConsensusCutSegmentation::Internals
{
  kerf::SurfaceInput surface;
};

vtkConsensusCutSegmentation::vtkConsensusCutSegmentation()
  : State(new Internals)
{
  this->SetSegmentArrayName("Segment");
}

vtkConsensusCutSegmentation::~vtkConsensusCutSegmentation()
{
  this->SetSegmentArrayName(nullptr);
}

int vtkConsensusCutSegmentation::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Consensus Cut Segmentation", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->SegmentArrayName });
    kerf::MeshRequirements requirements;
    requirements.manifold = true;
    requirements.consistentOrientation = true;
    requirements.allowBoundary = true;
    requirements.allowSeveralComponents = true;
    kerf::LoadSurface(this->State->surface, input, requirements);
    const kerf::Surface& surface = this->State->surface.GetSurface();

    this->State->surface.MakeOutput(input, output);
    std::vector<int> labels;
    kerf::ConsensusCutOptions options;
    options.extraFeaturePoints = this->ExtraFeaturePoints;
    options.maximumFeaturePoints = this->MaximumFeaturePoints;
    options.minimumSegmentArea = kerf::Finite(this->MinimumSegmentArea, "MinimumSegmentArea");
    const kerf::ConsensusCutResult result = kerf::segmentByConsensusCuts(surface, this->SegmentCount, options);
    labels = result.labels;
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("ChosenCuts", result.chosenCuts));
    kerf::AddSegmentLabels(this->State->surface, output, this->SegmentArrayName, labels);
  });
}

void vtkConsensusCutSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "ExtraFeaturePoints: " << this->ExtraFeaturePoints << "\n";
  os << indent << "MaximumFeaturePoints: " << this->MaximumFeaturePoints << "\n";
  os << indent << "MinimumSegmentArea: " << this->MinimumSegmentArea << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
