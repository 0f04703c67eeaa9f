// vtkGeodesicPolyline: the points placed on the surface, kerf::geodesicPolyline through them, the polyline and its
// arrays out.
#include "vtkGeodesicPolyline.h"

#include "Error.h"
#include "Geodesic/GeodesicPaths.h"
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
#include <vtkPointSet.h>
#include <vtkPolyData.h>

#include <string>
#include <vector>

vtkStandardNewMacro(vtkGeodesicPolyline);

struct vtkGeodesicPolyline::Internals
{
  kerf::SurfaceInput surface;
  kerf::StrokePointList pathPoints;
  kerf::StrokePointList drawnPoints;
  kerf::GeodesicLegCache legs; // moving one point retraces only its two legs
};

vtkGeodesicPolyline::vtkGeodesicPolyline()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
}

vtkGeodesicPolyline::~vtkGeodesicPolyline() = default;

void vtkGeodesicPolyline::SetNumberOfPathPoints(int count)
{
  kerf::SetPanelPointCount(this, this->State->pathPoints, count, "path");
}

int vtkGeodesicPolyline::GetNumberOfPathPoints() const
{
  return this->State->pathPoints.Count();
}

void vtkGeodesicPolyline::SetPathPoint(int index, double x, double y, double z)
{
  kerf::SetPanelPoint(this, this->State->pathPoints, index, kerf::Vector3(x, y, z), "path");
}

void vtkGeodesicPolyline::SetNumberOfDrawnPoints(int count)
{
  kerf::SetPanelPointCount(this, this->State->drawnPoints, count, "clicked");
}

int vtkGeodesicPolyline::GetNumberOfDrawnPoints() const
{
  return this->State->drawnPoints.Count();
}

void vtkGeodesicPolyline::SetDrawnPoint(int index, double x, double y, double z)
{
  kerf::SetPanelPoint(this, this->State->drawnPoints, index, kerf::Vector3(x, y, z), "clicked");
}

int vtkGeodesicPolyline::FillInputPortInformation(int port, vtkInformation* info)
{
  return kerf::FillSurfaceAndOptionalPointsPorts(port, info);
}

int vtkGeodesicPolyline::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot trace the geodesic path", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    const kerf::Surface& surface = this->State->surface.GetSurface();

    std::vector<kerf::SurfacePoint> points;
    vtkPointSet* pointInput = vtkPointSet::GetData(inputVector[1], 0);
    if (pointInput)
    {
      points = kerf::ProjectPointsOntoSurface(surface, pointInput,
        kerf::ProjectionLimit(this->MaximumProjectionDistance, surface, "MaximumProjectionDistance"), "path point");
    }
    else
    {
      const kerf::StrokePointList& panel =
        this->State->drawnPoints.Count() > 0 ? this->State->drawnPoints : this->State->pathPoints;
      for (const kerf::Vector3& point : panel.Points())
      {
        points.push_back(kerf::PanelPointOnSurface(surface, point, "path point " + std::to_string(points.size())));
      }
    }
    if (points.empty())
    {
      throw kerf::Error(pointInput ? "the point input holds no point"
                                   : "there are no path points: click them on the surface (in ParaView: hold Ctrl and "
                                     "click), type them (PathPoints) or connect points to the Points input");
    }
    this->UpdateProgress(0.1);

    kerf::GeodesicPathOptions options;
    options.vectorDijkstra = this->Metric == ANISOTROPIC;
    options.metric.gamma = this->Metric == ANISOTROPIC ? kerf::Finite(this->Gamma, "Gamma") : 0.0;
    options.depth = this->Depth;
    const kerf::GeodesicPolyline path =
      kerf::geodesicPolyline(surface, points, this->ClosedLoop, options, &this->State->legs);

    const kerf::SurfaceCurve& curve = path.path.curve;
    kerf::WritePolylines({ { &curve.points, curve.closed, path.path.length } }, output);
    std::vector<int> faces(curve.points.size());
    std::vector<int> pathPoints(curve.points.size(), -1);
    const std::vector<vtkIdType>& inputCells = this->State->surface.SourceCells();
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
      faces[i] = static_cast<int>(inputCells[curve.faces[std::min(i, curve.faces.size() - 1)]]);
    }
    for (std::size_t k = 0; k < path.waypoints.size(); ++k)
    {
      pathPoints[path.waypoints[k]] = static_cast<int>(k);
    }
    output->GetPointData()->AddArray(kerf::MakeArray("ArcLength", path.arcLength));
    output->GetPointData()->AddArray(kerf::MakeIntArray("Face", faces));
    output->GetPointData()->AddArray(kerf::MakeIntArray("PathPoint", pathPoints));
    output->GetPointData()->SetActiveScalars("ArcLength");
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("TotalLength", path.path.length));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("SelfCrossings", static_cast<double>(path.selfCrossings)));
    output->GetFieldData()->AddArray(
      kerf::MakeFieldValue("LegsTraced", static_cast<double>(this->State->legs.computed())));
  });
}

void vtkGeodesicPolyline::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PathPoints: " << this->State->pathPoints.Count() << "\n";
  os << indent << "Metric: " << (this->Metric == ANISOTROPIC ? "anisotropic" : "isotropic") << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "Depth: " << this->Depth << "\n";
  os << indent << "ClosedLoop: " << this->ClosedLoop << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
}
