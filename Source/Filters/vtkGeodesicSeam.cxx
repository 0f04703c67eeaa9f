// vtkGeodesicSeam: the cut lines and the target placed on the surface, the seam traced through the surface's
// SeamSession.
#include "vtkGeodesicSeam.h"

#include "Error.h"
#include "Geodesic/GeodesicSeam.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfPanelPoints.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkGeodesicSeam);

struct vtkGeodesicSeam::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::SeamSession> session;
  kerf::StrokePointList drawnPoints;
};

vtkGeodesicSeam::vtkGeodesicSeam()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->SetArrayName("SeamDistance");
}

vtkGeodesicSeam::~vtkGeodesicSeam()
{
  this->SetArrayName(nullptr);
}

vtkPolyData* vtkGeodesicSeam::GetSeam()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkGeodesicSeam::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

void vtkGeodesicSeam::SetNumberOfDrawnPoints(int count)
{
  kerf::SetPanelPointCount(this, this->State->drawnPoints, count, "clicked");
}

int vtkGeodesicSeam::GetNumberOfDrawnPoints() const
{
  return this->State->drawnPoints.Count();
}

void vtkGeodesicSeam::SetDrawnPoint(int index, double x, double y, double z)
{
  kerf::SetPanelPoint(this, this->State->drawnPoints, index, kerf::Vector3(x, y, z), "clicked");
}

int vtkGeodesicSeam::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot trace the seam", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->ArrayName });
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    kerf::SeamSession& session = this->State->surface.SessionFor(this->State->session);
    const kerf::Surface& surface = session.surface();
    const double maximumDistance =
      kerf::ProjectionLimit(this->MaximumProjectionDistance, surface, "MaximumProjectionDistance");
    vtkPolyData* lines = vtkPolyData::GetData(inputVector[1], 0);
    if (!lines)
    {
      throw kerf::Error("there is no cut line: connect polylines on the surface to input 1 (for example Stroke "
                        "Cut's cut)");
    }
    const std::vector<kerf::SurfaceCurve> curves =
      kerf::PlaceLinesOnSurface(surface, lines, maximumDistance, "the cut input");
    const kerf::Vector3 typed(this->TargetPoint[0], this->TargetPoint[1], this->TargetPoint[2]);
    const std::vector<kerf::Vector3>& clicked = this->State->drawnPoints.Points();
    const kerf::SurfacePoint target =
      kerf::PanelPointOnSurface(surface, clicked.empty() ? typed : clicked.back(), "the target point");
    this->UpdateProgress(0.1);

    kerf::SeamOptions options;
    options.metric.gamma = kerf::Finite(this->Gamma, "Gamma");
    options.depth = this->Depth;
    bool reused = false;
    const kerf::SeamField& field = session.field(curves, options, &reused);
    this->UpdateProgress(0.8);
    const kerf::SurfacePath seam = this->UseAnchor
      ? field.anchoredSeam(target,
          kerf::PanelPointOnSurface(surface,
            kerf::Vector3(this->AnchorPoint[0], this->AnchorPoint[1], this->AnchorPoint[2]), "the anchor point"))
      : field.seam(target);

    this->State->surface.MakeOutput(input, output);
    output->GetPointData()->AddArray(
      kerf::MakeArray(this->ArrayName, this->State->surface.ToInputPoints(field.distance())));
    output->GetPointData()->SetActiveScalars(this->ArrayName);
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("SeamWork", reused ? "regrowth" : "field"));
    kerf::WritePolylines(
      { { &seam.curve.points, seam.curve.closed, seam.length } }, vtkPolyData::GetData(outputVector, 1));
  });
}

void vtkGeodesicSeam::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetPoint: " << this->TargetPoint[0] << " " << this->TargetPoint[1] << " " << this->TargetPoint[2]
     << "\n";
  os << indent << "UseAnchor: " << this->UseAnchor << "\n";
  os << indent << "AnchorPoint: " << this->AnchorPoint[0] << " " << this->AnchorPoint[1] << " " << this->AnchorPoint[2]
     << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "Depth: " << this->Depth << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
}
