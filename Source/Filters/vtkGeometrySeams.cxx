// vtkGeometrySeams: reads the regions, runs kerf::computeGeometrySeams, writes the field, sectors, rings, costs and
// contours.
#include "vtkGeometrySeams.h"

#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "SeamCarving/GeometrySeams.h"

#include <vtkCellData.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkGeometrySeams);

static_assert(static_cast<int>(kerf::RingCandidateSearch::GlobalCutFirst) == vtkGeometrySeams::GLOBAL_CUT_FIRST &&
    static_cast<int>(kerf::RingCandidateSearch::Exhaustive) == vtkGeometrySeams::EXHAUSTIVE,
  "vtkGeometrySeams's CandidateSearches follow kerf::RingCandidateSearch");

struct vtkGeometrySeams::Internals
{
  kerf::SurfaceInput surface;
};

vtkGeometrySeams::vtkGeometrySeams()
  : State(new Internals)
{
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Region");
  this->SetHarmonicFieldArrayName("HarmonicField");
  this->SetSectorArrayName("Sector");
  this->SetRingSeamArrayName("RingSeam");
  this->SetEdgeCostArrayName("EdgeCost");
}

vtkGeometrySeams::~vtkGeometrySeams()
{
  this->SetHarmonicFieldArrayName(nullptr);
  this->SetSectorArrayName(nullptr);
  this->SetRingSeamArrayName(nullptr);
  this->SetEdgeCostArrayName(nullptr);
}

vtkPolyData* vtkGeometrySeams::GetContours()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkGeometrySeams::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot compute geometry seams", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames(
      { this->HarmonicFieldArrayName, this->SectorArrayName, this->RingSeamArrayName, this->EdgeCostArrayName });
    // The isolines need an oriented 2-manifold; a border or other components may lie outside the
    // modeling region.
    kerf::MeshRequirements requirements;
    requirements.manifold = true;
    requirements.consistentOrientation = true;
    kerf::SurfaceInput& surface = this->State->surface;
    kerf::LoadSurface(surface, input, requirements);
    const std::vector<double> region = kerf::ReadInputArray(this, 0, input->GetNumberOfPoints(), "the surface");

    kerf::GeometrySeamsOptions options;
    options.ringCount = this->NumberOfRings;
    options.isoContourCount = this->NumberOfIsoContours;
    options.sectorCount = this->NumberOfSectors;
    options.alpha = this->Alpha;
    options.beta = this->Beta;
    options.gamma = this->Gamma;
    options.search = static_cast<kerf::RingCandidateSearch>(this->CandidateSearch);
    options.ringDone = [this](int done) { this->UpdateProgress(0.2 + 0.75 * done / this->NumberOfRings); };
    const std::vector<double>& angle = surface.GetSurface().descriptors().normalConeAngle;
    this->UpdateProgress(0.1);
    const kerf::GeometrySeamsResult result = kerf::computeGeometrySeams(surface.Mesh(), region, angle, options);

    surface.MakeOutput(input, output);
    output->GetPointData()->AddArray(
      kerf::MakeArray(this->HarmonicFieldArrayName, surface.ToInputPoints(result.harmonicField)));
    output->GetPointData()->SetActiveScalars(this->HarmonicFieldArrayName);
    output->GetPointData()->AddArray(kerf::MakeIntArray(this->SectorArrayName, surface.ToInputPoints(result.sector)));
    output->GetCellData()->AddArray(kerf::MakeIntArray(this->SectorArrayName, result.faceSector));
    output->GetCellData()->AddArray(kerf::MakeIntArray(this->RingSeamArrayName, result.ring));
    output->GetCellData()->AddArray(kerf::MakeArray(this->EdgeCostArrayName, result.faceCost));
    output->GetFieldData()->AddArray(kerf::MakeFieldValue("RingCount", static_cast<double>(result.ringCost.size())));

    vtkPolyData* contours = vtkPolyData::GetData(outputVector, 1);
    std::vector<kerf::PolylineToWrite> lines;
    std::vector<int> kinds, indices;
    for (const kerf::SeamContour& contour : result.contours)
    {
      lines.push_back({ &contour.points, contour.closed, contour.length });
      kinds.push_back(static_cast<int>(contour.kind));
      indices.push_back(contour.index);
    }
    kerf::WritePolylines(lines, contours);
    contours->GetCellData()->AddArray(kerf::MakeIntArray("Kind", kinds));
    contours->GetCellData()->AddArray(kerf::MakeIntArray("ContourIndex", indices));
  });
}

void vtkGeometrySeams::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto show = [](const char* s) { return s ? s : "(none)"; };
  os << indent << "NumberOfRings: " << this->NumberOfRings << "\n";
  os << indent << "NumberOfIsoContours: " << this->NumberOfIsoContours << "\n";
  os << indent << "NumberOfSectors: " << this->NumberOfSectors << "\n";
  os << indent << "Alpha: " << this->Alpha << "\n";
  os << indent << "Beta: " << this->Beta << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "CandidateSearch: " << this->CandidateSearch << "\n";
  os << indent << "HarmonicFieldArrayName: " << show(this->HarmonicFieldArrayName) << "\n";
  os << indent << "SectorArrayName: " << show(this->SectorArrayName) << "\n";
  os << indent << "RingSeamArrayName: " << show(this->RingSeamArrayName) << "\n";
  os << indent << "EdgeCostArrayName: " << show(this->EdgeCostArrayName) << "\n";
}
