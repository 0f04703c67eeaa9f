// vtkGeodesicDisc: clicks placed on the surface, their geodesic discs united and subtracted through the Core, region
// and distance out.
#include "vtkGeodesicDisc.h"

#include "Geodesic/ROIScissor.h"
#include "KerfDrawnInput.h"
#include "KerfFilterBorder.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

vtkStandardNewMacro(vtkGeodesicDisc);

struct vtkGeodesicDisc::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::ClickDistances> clickDistances;
};

vtkGeodesicDisc::vtkGeodesicDisc()
  : State(new Internals)
{
  this->SetRegionArrayName("GeodesicDisc");
  this->SetDistanceArrayName("ClickDistance");
}

vtkGeodesicDisc::~vtkGeodesicDisc()
{
  this->SetRegionArrayName(nullptr);
  this->SetDistanceArrayName(nullptr);
}

int vtkGeodesicDisc::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot compute the geodesic discs", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->RegionArrayName, this->DistanceArrayName });
    kerf::CheckDifferentNames(this->RegionArrayName, this->DistanceArrayName, "point arrays");
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    kerf::ClickDistances& distances = this->State->surface.SessionFor(this->State->clickDistances);
    const kerf::DiscClicks clicks =
      kerf::ReadDiscClicks(distances.surface(), this, *this->DrawnDiscs, vtkPointSet::GetData(inputVector[1], 0));
    this->UpdateProgress(0.1);
    const kerf::GeodesicDiscs discs = kerf::geodesicDiscs(
      distances.surface(), clicks.added, clicks.subtracted, clicks.tolerance, kerf::HeatGeodesicOptions(), &distances);
    this->UpdateProgress(0.9);

    const kerf::SurfaceInput& surface = this->State->surface;
    surface.MakeOutput(input, output);
    output->GetPointData()->AddArray(kerf::MakeArray(this->RegionArrayName,
      surface.ToInputPoints(std::vector<unsigned char>(discs.vertices.begin(), discs.vertices.end()))));
    output->GetPointData()->SetActiveScalars(this->RegionArrayName);
    output->GetPointData()->AddArray(
      kerf::MakeArray(this->DistanceArrayName, surface.ToInputPoints(discs.nearestAdded)));
    output->GetCellData()->AddArray(
      kerf::MakeArray(this->RegionArrayName, std::vector<unsigned char>(discs.faces.begin(), discs.faces.end())));
    kerf::WriteSegmentSizes(std::vector<int>(discs.faces.begin(), discs.faces.end()), output);
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("RegionArea", discs.area));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("RegionAreaFraction", discs.area / discs.surfaceArea));
    output->GetFieldData()->AddArray(
      kerf::MakeFieldValue("ClickDistanceFields", static_cast<double>(distances.computations())));
  });
}

void vtkGeodesicDisc::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RegionArrayName: " << (this->RegionArrayName ? this->RegionArrayName : "(none)") << "\n";
  os << indent << "DistanceArrayName: " << (this->DistanceArrayName ? this->DistanceArrayName : "(none)") << "\n";
}
