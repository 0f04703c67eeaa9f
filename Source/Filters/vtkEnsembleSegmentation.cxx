// vtkEnsembleSegmentation: converts and validates the surface, runs the Core ensemble, writes the labels.
#include "vtkEnsembleSegmentation.h"

#include "CacheKey.h"
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

#include <string>
#include <vector>

vtkStandardNewMacro(vtkEnsembleSegmentation);

struct vtkEnsembleSegmentation::Internals
{
  kerf::SurfaceInput surface;
  /// With UseHierarchy: the tree, the surface it was built on (held, so that its address cannot
  /// pass to another surface) and the parameters it was built with.
  std::shared_ptr<const kerf::Surface> hierarchySurface;
  std::string hierarchyKey;
  kerf::EnsembleHierarchy hierarchy;
};

namespace
{
// The parameters an ensemble hierarchy depends on (the count it chooses too: the tolerance and the
// refinement).
std::string HierarchyKey(const kerf::EnsembleSegmentationOptions& options, int minimumCount, int maximumCount)
{
  std::string key =
    std::to_string(minimumCount) + " " + std::to_string(maximumCount) + " " + std::to_string(options.areaWeighted);
  for (double value : { options.consensusCutsWeight, options.spectralWeight, options.convexFloodingWeight,
         options.kMeansWeight, options.watershedWeight, options.faceClusteringWeight, options.coreExtractionWeight,
         options.convexTolerance, options.refinement.bandWidth, options.refinement.convexWeight })
  {
    key += " " + kerf::cacheKey(value);
  }
  return key;
}
} // namespace

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
        if (this->UseHierarchy)
        {
          return this->CutHierarchy(surface, options, fieldData);
        }
        // A tree kept from an earlier Use Hierarchy is let go (with its surface).
        this->State->hierarchySurface.reset();
        this->State->hierarchyKey.clear();
        this->State->hierarchy = kerf::EnsembleHierarchy();
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

std::vector<int> vtkEnsembleSegmentation::CutHierarchy(
  const kerf::Surface& surface, const kerf::EnsembleSegmentationOptions& options, vtkFieldData* fieldData)
{
  Internals& state = *this->State;
  if (!this->ChooseSegmentCount)
  {
    kerf::checkSegmentCount(this->SegmentCount, surface.mesh().faceCount()); // before a build, not after
  }
  const std::string key = HierarchyKey(options, this->MinimumSegmentCount, this->MaximumSegmentCount);
  const bool build = state.hierarchySurface.get() != &surface || state.hierarchyKey != key;
  if (build)
  {
    state.hierarchySurface.reset();
    state.hierarchy = kerf::ensembleHierarchy(surface, this->MinimumSegmentCount, this->MaximumSegmentCount, options);
    state.hierarchySurface = state.surface.SharedSurface();
    state.hierarchyKey = key;
  }
  const kerf::EnsembleHierarchy& hierarchy = state.hierarchy;
  const int count = this->ChooseSegmentCount ? hierarchy.chosenCount : this->SegmentCount;
  const kerf::EnsembleSegmentationResult result =
    kerf::cutEnsembleHierarchy(surface, hierarchy, count, options.refinement);
  std::vector<int> first, second;
  for (const auto& merge : hierarchy.consensus.merges)
  {
    first.push_back(merge[0]);
    second.push_back(merge[1]);
  }
  fieldData->AddArray(kerf::MakeFieldValue("Members", result.members));
  fieldData->AddArray(kerf::MakeFieldValue("Atoms", result.atoms));
  fieldData->AddArray(kerf::MakeIntArray("MergeFirst", first));
  fieldData->AddArray(kerf::MakeIntArray("MergeSecond", second));
  fieldData->AddArray(kerf::MakeArray("MergeLinkage", hierarchy.consensus.linkages));
  fieldData->AddArray(kerf::MakeArray("CountScores", hierarchy.countScores));
  fieldData->AddArray(kerf::MakeFieldValue("Work", build ? std::string("hierarchy") : std::string("relabel")));
  return result.labels;
}

void vtkEnsembleSegmentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "ChooseSegmentCount: " << this->ChooseSegmentCount << "\n";
  os << indent << "UseHierarchy: " << this->UseHierarchy << "\n";
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
