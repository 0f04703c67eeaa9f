// vtkBoundaryBandCut: reads a surface's labels, re-cuts their boundaries within bands (kerf::refineSegmentBoundaries),
// writes them.
#include "vtkBoundaryBandCut.h"

#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Segmentation/BoundaryRefinement.h"
#include "Segmentation/FaceGraph.h"

#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <algorithm>

vtkStandardNewMacro(vtkBoundaryBandCut);

struct vtkBoundaryBandCut::Internals
{
  kerf::SurfaceInput surface;
};

vtkBoundaryBandCut::vtkBoundaryBandCut()
  : State(new Internals)
{
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Segment");
}

vtkBoundaryBandCut::~vtkBoundaryBandCut() = default;

int vtkBoundaryBandCut::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot re-cut the boundaries", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    const kerf::InputLabels read =
      kerf::LoadLabelledSurface(this, this->State->surface, input, kerf::MeshRequirements());
    const kerf::SurfaceInput& surface = this->State->surface;

    kerf::BoundaryRefinementOptions options;
    options.bandWidth = kerf::Finite(this->BoundaryBand, "BoundaryBand");
    options.convexWeight = kerf::Finite(this->ConvexWeight, "ConvexWeight");
    this->UpdateProgress(0.1);
    const kerf::BoundaryRefinementResult result =
      kerf::refineSegmentBoundaries(kerf::faceGraph(surface.GetSurface()), read.labels, options);
    this->UpdateProgress(0.9);

    kerf::WriteRelabelledSurface(surface, input, output, read, result.labels);
    const int segments = result.labels.empty() ? 0 : *std::max_element(result.labels.begin(), result.labels.end()) + 1;
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("SegmentCount", segments));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("RecutBoundaries", result.boundaries));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("MovedFaces", result.movedFaces));
  });
}

void vtkBoundaryBandCut::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BoundaryBand: " << this->BoundaryBand << "\n";
  os << indent << "ConvexWeight: " << this->ConvexWeight << "\n";
}
