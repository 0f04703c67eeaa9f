// vtkConvexFlooding: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkConvexFlooding.h"

#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/ConvexFlooding.h"
#include "Segmentation/FaceGraph.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkConvexFlooding);

struct vtkConvexFlooding::Internals
{
  kerf::SurfaceInput surface;
};

vtkConvexFlooding::vtkConvexFlooding()
  : State(new Internals)
{
  this->SetSegmentArrayName("Segment");
}

vtkConvexFlooding::~vtkConvexFlooding()
{
  this->SetSegmentArrayName(nullptr);
}

int vtkConvexFlooding::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Convex Flooding", [&]() {
    const kerf::MeshRequirements requirements; // edge-manifold, consistently oriented
    kerf::SegmentSurface(this, this->State->surface, vtkPolyData::GetData(inputVector[0], 0),
      vtkPolyData::GetData(outputVector, 0), this->SegmentArrayName, requirements,
      [this](const kerf::Surface& surface, vtkFieldData* fieldData) {
        kerf::ConvexFloodingOptions options;
        options.angleTolerance = kerf::Finite(this->AngleTolerance, "AngleTolerance");
        options.minimumAreaFraction = kerf::Finite(this->MinimumAreaFraction, "MinimumAreaFraction");
        options.segmentCount = this->SegmentCount;
        const kerf::ConvexFloodingResult result = kerf::segmentByConvexFlooding(kerf::faceGraph(surface), options);
        fieldData->AddArray(kerf::MakeFieldValue("FloodedPatches", result.floodedPatches));
        return result.labels;
      });
  });
}

void vtkConvexFlooding::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AngleTolerance: " << this->AngleTolerance << "\n";
  os << indent << "MinimumAreaFraction: " << this->MinimumAreaFraction << "\n";
  os << indent << "SegmentCount: " << this->SegmentCount << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
