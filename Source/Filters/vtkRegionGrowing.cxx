// vtkRegionGrowing: labelled strokes of input 1 grown over the surface under the isophotic metric (kerf::easyMeshCut
// without refinement).
#include "vtkRegionGrowing.h"

#include "Error.h"
#include "KerfDrawnInput.h"
#include "KerfEasyMeshCutting.h"
#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkRegionGrowing);

struct vtkRegionGrowing::Internals
{
  kerf::SurfaceInput surface;
};

vtkRegionGrowing::vtkRegionGrowing()
  : State(new Internals)
{
}

vtkRegionGrowing::~vtkRegionGrowing() = default;

int vtkRegionGrowing::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot grow regions from the strokes", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->SegmentArrayName });
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    const kerf::SurfaceInput& surface = this->State->surface;
    const kerf::PanelLabelledStrokes strokes = kerf::ReadGrowingStrokes(vtkPolyData::GetData(inputVector[1], 0),
      this->StrokeLabelArrayName, *this->DrawnStrokes, {}, surface.GetSurface());
    if (!strokes.overrides.empty())
    {
      throw kerf::Error("override strokes (label -1) edit the boundaries of Easy Mesh Cut and Snake Refinement; Region "
                        "Growing takes strokes of labels 0 and up");
    }
    kerf::EasyMeshCutOptions options;
    options.growing = kerf::ReadGrowingOptions(this, surface.Mesh().boundingBoxDiagonal());
    options.refine = false;
    this->UpdateProgress(0.1);
    const kerf::EasyMeshCutResult result = kerf::easyMeshCut(surface.SharedSurface(), strokes.strokes, options);
    this->UpdateProgress(0.9);

    surface.MakeOutput(input, output);
    output->GetCellData()->AddArray(kerf::MakeIntArray(this->SegmentArrayName, result.faceLabels));
    kerf::WriteSegmentSizes(result.faceLabels, output);
    output->GetCellData()->SetActiveScalars(this->SegmentArrayName);
    output->GetPointData()->AddArray(
      kerf::MakeIntArray(this->SegmentArrayName, surface.ToInputPoints(result.growing.vertexLabels)));
    output->GetPointData()->AddArray(kerf::MakeArray("IsophoticDistance", surface.ToInputPoints(result.distances)));
    if (!result.growing.probabilities.empty())
    {
      output->GetPointData()->AddArray(
        kerf::MakeArray("Probability", surface.ToInputPoints(result.growing.probabilities)));
    }
    output->GetFieldData()->AddArray(
      kerf::MakeFieldValue("UnreachableVertices", static_cast<double>(result.growing.unreachableVertices)));
    kerf::WriteLabelBoundaries(result.boundaries, vtkPolyData::GetData(outputVector, 1));
  });
}

void vtkRegionGrowing::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
