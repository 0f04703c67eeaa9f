// vtkStrokeConstraintAlgorithm: the stroke and sampling parameters shared by the filters that place a harmonic cut's
// constraints along strokes.
#include "vtkStrokeConstraintAlgorithm.h"

#include "KerfPanelPoints.h"

#include <vtkInformation.h>

vtkStrokeConstraintAlgorithm::vtkStrokeConstraintAlgorithm()
  : StrokePoints(new kerf::StrokePointList)
{
  this->SetNumberOfInputPorts(2);
}

vtkStrokeConstraintAlgorithm::~vtkStrokeConstraintAlgorithm() = default;

void vtkStrokeConstraintAlgorithm::SetNumberOfStrokePoints(int count)
{
  kerf::SetPanelPointCount(this, *this->StrokePoints, count, "stroke");
}

int vtkStrokeConstraintAlgorithm::GetNumberOfStrokePoints() const
{
  return this->StrokePoints->Count();
}

void vtkStrokeConstraintAlgorithm::SetStrokePoint(int index, double x, double y, double z)
{
  kerf::SetPanelPoint(this, *this->StrokePoints, index, kerf::Vector3(x, y, z), "stroke");
}

int vtkStrokeConstraintAlgorithm::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

void vtkStrokeConstraintAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplesPerSegment: " << this->SamplesPerSegment << "\n";
  os << indent << "Offset: " << this->Offset << "\n";
  os << indent << "OffsetLengthFraction: " << this->OffsetLengthFraction << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "StrokePoints: " << this->StrokePoints->Count() << "\n";
}
