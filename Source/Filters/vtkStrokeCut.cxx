// vtkStrokeCut: the stroke, the field and the cut in one filter, through the surface's HarmonicCutSession.
#include "vtkStrokeCut.h"

#include "Error.h"
#include "Harmonic/HarmonicCutSession.h"
#include "KerfDrawnInput.h"
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

#include <cmath>
#include <string>

vtkStandardNewMacro(vtkStrokeCut);

struct vtkStrokeCut::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::HarmonicCutSession> session;
};

vtkStrokeCut::vtkStrokeCut()
  : State(new Internals)
{
  this->SetNumberOfOutputPorts(2);
}

vtkStrokeCut::~vtkStrokeCut() = default;

vtkPolyData* vtkStrokeCut::GetCut()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkStrokeCut::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot cut along the stroke", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::StrokeIsoValue(this->IsoValue);
    kerf::MeshRequirements requirements;
    requirements.manifold = true;
    requirements.consistentOrientation = true;
    kerf::LoadSurface(this->State->surface, input, requirements);
    kerf::HarmonicCutSession& session = this->State->surface.SessionFor(this->State->session);
    const double diagonal = session.mesh().boundingBoxDiagonal();
    const std::vector<std::vector<kerf::Vector3>> strokes = kerf::ReadStrokes(
      vtkPolyData::GetData(inputVector[1], 0), *this->DrawnStrokes, *this->StrokePoints, session.surface());
    this->UpdateProgress(0.1);

    kerf::FieldConstraints constraints;
    constraints.soft = session.strokeConstraints(strokes, kerf::ReadStrokeOptions(this, diagonal)).constraints;
    // Components no stroke touches stay whole, on the stroke's +1 side.
    session.holdUnconstrainedComponents(constraints, this->IsoValue + 1.0);
    kerf::HarmonicFieldOptions fieldOptions;
    fieldOptions.weights.weighting = static_cast<kerf::LaplacianWeighting>(this->Weighting);
    fieldOptions.softWeight = kerf::Finite(this->SoftConstraintWeight, "SoftConstraintWeight");
    fieldOptions.formulation = kerf::FilterFormulation(this->Formulation, session);
    const kerf::HarmonicFieldSolution solution = session.solve(constraints, fieldOptions);
    this->UpdateProgress(0.8);

    kerf::CutOptions cutOptions;
    cutOptions.mode = kerf::CutMode::NearStroke;
    cutOptions.isoValue = this->IsoValue;
    for (const std::vector<kerf::Vector3>& stroke : strokes)
    {
      cutOptions.stroke.insert(cutOptions.stroke.end(), stroke.begin(), stroke.end());
    }
    const kerf::CutResult cut = session.chooseCut(solution.field, cutOptions);

    this->State->surface.MakeOutput(input, output);
    kerf::WriteField(this->State->surface, solution, constraints, "HarmonicField", output);
    output->GetCellData()->AddArray(kerf::MakeIntArray("Segment", cut.labels));
    kerf::WriteSegmentSizes(cut.labels, output);
    output->GetCellData()->SetActiveScalars("Segment"); // what ParaView colours by after Apply
    kerf::WriteCutLines(cut, vtkPolyData::GetData(outputVector, 1));
  });
}

void vtkStrokeCut::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << this->Weighting << "\n";
  os << indent << "Formulation: " << this->Formulation << "\n";
  os << indent << "SoftConstraintWeight: " << this->SoftConstraintWeight << "\n";
}
