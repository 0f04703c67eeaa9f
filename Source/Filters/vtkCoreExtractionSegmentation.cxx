// vtkCoreExtractionSegmentation: converts and validates the surface, runs the Core segmentation, writes the labels and
// the core.
#include "vtkCoreExtractionSegmentation.h"

#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/CoreExtraction.h"
#include "Segmentation/FaceGraph.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <vector>

vtkStandardNewMacro(vtkCoreExtractionSegmentation);

struct vtkCoreExtractionSegmentation::Internals
{
  kerf::SurfaceInput surface;
};

vtkCoreExtractionSegmentation::vtkCoreExtractionSegmentation()
  : State(new Internals)
{
  this->SetSegmentArrayName("Segment");
}

vtkCoreExtractionSegmentation::~vtkCoreExtractionSegmentation()
{
  this->SetSegmentArrayName(nullptr);
}

int vtkCoreExtractionSegmentation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Core Extraction Segmentation", [&]() {
    const kerf::MeshRequirements requirements; // edge-manifold, consistently oriented
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    std::vector<int> core;
    kerf::SegmentSurface(this, this->State->surface, vtkPolyData::GetData(inputVector[0], 0), output,
      this->SegmentArrayName, requirements, [this, &core](const kerf::Surface& surface, vtkFieldData* fieldData) {
        kerf::CoreExtractionOptions options;
        options.coarseSize = this->CoarseSize;
        options.featureRadius = kerf::Finite(this->FeatureRadius, "FeatureRadius");
        options.hullTolerance = kerf::Finite(this->HullTolerance, "HullTolerance");
        options.extensionFactor = kerf::Finite(this->ExtensionFactor, "ExtensionFactor");
        options.minimumSegmentArea = kerf::Finite(this->MinimumSegmentArea, "MinimumSegmentArea");
        options.refinement.bandWidth = kerf::Finite(this->BandWidth, "BandWidth");
        const kerf::CoreExtractionResult result = kerf::segmentByCoreExtraction(kerf::faceGraph(surface), options);
        fieldData->AddArray(kerf::MakeFieldValue("FeaturePoints", result.featurePoints));
        fieldData->AddArray(kerf::MakeFieldValue("CoreExtensions", result.coreExtensions));
        fieldData->AddArray(kerf::MakeIntArray("FeatureFaces", result.featureFaces));
        core.assign(result.core.begin(), result.core.end());
        return result.labels;
      });
    kerf::WriteTriangleArray(this->State->surface, output, "Core", core);
  });
}

void vtkCoreExtractionSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CoarseSize: " << this->CoarseSize << "\n";
  os << indent << "FeatureRadius: " << this->FeatureRadius << "\n";
  os << indent << "HullTolerance: " << this->HullTolerance << "\n";
  os << indent << "ExtensionFactor: " << this->ExtensionFactor << "\n";
  os << indent << "MinimumSegmentArea: " << this->MinimumSegmentArea << "\n";
  os << indent << "BandWidth: " << this->BandWidth << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
