// vtkStrokeConstraints: reads strokes, keeps the surface and its locator, calls kerf::strokeConstraints.
#include "vtkStrokeConstraints.h"

#include "Geometry/ClosestPoint.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Harmonic/StrokeConstraints.h"
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

vtkStandardNewMacro(vtkStrokeConstraints);

struct vtkStrokeConstraints::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::ClosestPointLocator> locator;
  std::vector<kerf::Vector3> normals;
  std::vector<kerf::Vector3> strokePoints;
};

vtkStrokeConstraints::vtkStrokeConstraints()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
}

vtkStrokeConstraints::~vtkStrokeConstraints() = default;

void vtkStrokeConstraints::SetNumberOfStrokePoints(int count)
{
  if (count >= 0 && static_cast<std::size_t>(count) != this->State->strokePoints.size())
  {
    this->State->strokePoints.resize(static_cast<std::size_t>(count), kerf::Vector3::Zero());
    this->Modified();
  }
}

int vtkStrokeConstraints::GetNumberOfStrokePoints() const
{
  return static_cast<int>(this->State->strokePoints.size());
}

void vtkStrokeConstraints::SetStrokePoint(int index, double x, double y, double z)
{
  if (index < 0)
  {
    return;
  }
  if (static_cast<std::size_t>(index) >= this->State->strokePoints.size())
  {
    this->State->strokePoints.resize(static_cast<std::size_t>(index) + 1, kerf::Vector3::Zero());
  }
  const kerf::Vector3 p(x, y, z);
  if (this->State->strokePoints[static_cast<std::size_t>(index)] != p)
  {
    this->State->strokePoints[static_cast<std::size_t>(index)] = p;
    this->Modified();
  }
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
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* strokeInput = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  Internals& state = *this->State;

  if (!std::isfinite(this->IsoValue) || !(this->IsoValue + 1.0 > this->IsoValue) ||
    !(this->IsoValue - 1.0 < this->IsoValue))
  {
    vtkErrorMacro("IsoValue " << this->IsoValue
                              << " must be finite, and small enough that IsoValue +- 1 differ from it.");
    return 0;
  }
  if (!std::isfinite(this->MaximumProjectionDistance))
  {
    vtkErrorMacro("MaximumProjectionDistance must be a number (0 for no limit).");
    return 0;
  }

  kerf::MeshRequirements requirements;
  bool reused = false;
  std::string error;
  if (!state.surface.LoadIfChanged(input, requirements, error, reused))
  {
    vtkErrorMacro("Cannot place stroke constraints: " << error);
    return 0;
  }
  const kerf::TriangleMesh& mesh = state.surface.Mesh();
  if (!reused)
  {
    state.locator.reset(new kerf::ClosestPointLocator(mesh));
    state.normals = kerf::computeVertexNormals(mesh);
  }

  std::vector<std::vector<kerf::Vector3>> strokes;
  if (strokeInput)
  {
    auto lines = vtk::TakeSmartPointer(strokeInput->GetLines()->NewIterator());
    const vtkIdType pointCount = strokeInput->GetNumberOfPoints();
    for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      lines->GetCurrentCell(size, ids);
      std::vector<kerf::Vector3> stroke(static_cast<std::size_t>(size));
      for (vtkIdType k = 0; k < size; ++k)
      {
        if (ids[k] < 0 || ids[k] >= pointCount)
        {
          vtkErrorMacro("Stroke line " << lines->GetCurrentCellId() << " uses point " << ids[k]
                                       << ", but the stroke input has " << pointCount << " points.");
          return 0;
        }
        strokeInput->GetPoint(ids[k], stroke[static_cast<std::size_t>(k)].data());
      }
      strokes.push_back(std::move(stroke));
    }
    if (strokes.empty())
    {
      vtkErrorMacro("The stroke input holds no lines.");
      return 0;
    }
  }
  else if (!state.strokePoints.empty())
  {
    strokes.push_back(state.strokePoints);
  }
  else
  {
    vtkErrorMacro("No stroke: connect polylines to input 1 or set the stroke points.");
    return 0;
  }

  kerf::StrokeConstraintSet set;
  try
  {
    kerf::StrokeOptions options;
    const double diagonal = mesh.boundingBoxDiagonal();
    options.samplesPerSegment = this->SamplesPerSegment;
    options.offset = this->Offset * diagonal;
    options.isoValue = this->IsoValue;
    options.maximumDistance = this->MaximumProjectionDistance * diagonal;
    set = kerf::strokeConstraints(mesh, *state.locator, state.normals, strokes, options);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot place stroke constraints: " << e.what());
    return 0;
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkDoubleArray> values;
  values->SetName("ConstraintValue");
  vtkNew<vtkSignedCharArray> sides;
  sides->SetName("Side");
  for (std::size_t i = 0; i < set.constraints.size(); ++i)
  {
    const vtkIdType id = points->InsertNextPoint(set.positions[i].data());
    vertices->InsertNextCell(1, &id);
    values->InsertNextValue(set.constraints[i].value);
    sides->InsertNextValue(set.constraints[i].value > this->IsoValue ? 1 : -1);
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(values);
  output->GetPointData()->SetActiveScalars("ConstraintValue");
  output->GetPointData()->AddArray(sides);
  vtkNew<vtkDoubleArray> isoValue;
  isoValue->SetName("IsoValue");
  isoValue->InsertNextValue(this->IsoValue);
  output->GetFieldData()->AddArray(isoValue);
  return 1;
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
