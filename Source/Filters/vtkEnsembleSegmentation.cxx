// vtkEnsembleSegmentation: converts and validates the surface, runs the Core ensemble, writes the labels.
#include "vtkEnsembleSegmentation.h"

#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/EnsembleSegmentation.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkEnsembleSegmentation);

struct vtkEnsembleSegmentation::Internals
{
  kerf::SurfaceInput surface;
};

vtkEnsembleSegmentation::vtkEnsembleSegmentation()
  : State(new Internals)
{
  this->SetSegmentArrayName("Segment");
}

vtkEnsembleSegmentation::~vtkEnsembleSegmentation()
{
  this->SetSegmentArrayName(nullptr);
}

int vtkEnsembleSegmentation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Ensemble Segmentation", [&]() {
    const kerf::MeshRequirements requirements; // edge-manifold, consistently oriented
    kerf::SegmentSurface(this, this->State->surface, vtkPolyData::GetData(inputVector[0], 0),
      vtkPolyData::GetData(outputVector, 0), this->SegmentArrayName, requirements,
      [this](const kerf::Surface& surface, vtkFieldData* fieldData) {
        kerf::EnsembleSegmentationOptions options;
        options.consensusCutsWeight = kerf::Finite(this->ConsensusCutsWeight, "ConsensusCutsWeight");
        options.spectralWeight = kerf::Finite(this->SpectralWeight, "SpectralWeight");
        options.convexFloodingWeight = kerf::Finite(this->ConvexFloodingWeight, "ConvexFloodingWeight");
        options.kMeansWeight = kerf::Finite(this->KMeansWeight, "KMeansWeight");
        options.watershedWeight = kerf::Finite(this->WatershedWeight, "WatershedWeight");
        options.faceClusteringWeight = kerf::Finite(this->FaceClusteringWeight, "FaceClusteringWeight");
        options.coreExtractionWeight = kerf::Finite(this->CoreExtractionWeight, "CoreExtractionWeight");
        options.areaWeighted = this->AreaWeighted;
        options.convexTolerance = this->ConvexTolerance;
        options.refinement.bandWidth = kerf::Finite(this->BoundaryBand, "BoundaryBand");
        options.refinement.convexWeight = kerf::Finite(this->ConvexWeight, "ConvexWeight");
        const kerf::EnsembleSegmentationResult result = this->ChooseSegmentCount
          ? kerf::segmentByEnsembleChoosingCount(surface, this->MinimumSegmentCount, this->MaximumSegmentCount, options)
          : kerf::segmentByEnsemble(surface, this->SegmentCount, options);
        fieldData->AddArray(kerf::MakeFieldValue("Members", result.members));
        fieldData->AddArray(kerf::MakeFieldValue("Atoms", result.atoms));
        if (this->ChooseSegmentCount)
        {
          fieldData->AddArray(kerf::MakeArray("CountScores", result.countScores));
        }
        return result.labels;
      });
  });
}

void vtkEnsembleSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "ChooseSegmentCount: " << this->ChooseSegmentCount << "\n";
  os << indent << "MinimumSegmentCount: " << this->MinimumSegmentCount << "\n";
  os << indent << "MaximumSegmentCount: " << this->MaximumSegmentCount << "\n";
  os << indent << "ConvexTolerance: " << this->ConvexTolerance << "\n";
  os << indent << "ConsensusCutsWeight: " << this->ConsensusCutsWeight << "\n";
  os << indent << "SpectralWeight: " << this->SpectralWeight << "\n";
  os << indent << "ConvexFloodingWeight: " << this->ConvexFloodingWeight << "\n";
  os << indent << "KMeansWeight: " << this->KMeansWeight << "\n";
  os << indent << "WatershedWeight: " << this->WatershedWeight << "\n";
  os << indent << "FaceClusteringWeight: " << this->FaceClusteringWeight << "\n";
  os << indent << "CoreExtractionWeight: " << this->CoreExtractionWeight << "\n";
  os << indent << "AreaWeighted: " << this->AreaWeighted << "\n";
  os << indent << "BoundaryBand: " << this->BoundaryBand << "\n";
  os << indent << "ConvexWeight: " << this->ConvexWeight << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
