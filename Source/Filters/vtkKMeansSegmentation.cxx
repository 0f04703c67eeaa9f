// vtkKMeansSegmentation: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkKMeansSegmentation.h"

#include "Segmentation/KMeansSegmentation.h"
#include "Error.h"
#include "KerfFilterUtilities.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
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

int vtkKMeansSegmentation::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with KMeans Segmentation", [&]() {
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
    kerf::KMeansSegmentationOptions options;
    options.physicalWeight = kerf::Finite(this->PhysicalWeight, "PhysicalWeight");
    options.maximumIterations = this->MaximumIterations;
    const kerf::KMeansSegmentationResult result =
      kerf::segmentByKMeans(kerf::FaceGraph(surface.mesh()), this->SegmentCount, options);
    labels = result.labels;
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("Iterations", result.iterations));
    kerf::AddSegmentLabels(this->State->surface, output, this->SegmentArrayName, labels);
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
