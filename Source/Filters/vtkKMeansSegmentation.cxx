// vtkKMeansSegmentation: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkKMeansSegmentation.h"

#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/FaceGraph.h"
#include "Segmentation/KMeansSegmentation.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkKMeansSegmentation);

struct vtkKMeansSegmentation::Internals
{
  kerf::SurfaceInput surface;
};

vtkKMeansSegmentation::vtkKMeansSegmentation()
  : State(new Internals)
{
  this->SetSegmentArrayName("Segment");
}

vtkKMeansSegmentation::~vtkKMeansSegmentation()
{
  this->SetSegmentArrayName(nullptr);
}

int vtkKMeansSegmentation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with K-Means Segmentation", [&]() {
    const kerf::MeshRequirements requirements; // edge-manifold, consistently oriented
    kerf::SegmentSurface(this, this->State->surface, vtkPolyData::GetData(inputVector[0], 0),
      vtkPolyData::GetData(outputVector, 0), this->SegmentArrayName, requirements,
      [this](const kerf::Surface& surface, vtkFieldData* fieldData) {
        kerf::KMeansSegmentationOptions options;
        options.physicalWeight = kerf::Finite(this->PhysicalWeight, "PhysicalWeight");
        options.maximumIterations = this->MaximumIterations;
        const kerf::KMeansSegmentationResult result =
          kerf::segmentByKMeans(kerf::faceGraph(surface), this->SegmentCount, options);
        fieldData->AddArray(kerf::MakeFieldValue("Iterations", result.iterations));
        return result.labels;
      });
  });
}

void vtkKMeansSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "PhysicalWeight: " << this->PhysicalWeight << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
