// vtkStrokeConstraints: reads the strokes, places their constraints with the surface's session, writes the points.
#include "vtkStrokeConstraints.h"

#include "Error.h"
#include "Harmonic/HarmonicCutSession.h"
#include "KerfDrawnInput.h"
#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSignedCharArray.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <string>

vtkStandardNewMacro(vtkStrokeConstraints);

struct vtkStrokeConstraints::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::HarmonicCutSession> session;
};

vtkStrokeConstraints::vtkStrokeConstraints()
  : State(new Internals)
{
}

vtkStrokeConstraints::~vtkStrokeConstraints() = default;

int vtkStrokeConstraints::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot place stroke constraints", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* strokeInput = vtkPolyData::GetData(inputVector[1], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::StrokeIsoValue(this->IsoValue);
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    kerf::HarmonicCutSession& session = this->State->surface.SessionFor(this->State->session);
    const double diagonal = session.mesh().boundingBoxDiagonal();

    const std::vector<std::vector<kerf::Vector3>> strokes =
      kerf::ReadStrokes(strokeInput, *this->DrawnStrokes, *this->StrokePoints, session.surface());

    const kerf::StrokeConstraintSet set = session.strokeConstraints(strokes, kerf::ReadStrokeOptions(this, diagonal));

    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray> vertices;
    std::vector<double> values;
    vtkNew<vtkSignedCharArray> sides;
    sides->SetName("Side");
    for (std::size_t i = 0; i < set.constraints.size(); ++i)
    {
      const vtkIdType id = points->InsertNextPoint(set.positions[i].data());
      vertices->InsertNextCell(1, &id);
      values.push_back(set.constraints[i].value);
      sides->InsertNextValue(set.constraints[i].value > this->IsoValue ? 1 : -1);
    }
    output->SetPoints(points);
    output->SetVerts(vertices);
    output->GetPointData()->AddArray(kerf::MakeArray("ConstraintValue", values));
    output->GetPointData()->SetActiveScalars("ConstraintValue");
    output->GetPointData()->AddArray(sides);
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("IsoValue", this->IsoValue));
  });
}

void vtkStrokeConstraints::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
