// vtkROIScissor: clicks placed on the surface, ROI Scissor through the Core with the surface's click distances kept,
// labels and boundary out.
#include "vtkROIScissor.h"

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

vtkStandardNewMacro(vtkROIScissor);

struct vtkROIScissor::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::ClickDistances> clickDistances;
};

vtkROIScissor::vtkROIScissor()
  : State(new Internals)
{
  this->SetNumberOfOutputPorts(2);
  this->SetRegionArrayName("RoiRegion");
}

vtkROIScissor::~vtkROIScissor()
{
  this->SetRegionArrayName(nullptr);
}

vtkPolyData* vtkROIScissor::GetBoundary()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkROIScissor::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot select the region", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->RegionArrayName });
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    kerf::ClickDistances& distances = this->State->surface.SessionFor(this->State->clickDistances);
    const kerf::DiscClicks clicks =
      kerf::ReadDiscClicks(distances.surface(), this, *this->DrawnDiscs, vtkPointSet::GetData(inputVector[1], 0));
    kerf::ROIScissorOptions options;
    options.innerFraction = kerf::Finite(this->InnerFraction, "InnerFraction");
    options.isolineCount = this->IsolineCount;
    options.segmentFraction = kerf::Finite(this->SegmentFraction, "SegmentFraction");
    options.paths.metric.gamma = kerf::Finite(this->Gamma, "Gamma");
    options.clickTolerance = clicks.tolerance;
    this->UpdateProgress(0.1);
    const kerf::ROIScissorResult result =
      kerf::roiScissor(distances.surface(), clicks.added, clicks.subtracted, options, &distances);
    this->UpdateProgress(0.9);

    const kerf::SurfaceInput& surface = this->State->surface;
    surface.MakeOutput(input, output);
    output->GetCellData()->AddArray(kerf::MakeIntArray(this->RegionArrayName, result.faceLabels));
    kerf::WriteSegmentSizes(result.faceLabels, output);
    output->GetCellData()->SetActiveScalars(this->RegionArrayName);
    output->GetPointData()->AddArray(kerf::MakeArray("RoiField", surface.ToInputPoints(result.field)));
    output->GetPointData()->AddArray(kerf::MakeArray("RoiCandidate",
      surface.ToInputPoints(std::vector<unsigned char>(result.candidate.begin(), result.candidate.end()))));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("IsoValue", result.isovalue));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("Score", result.score));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("BoundaryEncloses", result.boundaryEncloses ? 1.0 : 0.0));
    output->GetFieldData()->AddArray(
      kerf::MakeFieldValue("ClickDistanceFields", static_cast<double>(distances.computations())));

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
  os << indent << "InnerFraction: " << this->InnerFraction << "\n";
  os << indent << "IsolineCount: " << this->IsolineCount << "\n";
  os << indent << "SegmentFraction: " << this->SegmentFraction << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "RegionArrayName: " << (this->RegionArrayName ? this->RegionArrayName : "(none)") << "\n";
}
