// vtkConvexFlooding: converts and validates the surface, runs the Core segmentation, writes the labels.
#include "vtkConvexFlooding.h"

#include "Segmentation/ConvexFlooding.h"
#include "Error.h"
#include "KerfFilterUtilities.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
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

int vtkConvexFlooding::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot segment with Convex Flooding", [&]() {
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
    kerf::ConvexFloodingOptions options;
    options.angleTolerance = kerf::Finite(this->AngleTolerance, "AngleTolerance");
    options.minimumAreaFraction = kerf::Finite(this->MinimumAreaFraction, "MinimumAreaFraction");
    options.segmentCount = this->SegmentCount;
    const kerf::ConvexFloodingResult result = kerf::segmentByConvexFlooding(kerf::FaceGraph(surface.mesh()), options);
    labels = result.labels;
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("FloodedPatches", result.floodedPatches));
    kerf::AddSegmentLabels(this->State->surface, output, this->SegmentArrayName, labels);
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
