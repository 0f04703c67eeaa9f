// vtkSegmentationMetrics: reads two label arrays, checks them, calls kerf::SegmentationEvaluator.
#include "vtkSegmentationMetrics.h"

#include "Error.h"
#include "Evaluation/SegmentationMetrics.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfSurfaceInput.h"

#include <vtkAlgorithmOutput.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <cmath>
#include <limits>
#include <string>

vtkStandardNewMacro(vtkSegmentationMetrics);

struct vtkSegmentationMetrics::Internals
{
  kerf::SurfaceInput surface;
};

namespace
{
bool sameMesh(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() || a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return false;
  }
  const double tolerance = 1e-9 * std::max(a->GetLength(), 1e-300);
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (std::abs(p[0] - q[0]) > tolerance || std::abs(p[1] - q[1]) > tolerance || std::abs(p[2] - q[2]) > tolerance)
    {
      return false;
    }
  }
  return true;
}

void addColumn(vtkTable* table, const char* name, double value)
{
  vtkNew<vtkDoubleArray> column;
  column->SetName(name);
  column->InsertNextValue(value);
  table->AddColumn(column);
}
} // namespace

vtkSegmentationMetrics::vtkSegmentationMetrics()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Segment");
  this->SetInputArrayToProcess(1, 1, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Segment");
}

vtkSegmentationMetrics::~vtkSegmentationMetrics() = default;

int vtkSegmentationMetrics::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkSegmentationMetrics::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot compare segmentations", [&]() {
    vtkPolyData* mesh = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* reference = vtkPolyData::GetData(inputVector[1], 0);
    vtkTable* output = vtkTable::GetData(outputVector, 0);

    vtkInformation* referenceArrayInfo = this->GetInputArrayInformation(1);
    const int referencePort = referenceArrayInfo->Has(INPUT_PORT()) ? referenceArrayInfo->Get(INPUT_PORT()) : 1;
    if (referencePort == 1 && !reference)
    {
      throw kerf::Error("the reference segmentation is read from input 1, which is not connected: "
                        "connect a second mesh or select the reference array on input 0");
    }
    if (reference && !sameMesh(mesh, reference))
    {
      throw kerf::Error("the two inputs are different meshes (" + std::to_string(mesh->GetNumberOfPoints()) +
        " points, " + std::to_string(mesh->GetNumberOfCells()) + " cells against " +
        std::to_string(reference->GetNumberOfPoints()) + " points, " + std::to_string(reference->GetNumberOfCells()) +
        " cells, or points that differ)");
    }

    // The metrics need no manifold: benchmark meshes may have any defect but NaN coordinates.
    kerf::MeshRequirements requirements;
    requirements.manifold = false;
    requirements.consistentOrientation = false;
    requirements.allowDuplicateFaces = true;
    kerf::SurfaceInput& surface = this->State->surface;
    kerf::LoadSurface(surface, mesh, requirements);
    const std::vector<int> evaluated =
      kerf::ReadTriangleLabels(this, 0, surface, mesh->GetNumberOfCells(), "the evaluated segmentation");
    const std::vector<int> referenceLabels =
      kerf::ReadTriangleLabels(this, 1, surface, mesh->GetNumberOfCells(), "the reference segmentation");
    this->UpdateProgress(0.3);

    const kerf::SegmentationEvaluator evaluator(surface.Mesh());
    const kerf::SegmentationScores scores =
      evaluator.compare(evaluator.prepare(evaluated), evaluator.prepare(referenceLabels));
    addColumn(output, "CutDiscrepancy", scores.cutDiscrepancy);
    addColumn(output, "CutDiscrepancyEvaluatedToReference", scores.directionalCutDiscrepancy12);
    addColumn(output, "CutDiscrepancyReferenceToEvaluated", scores.directionalCutDiscrepancy21);
    addColumn(output, "HammingDistance", scores.hammingDistance);
    addColumn(output, "MissingRate", scores.missingRate);
    addColumn(output, "FalseAlarmRate", scores.falseAlarmRate);
    addColumn(output, "RandIndexError", scores.randIndexError);
    addColumn(output, "GlobalConsistencyError", scores.globalConsistencyError);
    addColumn(output, "LocalConsistencyError", scores.localConsistencyError);
    addColumn(output, "EvaluatedSegments", scores.segments1);
    addColumn(output, "ReferenceSegments", scores.segments2);
    addColumn(output, "ComparedFaces", scores.comparedFaces);
    addColumn(output, "CutsCompared", scores.cutsCompared ? 1.0 : 0.0);
  });
}

void vtkSegmentationMetrics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
