// vtkStrokeGrowingAlgorithm: the stroke and metric parameters, ports and boundary output shared by the filters that
// grow parts from labelled strokes.
#include "vtkStrokeGrowingAlgorithm.h"

#include <vtkInformation.h>
#include <vtkPolyData.h>

vtkStrokeGrowingAlgorithm::vtkStrokeGrowingAlgorithm()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->SetStrokeLabelArrayName("Label");
  this->SetSegmentArrayName("Segment");
}

vtkStrokeGrowingAlgorithm::~vtkStrokeGrowingAlgorithm()
{
  this->SetStrokeLabelArrayName(nullptr);
  this->SetSegmentArrayName(nullptr);
}

vtkPolyData* vtkStrokeGrowingAlgorithm::GetBoundary()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkStrokeGrowingAlgorithm::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port >= 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

void vtkStrokeGrowingAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NormalWeight: " << this->NormalWeight << "\n";
  os << indent << "CurvatureWeight: " << this->CurvatureWeight << "\n";
  os << indent << "CurvatureAugmentation: " << this->CurvatureAugmentation << "\n";
  os << indent << "CurvaturePerEdge: " << this->CurvaturePerEdge << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "BoundaryPlacement: " << this->BoundaryPlacement << "\n";
  os << indent << "CutBand: " << this->CutBand << "\n";
  os << indent << "StrokeLabelArrayName: " << (this->StrokeLabelArrayName ? this->StrokeLabelArrayName : "(none)")
     << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
