// vtkWatershedSegmentation: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkWatershedSegmentation.h"

#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/FaceGraph.h"
#include "Segmentation/WatershedSegmentation.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkWatershedSegmentation);

struct vtkWatershedSegmentation::Internals
{
  kerf::SurfaceInput surface;
};

vtkWatershedSegmentation::vtkWatershedSegmentation()
  : State(new Internals)
{
  this->SetSegmentArrayName("Segment");
}

vtkWatershedSegmentation::~vtkWatershedSegmentation()
{
  this->SetSegmentArrayName(nullptr);
}

int vtkWatershedSegmentation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Watershed Segmentation", [&]() {
    const kerf::MeshRequirements requirements; // edge-manifold, consistently oriented
    kerf::SegmentSurface(this, this->State->surface, vtkPolyData::GetData(inputVector[0], 0),
      vtkPolyData::GetData(outputVector, 0), this->SegmentArrayName, requirements,
      [this](const kerf::Surface& surface, vtkFieldData* fieldData) {
        kerf::WatershedOptions options;
        options.depthThreshold = kerf::Finite(this->DepthThreshold, "DepthThreshold");
        options.segmentCount = this->SegmentCount;
        const kerf::WatershedResult result = kerf::segmentByWatershed(kerf::faceGraph(surface), options);
        fieldData->AddArray(kerf::MakeFieldValue("Basins", result.basins));
        return result.labels;
      });
  });
}

void vtkWatershedSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthThreshold: " << this->DepthThreshold << "\n";
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
