// vtkConsensusCutSegmentation: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkConsensusCutSegmentation.h"

#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/ConsensusCutSegmentation.h"

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

int vtkConsensusCutSegmentation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Consensus Cut Segmentation", [&]() {
    const kerf::MeshRequirements requirements; // edge-manifold, consistently oriented
    kerf::SegmentSurface(this, this->State->surface, vtkPolyData::GetData(inputVector[0], 0),
      vtkPolyData::GetData(outputVector, 0), this->SegmentArrayName, requirements,
      [this](const kerf::Surface& surface, vtkFieldData* fieldData) {
        kerf::ConsensusCutOptions options;
        options.extraFeaturePoints = this->ExtraFeaturePoints;
        options.maximumFeaturePoints = this->MaximumFeaturePoints;
        options.minimumSegmentArea = kerf::Finite(this->MinimumSegmentArea, "MinimumSegmentArea");
        options.walkDepth = kerf::Finite(this->WalkDepth, "WalkDepth");
        const kerf::ConsensusCutResult result = kerf::segmentByConsensusCuts(surface, this->SegmentCount, options);
        fieldData->AddArray(kerf::MakeFieldValue("ChosenCuts", result.chosenCuts));
        fieldData->AddArray(kerf::MakeFieldValue("WalkedFaces", result.walkedFaces));
        return result.labels;
      });
  });
}

void vtkConsensusCutSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "ExtraFeaturePoints: " << this->ExtraFeaturePoints << "\n";
  os << indent << "MaximumFeaturePoints: " << this->MaximumFeaturePoints << "\n";
  os << indent << "MinimumSegmentArea: " << this->MinimumSegmentArea << "\n";
  os << indent << "WalkDepth: " << this->WalkDepth << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
