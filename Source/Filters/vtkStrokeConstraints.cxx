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
  std::vector<kerf::Vector3> strokePoints;
};

vtkStrokeConstraints::vtkStrokeConstraints()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
}

vtkStrokeConstraints::~vtkStrokeConstraints() = default;

namespace
{
// More stroke points than anyone draws: a larger count or index is a mistake, refused before it
// allocates gigabytes.
constexpr int MaximumStrokePoints = 10000000;

void checkStrokePointCount(long long count)
{
  if (count > MaximumStrokePoints)
  {
    throw kerf::Error("a stroke has at most " + std::to_string(MaximumStrokePoints) + " points, not " +
      std::to_string(count));
  }
}
} // namespace

void vtkStrokeConstraints::SetNumberOfStrokePoints(int count)
{
  kerf::GuardSetter(this, "Cannot set the number of stroke points", [&]() {
    checkStrokePointCount(count);
    if (count >= 0 && static_cast<std::size_t>(count) != this->State->strokePoints.size())
    {
      this->State->strokePoints.resize(static_cast<std::size_t>(count), kerf::Vector3::Zero());
      this->Modified();
    }
  });
}

int vtkStrokeConstraints::GetNumberOfStrokePoints() const
{
  return static_cast<int>(this->State->strokePoints.size());
}

void vtkStrokeConstraints::SetStrokePoint(int index, double x, double y, double z)
{
  kerf::GuardSetter(this, "Cannot set a stroke point", [&]() {
    if (index < 0)
    {
      return;
    }
    checkStrokePointCount(static_cast<long long>(index) + 1);
    std::vector<kerf::Vector3>& points = this->State->strokePoints;
    if (static_cast<std::size_t>(index) >= points.size())
    {
      points.resize(static_cast<std::size_t>(index) + 1, kerf::Vector3::Zero());
    }
    const kerf::Vector3 p(x, y, z);
    if (points[static_cast<std::size_t>(index)] != p)
    {
      points[static_cast<std::size_t>(index)] = p;
      this->Modified();
    }
  });
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
    if (!std::isfinite(this->IsoValue) || !(this->IsoValue + 1.0 > this->IsoValue) ||
      !(this->IsoValue - 1.0 < this->IsoValue))
    {
      throw kerf::Error("IsoValue " + std::to_string(this->IsoValue) +
        " must be finite, and small enough that IsoValue +- 1 differ from it");
    }
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    kerf::HarmonicCutSession& session = this->State->surface.SessionFor(this->State->session);
    const double diagonal = session.mesh().boundingBoxDiagonal();

    std::vector<std::vector<kerf::Vector3>> strokes;
    if (strokeInput)
    {
      strokes = kerf::ReadPolylines(strokeInput, "the stroke input");
      if (strokes.empty())
      {
        throw kerf::Error("the stroke input holds no lines");
      }
    }
    else if (!this->State->strokePoints.empty())
    {
      strokes.push_back(this->State->strokePoints);
    }
    else
    {
      throw kerf::Error("there is no stroke: connect polylines to input 1 or set the stroke points");
    }

    kerf::StrokeOptions options;
    options.samplesPerSegment = this->SamplesPerSegment;
    options.offset = kerf::Finite(this->Offset, "Offset") * diagonal;
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
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "StrokePoints: " << this->State->strokePoints.size() << "\n";
}
