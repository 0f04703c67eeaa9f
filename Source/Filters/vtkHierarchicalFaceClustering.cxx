// vtkHierarchicalFaceClustering: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkHierarchicalFaceClustering.h"

#include "Error.h"
#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/HierarchicalFaceClustering.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkHierarchicalFaceClustering);

struct vtkHierarchicalFaceClustering::Internals
{
  kerf::SurfaceInput surface;
};

vtkHierarchicalFaceClustering::vtkHierarchicalFaceClustering()
  : State(new Internals)
{
  this->SetSegmentArrayName("Segment");
}

vtkHierarchicalFaceClustering::~vtkHierarchicalFaceClustering()
{
  this->SetSegmentArrayName(nullptr);
}

int vtkHierarchicalFaceClustering::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Hierarchical Face Clustering", [&]() {
    const kerf::MeshRequirements requirements; // edge-manifold, consistently oriented
    kerf::SegmentSurface(this, this->State->surface, vtkPolyData::GetData(inputVector[0], 0),
      vtkPolyData::GetData(outputVector, 0), this->SegmentArrayName, requirements,
      [this](const kerf::Surface& surface, vtkFieldData* fieldData) {
        kerf::HierarchicalClusteringOptions options;
        options.directionWeight = kerf::Finite(this->DirectionWeight, "DirectionWeight");
        options.shapeWeight = kerf::Finite(this->ShapeWeight, "ShapeWeight");
        if (this->ExactClusterCount < 1 || this->BlockSize < 1)
        {
          throw kerf::Error("ExactClusterCount and BlockSize must be at least 1");
        }
        options.exactClusterCount = this->ExactClusterCount;
        options.blockSize = this->BlockSize;
        if (this->SegmentCount < 0)
        {
          throw kerf::Error("SegmentCount must be 0 (cut at MaximumError) or positive");
        }
        const int before = surface.computations();
        const kerf::FaceClusterHierarchy& hierarchy = kerf::faceClusterHierarchy(surface, options);
        const bool built = surface.computations() != before;
        std::vector<int> first, second;
        for (const auto& merge : hierarchy.merges)
        {
          first.push_back(merge[0]);
          second.push_back(merge[1]);
        }
        fieldData->AddArray(kerf::MakeIntArray("MergeFirst", first));
        fieldData->AddArray(kerf::MakeIntArray("MergeSecond", second));
        fieldData->AddArray(kerf::MakeArray("MergeCost", hierarchy.costs));
        fieldData->AddArray(kerf::MakeFieldValue("Work", built ? std::string("hierarchy") : std::string("relabel")));
        return this->SegmentCount > 0
          ? kerf::cutHierarchyAtCount(hierarchy, this->SegmentCount)
          : kerf::cutHierarchyAtError(hierarchy, kerf::Finite(this->MaximumError, "MaximumError"));
      });
  });
}

void vtkHierarchicalFaceClustering::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "DirectionWeight: " << this->DirectionWeight << "\n";
  os << indent << "ShapeWeight: " << this->ShapeWeight << "\n";
  os << indent << "ExactClusterCount: " << this->ExactClusterCount << "\n";
  os << indent << "BlockSize: " << this->BlockSize << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
