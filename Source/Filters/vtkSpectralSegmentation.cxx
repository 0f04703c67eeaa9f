// vtkSpectralSegmentation: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkSpectralSegmentation.h"

#include "Segmentation/SpectralSegmentation.h"
#include "Error.h"
#include "KerfFilterUtilities.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkSpectralSegmentation);

struct vtkSpectralSegmentation::Internals
{
  kerf::SurfaceInput surface;
};

vtkSpectralSegmentation::vtkSpectralSegmentation()
  : State(new Internals)
{
  this->SetSegmentArrayName("Segment");
}

vtkSpectralSegmentation::~vtkSpectralSegmentation()
{
  this->SetSegmentArrayName(nullptr);
}

int vtkSpectralSegmentation::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Spectral Segmentation", [&]() {
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
    kerf::SpectralSegmentationOptions options;
    options.geodesicWeight = kerf::Finite(this->GeodesicWeight, "GeodesicWeight");
    options.convexAngleWeight = kerf::Finite(this->ConvexAngleWeight, "ConvexAngleWeight");
    options.patchCount = this->PatchCount;
    const kerf::SpectralSegmentationResult result =
      kerf::segmentSpectrally(kerf::FaceGraph(surface.mesh()), this->SegmentCount, options);
    labels = result.labels;
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("Patches", result.patches));
    kerf::AddSegmentLabels(this->State->surface, output, this->SegmentArrayName, labels);
  });
}

void vtkSpectralSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "GeodesicWeight: " << this->GeodesicWeight << "\n";
  os << indent << "ConvexAngleWeight: " << this->ConvexAngleWeight << "\n";
  os << indent << "PatchCount: " << this->PatchCount << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
