// vtkStrokeConstraints: reads the strokes, places their constraints with the surface's session, writes the points.
#include "vtkStrokeConstraints.h"

#include "Error.h"
#include "Harmonic/HarmonicCutSession.h"
#include "KerfFilterUtilities.h"
#include "KerfSurfaceInput.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
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
  kerf::StrokePointList strokePoints;
};

vtkStrokeConstraints::vtkStrokeConstraints()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
}

vtkStrokeConstraints::~vtkStrokeConstraints() = default;

void vtkStrokeConstraints::SetNumberOfStrokePoints(int count)
{
  kerf::SetPanelPointCount(this, this->State->strokePoints, count, "stroke");
}

int vtkStrokeConstraints::GetNumberOfStrokePoints() const
{
  return this->State->strokePoints.Count();
}

void vtkStrokeConstraints::SetStrokePoint(int index, double x, double y, double z)
{
  kerf::SetPanelPoint(this, this->State->strokePoints, index, kerf::Vector3(x, y, z), "stroke");
}

int vtkStrokeConstraints::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

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

    const std::vector<std::vector<kerf::Vector3>> strokes = kerf::ReadStrokes(strokeInput, this->State->strokePoints, session.surface());

    kerf::StrokeOptions options;
    options.samplesPerSegment = this->SamplesPerSegment;
    options.offset = kerf::Finite(this->Offset, "Offset") * diagonal;
    options.offsetLengthFraction = kerf::Finite(this->OffsetLengthFraction, "OffsetLengthFraction");
    options.isoValue = this->IsoValue;
    options.maximumDistance =
      kerf::RelativeDistance(this->MaximumProjectionDistance, diagonal, "MaximumProjectionDistance");
    const kerf::StrokeConstraintSet set = session.strokeConstraints(strokes, options);

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
  os << indent << "SamplesPerSegment: " << this->SamplesPerSegment << "\n";
  os << indent << "Offset: " << this->Offset << "\n";
  os << indent << "OffsetLengthFraction: " << this->OffsetLengthFraction << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "StrokePoints: " << this->State->strokePoints.Count() << "\n";
}
