// vtkGeodesicDistance: sources placed on the surface, the heat method or Vector Dijkstra through the Core, one array
// out.
#include "vtkGeodesicDistance.h"

#include "Error.h"
#include "Geodesic/GeodesicPaths.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfPanelPoints.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"

#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkGeodesicDistance);

static_assert(static_cast<int>(kerf::HeatBoundaryCondition::Neumann) == vtkGeodesicDistance::NEUMANN &&
    static_cast<int>(kerf::HeatBoundaryCondition::Dirichlet) == vtkGeodesicDistance::DIRICHLET &&
    static_cast<int>(kerf::HeatBoundaryCondition::Mean) == vtkGeodesicDistance::MEAN,
  "vtkGeodesicDistance's BoundaryConditions follow kerf::HeatBoundaryCondition");

struct vtkGeodesicDistance::Internals
{
  kerf::SurfaceInput surface;
};

vtkGeodesicDistance::vtkGeodesicDistance()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetArrayName("GeodesicDistance");
}

vtkGeodesicDistance::~vtkGeodesicDistance()
{
  this->SetArrayName(nullptr);
}

int vtkGeodesicDistance::FillInputPortInformation(int port, vtkInformation* info)
{
  return kerf::FillSurfaceAndOptionalPointsPorts(port, info);
}

int vtkGeodesicDistance::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot compute the geodesic distance", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->ArrayName });
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    const kerf::Surface& surface = this->State->surface.GetSurface();
    const double maximumDistance =
      kerf::ProjectionLimit(this->MaximumProjectionDistance, surface, "MaximumProjectionDistance");

    kerf::GeodesicSource source;
    vtkPointSet* sources = vtkPointSet::GetData(inputVector[1], 0);
    if (sources)
    {
      source.points = kerf::ProjectPointsOntoSurface(surface, sources, maximumDistance, "source point");
      vtkPolyData* lines = vtkPolyData::SafeDownCast(sources);
      if (lines && lines->GetNumberOfLines() > 0)
      {
        source.curves = kerf::PlaceLinesOnSurface(surface, lines, maximumDistance, "the source input");
      }
      if (source.empty())
      {
        throw kerf::Error("the source input holds no point");
      }
    }
    else
    {
      source.points.push_back(kerf::PanelPointOnSurface(
        surface, kerf::Vector3(this->SourcePoint[0], this->SourcePoint[1], this->SourcePoint[2]), "the source point"));
    }
    this->UpdateProgress(0.1);

    kerf::GeodesicPathOptions options;
    options.metric.gamma = kerf::Finite(this->Gamma, "Gamma");
    options.depth = this->Depth;
    options.heat.timeFactor = kerf::Finite(this->TimeFactor, "TimeFactor");
    options.heat.boundary = static_cast<kerf::HeatBoundaryCondition>(this->BoundaryCondition);
    const kerf::GeodesicDistance distance = kerf::geodesicDistance(surface, source, options);

    this->State->surface.MakeOutput(input, output);
    output->GetPointData()->AddArray(
      kerf::MakeArray(this->ArrayName, this->State->surface.ToInputPoints(distance.distance)));
    output->GetPointData()->SetActiveScalars(this->ArrayName);
  });
}

void vtkGeodesicDistance::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SourcePoint: " << this->SourcePoint[0] << " " << this->SourcePoint[1] << " " << this->SourcePoint[2]
     << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "Depth: " << this->Depth << "\n";
  os << indent << "TimeFactor: " << this->TimeFactor << "\n";
  os << indent << "BoundaryCondition: " << this->BoundaryCondition << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(none)") << "\n";
}
