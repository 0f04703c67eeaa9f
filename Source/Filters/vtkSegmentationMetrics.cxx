// vtkSegmentationMetrics: reads two label arrays, checks them, calls kerf::SegmentationEvaluator.
#include "vtkSegmentationMetrics.h"

#include "Evaluation/SegmentationMetrics.h"
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

namespace
{
// Per-triangle labels from a per-cell array, or an error sentence.
std::string triangleLabels(vtkDataArray* array, const kerf::SurfaceInput& surface, vtkIdType cells,
  const char* role, std::vector<int>& labels)
{
  if (!array)
  {
    return std::string("no ") + role + " segmentation: select a cell array with SetInputArrayToProcess";
  }
  const std::string name = array->GetName() ? array->GetName() : "(unnamed)";
  if (array->GetNumberOfComponents() != 1)
  {
    return "the " + std::string(role) + " array '" + name + "' has " +
      std::to_string(array->GetNumberOfComponents()) + " components; labels have one";
  }
  if (array->GetNumberOfTuples() != cells)
  {
    return "the " + std::string(role) + " array '" + name + "' has " +
      std::to_string(array->GetNumberOfTuples()) + " values but the mesh has " +
      std::to_string(cells) + " cells";
  }
  labels.resize(surface.SourceCells().size());
  for (std::size_t t = 0; t < labels.size(); ++t)
  {
    const double value = array->GetComponent(surface.SourceCells()[t], 0);
    if (!std::isfinite(value) || value != std::floor(value) || value < -1.0 ||
      value > std::numeric_limits<int>::max())
    {
      return "cell " + std::to_string(surface.SourceCells()[t]) + " of the " + role + " array '" +
        name + "' holds " + std::to_string(value) + ", which is not a label (an integer >= -1)";
    }
    labels[t] = static_cast<int>(value);
  }
  return "";
}

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
    if (std::abs(p[0] - q[0]) > tolerance || std::abs(p[1] - q[1]) > tolerance ||
      std::abs(p[2] - q[2]) > tolerance)
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
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Segment");
  this->SetInputArrayToProcess(1, 1, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Segment");
}

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
  vtkPolyData* mesh = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* reference = vtkPolyData::GetData(inputVector[1], 0);
  vtkTable* output = vtkTable::GetData(outputVector, 0);

  vtkInformation* referenceArrayInfo = this->GetInputArrayInformation(1);
  const int referencePort = referenceArrayInfo->Has(INPUT_PORT()) ? referenceArrayInfo->Get(INPUT_PORT()) : 1;
  if (referencePort == 1 && !reference)
  {
    vtkErrorMacro("The reference segmentation is read from input 1, which is not connected: "
                  "connect a second mesh or select the reference array on input 0.");
    return 0;
  }
  if (reference && !sameMesh(mesh, reference))
  {
    vtkErrorMacro("The two inputs are different meshes (" << mesh->GetNumberOfPoints() << " points, "
                  << mesh->GetNumberOfCells() << " cells against " << reference->GetNumberOfPoints()
                  << " points, " << reference->GetNumberOfCells()
                  << " cells, or points that differ).");
    return 0;
  }

  kerf::MeshRequirements requirements;
  requirements.manifold = false;
  requirements.consistentOrientation = false;
  requirements.allowDuplicateFaces = true;
  kerf::SurfaceInput surface;
  std::string error;
  if (!surface.Load(mesh, requirements, error))
  {
    vtkErrorMacro("Cannot compare segmentations: " << error);
    return 0;
  }

  std::vector<int> evaluated, referenceLabels;
  error = triangleLabels(this->GetInputArrayToProcess(0, inputVector), surface, mesh->GetNumberOfCells(),
    "evaluated", evaluated);
  if (error.empty())
  {
    error = triangleLabels(this->GetInputArrayToProcess(1, inputVector), surface,
      mesh->GetNumberOfCells(), "reference", referenceLabels);
  }
  if (!error.empty())
  {
    vtkErrorMacro("Cannot compare segmentations: " << error << ".");
    return 0;
  }
  this->UpdateProgress(0.3);

  kerf::SegmentationScores scores;
  try
  {
    const kerf::SegmentationEvaluator evaluator(surface.Mesh());
    scores = evaluator.compare(evaluator.prepare(evaluated), evaluator.prepare(referenceLabels));
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot compare segmentations: " << e.what());
    return 0;
  }

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
  this->UpdateProgress(1.0);
  return 1;
}

void vtkSegmentationMetrics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
