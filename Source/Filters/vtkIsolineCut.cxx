// vtkIsolineCut: reads the field and the stroke, chooses the cut with the surface's session, writes it.
#include "vtkIsolineCut.h"

#include "Harmonic/HarmonicCutSession.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Numerics/FieldGradient.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTable.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkIsolineCut);

// The mode codes are the Core enumeration's values.
static_assert(static_cast<int>(kerf::CutMode::Value) == vtkIsolineCut::VALUE &&
    static_cast<int>(kerf::CutMode::BestScore) == vtkIsolineCut::BEST_SCORE &&
    static_cast<int>(kerf::CutMode::NearStroke) == vtkIsolineCut::NEAR_STROKE,
  "vtkIsolineCut's Modes follow kerf::CutMode");

struct vtkIsolineCut::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::HarmonicCutSession> session;
};

vtkIsolineCut::vtkIsolineCut()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(3);
  this->SetSegmentArrayName("Segment");
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "HarmonicField");
}

vtkIsolineCut::~vtkIsolineCut()
{
  this->SetSegmentArrayName(nullptr);
}

vtkPolyData* vtkIsolineCut::GetLabelledSurface()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

vtkTable* vtkIsolineCut::GetCandidates()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(2));
}

int vtkIsolineCut::FillInputPortInformation(int port, vtkInformation* info)
{
  return kerf::FillSurfaceAndOptionalPointsPorts(port, info);
}

int vtkIsolineCut::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 2 ? "vtkTable" : "vtkPolyData");
  return 1;
}

namespace
{
// Output 2: the candidates' values, scores and lengths (BEST_SCORE).
void writeCandidates(const kerf::CutResult& cut, vtkTable* table)
{
  std::vector<double> values, scores, lengths;
  for (const kerf::IsovalueScore& candidate : cut.candidates)
  {
    values.push_back(candidate.value);
    scores.push_back(candidate.score);
    lengths.push_back(candidate.length);
  }
  if (!cut.candidates.empty())
  {
    table->AddColumn(kerf::MakeArray("IsoValue", values));
    table->AddColumn(kerf::MakeArray("Score", scores));
    table->AddColumn(kerf::MakeArray("Length", lengths));
  }
}
} // namespace

int vtkIsolineCut::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot extract isolines", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPointSet* stroke = vtkPointSet::GetData(inputVector[1], 0);
    kerf::CheckOutputNames({ this->SegmentArrayName });
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    kerf::HarmonicCutSession& session = this->State->surface.SessionFor(this->State->session);

    kerf::CutOptions options;
    options.mode = static_cast<kerf::CutMode>(this->Mode);
    options.isoValue = this->IsoValue;
    options.candidateCount = this->NumberOfCandidates;
    if (this->Mode == NEAR_STROKE)
    {
      options.stroke = kerf::ReadPoints(stroke);
    }
    const std::vector<double> field = kerf::ReadInputArray(this, 0, input->GetNumberOfPoints(), "the surface");
    const kerf::CutResult cut = session.chooseCut(field, options);
    this->UpdateProgress(0.8);

    kerf::WriteCutLines(cut, vtkPolyData::GetData(outputVector, 0));
    vtkPolyData* labelled = vtkPolyData::GetData(outputVector, 1);
    this->State->surface.MakeOutput(input, labelled);
    labelled->GetCellData()->AddArray(kerf::MakeIntArray(this->SegmentArrayName, cut.labels));
    writeCandidates(cut, vtkTable::GetData(outputVector, 2));
  });
}

void vtkIsolineCut::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "NumberOfCandidates: " << this->NumberOfCandidates << "\n";
  os << indent << "SegmentArrayName: " << (this->SegmentArrayName ? this->SegmentArrayName : "(none)") << "\n";
}
