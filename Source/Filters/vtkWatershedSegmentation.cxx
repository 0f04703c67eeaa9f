// vtkWatershedSegmentation: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkWatershedSegmentation.h"

#include "Segmentation/WatershedSegmentation.h"
#include "Error.h"
#include "KerfFilterUtilities.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
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

int vtkWatershedSegmentation::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Watershed Segmentation", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->SegmentArrayName });
    kerf::MeshRequirements requirements;
    requirements.manifold = false;
    requirements.consistentOrientation = false;
    requirements.allowBoundary = true;
    requirements.allowSeveralComponents = true;
    kerf::LoadSurface(this->State->surface, input, requirements);
    const kerf::Surface& surface = this->State->surface.GetSurface();

    this->State->surface.MakeOutput(input, output);
    std::vector<int> labels;
    kerf::WatershedOptions options;
    options.depthThreshold = kerf::Finite(this->DepthThreshold, "DepthThreshold");
    options.segmentCount = this->SegmentCount;
    const kerf::WatershedResult result = kerf::segmentByWatershed(kerf::FaceGraph(surface.mesh()), options);
    labels = result.labels;
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("Basins", result.basins));
    kerf::AddSegmentLabels(this->State->surface, output, this->SegmentArrayName, labels);
  });
}

void vtkWatershedSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthThreshold: " << this->DepthThreshold << "\n";
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
