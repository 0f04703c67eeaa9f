// vtkROIScissor: clicks placed on the surface, ROI Scissor through the Core with the surface's click distances kept, labels and boundary out.
#include "vtkROIScissor.h"

#include "Error.h"
#include "Geodesic/RoiScissor.h"
#include "KerfFilterUtilities.h"
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

#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkROIScissor);

struct vtkROIScissor::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::ClickDistances> clickDistances;
};

vtkROIScissor::vtkROIScissor()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->SetRegionArrayName("RoiRegion");
  this->SetClickRadiusArrayName("Radius");
  this->SetClickSubtractArrayName("Subtract");
}

vtkROIScissor::~vtkROIScissor()
{
  this->SetRegionArrayName(nullptr);
  this->SetClickRadiusArrayName(nullptr);
  this->SetClickSubtractArrayName(nullptr);
}

vtkPolyData* vtkROIScissor::GetBoundary()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkROIScissor::FillInputPortInformation(int port, vtkInformation* info)
{
  return kerf::FillSurfaceAndOptionalPointsPorts(port, info);
}

int vtkROIScissor::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot select the region", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->RegionArrayName });
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    kerf::ClickDistances& distances = this->State->surface.SessionFor(this->State->clickDistances);
    const double diagonal = distances.surface().mesh().boundingBoxDiagonal();
    const double radius = kerf::Finite(this->AbsoluteRadius, "AbsoluteRadius") > 0.0
      ? this->AbsoluteRadius
      : kerf::RelativeDistance(this->Radius, diagonal, "Radius");

    std::vector<kerf::RoiClick> clicks, subtracted;
    vtkPointSet* clickInput = vtkPointSet::GetData(inputVector[1], 0);
    if (clickInput)
    {
      const std::vector<kerf::Vector3> points = kerf::ReadPoints(clickInput);
      // Optional per-click arrays: read when the input has them.
      const auto optional = [&](const char* name) {
        return name && *name && clickInput->GetPointData()->GetAbstractArray(name)
          ? kerf::ReadNamedPointArray(clickInput, name, "the clicks")
          : std::vector<double>();
      };
      const std::vector<double> radii = optional(this->ClickRadiusArrayName);
      const std::vector<double> subtract = optional(this->ClickSubtractArrayName);
      for (std::size_t i = 0; i < points.size(); ++i)
      {
        if (!radii.empty() && !(std::isfinite(radii[i]) && radii[i] > 0.0))
        {
          throw kerf::Error("click " + std::to_string(i) + " has the radius " + std::to_string(radii[i]) +
            "; radii are positive fractions of the diagonal");
        }
        const double r = radii.empty() ? radius : radii[i] * diagonal;
        (!subtract.empty() && subtract[i] != 0.0 ? subtracted : clicks).push_back({ points[i], r });
      }
      if (clicks.empty() && !subtracted.empty())
      {
        throw kerf::Error("every click subtracts its disc: at least one click must add one");
      }
    }
    else
    {
      const kerf::SurfacePoint click = kerf::PanelPointOnSurface(distances.surface(),
        kerf::Vector3(this->ClickPoint[0], this->ClickPoint[1], this->ClickPoint[2]), "the click point");
      clicks.push_back({ kerf::surfacePosition(distances.surface().mesh(), click), radius });
    }
    if (clicks.empty())
    {
      throw kerf::Error("the click input holds no point");
    }
    kerf::RoiScissorOptions options;
    options.innerFraction = kerf::Finite(this->InnerFraction, "InnerFraction");
    options.isolineCount = this->IsolineCount;
    options.segmentFraction = kerf::Finite(this->SegmentFraction, "SegmentFraction");
    options.paths.metric.gamma = kerf::Finite(this->Gamma, "Gamma");
    options.clickTolerance = kerf::Finite(this->MaximumProjectionDistance, "MaximumProjectionDistance") > 0.0
      ? this->MaximumProjectionDistance
      : std::numeric_limits<double>::infinity();
    this->UpdateProgress(0.1);
    const kerf::RoiScissorResult result = kerf::roiScissor(distances.surface(), clicks, subtracted, options, &distances);
    this->UpdateProgress(0.9);

    const kerf::SurfaceInput& surface = this->State->surface;
    surface.MakeOutput(input, output);
    output->GetCellData()->AddArray(kerf::MakeIntArray(this->RegionArrayName, result.faceLabels));
    output->GetCellData()->SetActiveScalars(this->RegionArrayName);
    output->GetPointData()->AddArray(kerf::MakeArray("RoiField", surface.ToInputPoints(result.field)));
    output->GetPointData()->AddArray(kerf::MakeArray("RoiCandidate", surface.ToInputPoints(
      std::vector<unsigned char>(result.candidate.begin(), result.candidate.end()))));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("IsoValue", result.isovalue));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("Score", result.score));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("BoundaryEncloses", result.boundaryEncloses ? 1.0 : 0.0));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("ClickDistanceFields", static_cast<double>(distances.computations())));

    std::vector<kerf::PolylineToWrite> loops;
    std::vector<int> selfCrossings;
    for (const kerf::GeodesicLoop& loop : result.boundaries)
    {
      loops.push_back({ &loop.path.curve.points, loop.path.curve.closed, loop.path.length });
      selfCrossings.push_back(loop.selfCrossings);
    }
    vtkPolyData* boundary = vtkPolyData::GetData(outputVector, 1);
    kerf::WritePolylines(loops, boundary);
    boundary->GetCellData()->AddArray(kerf::MakeIntArray("SelfCrossings", selfCrossings));
  });
}

void vtkROIScissor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ClickPoint: " << this->ClickPoint[0] << " " << this->ClickPoint[1] << " " << this->ClickPoint[2]
     << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "AbsoluteRadius: " << this->AbsoluteRadius << "\n";
  os << indent << "InnerFraction: " << this->InnerFraction << "\n";
  os << indent << "IsolineCount: " << this->IsolineCount << "\n";
  os << indent << "SegmentFraction: " << this->SegmentFraction << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "RegionArrayName: " << (this->RegionArrayName ? this->RegionArrayName : "(none)") << "\n";
  os << indent << "ClickRadiusArrayName: " << (this->ClickRadiusArrayName ? this->ClickRadiusArrayName : "(none)") << "\n";
  os << indent << "ClickSubtractArrayName: " << (this->ClickSubtractArrayName ? this->ClickSubtractArrayName : "(none)") << "\n";
}
