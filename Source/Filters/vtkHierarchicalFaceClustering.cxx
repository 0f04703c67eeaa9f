// vtkHierarchicalFaceClustering: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkHierarchicalFaceClustering.h"

#include "Segmentation/HierarchicalFaceClustering.h"
#include "Error.h"
#include "KerfFilterUtilities.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
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

int vtkHierarchicalFaceClustering::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Hierarchical Face Clustering", [&]() {
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
    kerf::HierarchicalClusteringOptions options;
    options.directionWeight = kerf::Finite(this->DirectionWeight, "DirectionWeight");
    options.shapeWeight = kerf::Finite(this->ShapeWeight, "ShapeWeight");
    if (this->SegmentCount < 0)
    {
      throw kerf::Error("SegmentCount must be 0 (cut at MaximumError) or positive");
    }
    const int before = surface.computations();
    const kerf::FaceClusterHierarchy& hierarchy = kerf::faceClusterHierarchy(surface, options);
    const bool built = surface.computations() != before;
    labels = this->SegmentCount > 0 ? kerf::cutHierarchyAtCount(hierarchy, this->SegmentCount)
                                    : kerf::cutHierarchyAtError(hierarchy, kerf::Finite(this->MaximumError, "MaximumError"));
    std::vector<int> first, second;
    for (const auto& merge : hierarchy.merges)
    {
      first.push_back(merge[0]);
      second.push_back(merge[1]);
    }
    output->GetFieldData()->AddArray(kerf::MakeIntArray("MergeFirst", first));
    output->GetFieldData()->AddArray(kerf::MakeIntArray("MergeSecond", second));
    output->GetFieldData()->AddArray(kerf::MakeArray("MergeCost", hierarchy.costs));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("Work", built ? std::string("hierarchy") : std::string("relabel")));
    kerf::AddSegmentLabels(this->State->surface, output, this->SegmentArrayName, labels);
  });
}

void vtkHierarchicalFaceClustering::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "DirectionWeight: " << this->DirectionWeight << "\n";
  os << indent << "ShapeWeight: " << this->ShapeWeight << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
