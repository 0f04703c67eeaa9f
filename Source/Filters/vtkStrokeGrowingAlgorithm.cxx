// vtkStrokeGrowingAlgorithm: the stroke and metric parameters shared by the filters that grow parts from labelled strokes.
#include "vtkStrokeGrowingAlgorithm.h"

vtkStrokeGrowingAlgorithm::vtkStrokeGrowingAlgorithm()
{
  this->SetStrokeLabelArrayName("Label");
  this->SetSegmentArrayName("Segment");
}

vtkStrokeGrowingAlgorithm::~vtkStrokeGrowingAlgorithm()
{
  this->SetStrokeLabelArrayName(nullptr);
  this->SetSegmentArrayName(nullptr);
}

void vtkStrokeGrowingAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NormalWeight: " << this->NormalWeight << "\n";
  os << indent << "CurvatureWeight: " << this->CurvatureWeight << "\n";
  os << indent << "CurvatureAugmentation: " << this->CurvatureAugmentation << "\n";
  os << indent << "CurvaturePerEdge: " << this->CurvaturePerEdge << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "StrokeLabelArrayName: " << (this->StrokeLabelArrayName ? this->StrokeLabelArrayName : "(none)") << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
