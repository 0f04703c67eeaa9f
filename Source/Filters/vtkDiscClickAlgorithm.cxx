// vtkDiscClickAlgorithm: the click and radius parameters shared by the filters with geodesic discs.
#include "vtkDiscClickAlgorithm.h"

#include "KerfFilterUtilities.h"

vtkDiscClickAlgorithm::vtkDiscClickAlgorithm()
{
  this->SetNumberOfInputPorts(2);
  this->SetClickRadiusArrayName("Radius");
  this->SetClickSubtractArrayName("Subtract");
}

vtkDiscClickAlgorithm::~vtkDiscClickAlgorithm()
{
  this->SetClickRadiusArrayName(nullptr);
  this->SetClickSubtractArrayName(nullptr);
}

int vtkDiscClickAlgorithm::FillInputPortInformation(int port, vtkInformation* info)
{
  return kerf::FillSurfaceAndOptionalPointsPorts(port, info);
}

void vtkDiscClickAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ClickPoint: " << this->ClickPoint[0] << " " << this->ClickPoint[1] << " " << this->ClickPoint[2]
     << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "AbsoluteRadius: " << this->AbsoluteRadius << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "ClickRadiusArrayName: " << (this->ClickRadiusArrayName ? this->ClickRadiusArrayName : "(none)") << "\n";
  os << indent << "ClickSubtractArrayName: " << (this->ClickSubtractArrayName ? this->ClickSubtractArrayName : "(none)") << "\n";
}
