// vtkSpectralSegmentation: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkSpectralSegmentation.h"

#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/FaceGraph.h"
#include "Segmentation/SpectralSegmentation.h"

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

int vtkSpectralSegmentation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Spectral Segmentation", [&]() {
    const kerf::MeshRequirements requirements; // edge-manifold, consistently oriented
    kerf::SegmentSurface(this, this->State->surface, vtkPolyData::GetData(inputVector[0], 0),
      vtkPolyData::GetData(outputVector, 0), this->SegmentArrayName, requirements,
      [this](const kerf::Surface& surface, vtkFieldData* fieldData) {
        kerf::SpectralSegmentationOptions options;
        options.geodesicWeight = kerf::Finite(this->GeodesicWeight, "GeodesicWeight");
        options.convexAngleWeight = kerf::Finite(this->ConvexAngleWeight, "ConvexAngleWeight");
        options.patchCount = this->PatchCount;
        const kerf::SpectralSegmentationResult result = kerf::segmentSpectrally(surface, this->SegmentCount, options);
        fieldData->AddArray(kerf::MakeFieldValue("Patches", result.patches));
        return result.labels;
      });
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
