// vtkDiscClickAlgorithm: the click and radius parameters shared by the filters with geodesic discs.
#include "vtkDiscClickAlgorithm.h"

#include "KerfDrawnInput.h"
#include "KerfFilterBorder.h"

vtkDiscClickAlgorithm::vtkDiscClickAlgorithm()
  : DrawnDiscs(new kerf::DrawnDiscList)
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

void vtkDiscClickAlgorithm::SetNumberOfDrawnDiscs(int count)
{
  kerf::SetPanelDiscCount(this, *this->DrawnDiscs, count);
}

int vtkDiscClickAlgorithm::GetNumberOfDrawnDiscs() const
{
  return this->DrawnDiscs->Count();
}

void vtkDiscClickAlgorithm::SetDrawnDisc(int index, double x, double y, double z, double radius, double subtract)
{
  kerf::SetPanelDisc(this, *this->DrawnDiscs, index, { x, y, z, radius, subtract });
}

void vtkDiscClickAlgorithm::AddDrawnDisc(double x, double y, double z, double radius, bool subtract)
{
  this->SetDrawnDisc(this->DrawnDiscs->Count(), x, y, z, radius, subtract ? 1.0 : 0.0);
}

void vtkDiscClickAlgorithm::RemoveAllDrawnDiscs()
{
  this->SetNumberOfDrawnDiscs(0);
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
  os << indent << "ClickRadiusArrayName: " << (this->ClickRadiusArrayName ? this->ClickRadiusArrayName : "(none)")
     << "\n";
  os << indent << "DrawnDiscs: " << this->DrawnDiscs->Count() << "\n";
  os << indent << "ClickSubtractArrayName: " << (this->ClickSubtractArrayName ? this->ClickSubtractArrayName : "(none)")
     << "\n";
}
