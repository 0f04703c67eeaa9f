// vtkHarmonicField: gathers constraints, keeps mesh, weights and factorization between runs.
#include "vtkHarmonicField.h"

#include "Error.h"
#include "Geometry/ClosestPoint.h"
#include "Geometry/SurfaceDescriptors.h"
#include "Harmonic/FieldGradient.h"
#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/LaplacianWeights.h"
#include "KerfSurfaceInput.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

vtkStandardNewMacro(vtkHarmonicField);

struct vtkHarmonicField::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::ClosestPointLocator> locator;
  // The weights and what they were computed from.
  bool weightsValid = false;
  kerf::LaplacianWeightOptions weightOptions;
  std::vector<double> weights;
  double meanDiagonal = 1.0;
  kerf::HarmonicFieldSolver solver;
};

namespace
{
kerf::LaplacianWeighting toWeighting(int w)
{
  switch (w)
  {
    case vtkHarmonicField::UNIFORM:
      return kerf::LaplacianWeighting::Uniform;
    case vtkHarmonicField::CONCAVITY_AWARE:
      return kerf::LaplacianWeighting::ConcavityAware;
    case vtkHarmonicField::SMOOTH_CONCAVITY:
      return kerf::LaplacianWeighting::SmoothConcavity;
    default:
      return kerf::LaplacianWeighting::Cotangent;
  }
}

const char* workName(kerf::HarmonicFieldSolution::Work work)
{
  switch (work)
  {
    case kerf::HarmonicFieldSolution::Work::Factorization:
      return "factorization";
    case kerf::HarmonicFieldSolution::Work::Update:
      return "update";
    default:
      return "back-substitution";
  }
}

} // namespace

vtkHarmonicField::vtkHarmonicField()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetFieldArrayName("HarmonicField");
  this->SetGradientArrayName("FieldGradient");
  this->SetGradientMagnitudeArrayName("FieldGradientMagnitude");
  this->SetConstraintValueArrayName("ConstraintValue");
}

vtkHarmonicField::~vtkHarmonicField()
{
  this->SetHardValueArrayName(nullptr);
  this->SetConstraintValueArrayName(nullptr);
  this->SetFieldArrayName(nullptr);
  this->SetGradientArrayName(nullptr);
  this->SetGradientMagnitudeArrayName(nullptr);
}

int vtkHarmonicField::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkHarmonicField::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPointSet* constraintPoints = vtkPointSet::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  Internals& state = *this->State;

  for (const char* name : { this->FieldArrayName, this->GradientArrayName, this->GradientMagnitudeArrayName })
  {
    if (!name || !*name)
    {
      vtkErrorMacro("Every output array needs a non-empty name.");
      return 0;
    }
  }
  if (std::string(this->GradientArrayName) == this->GradientMagnitudeArrayName)
  {
    vtkErrorMacro("The gradient and its magnitude need different names (both are cell arrays).");
    return 0;
  }

  kerf::MeshRequirements requirements;
  requirements.manifold = true;
  requirements.consistentOrientation = true;
  bool reused = false;
  std::string error;
  if (!state.surface.LoadIfChanged(input, requirements, error, reused))
  {
    vtkErrorMacro("Cannot compute the harmonic field: " << error);
    return 0;
  }
  const kerf::TriangleMesh& mesh = state.surface.Mesh();
  if (!reused)
  {
    state.locator.reset(new kerf::ClosestPointLocator(mesh));
    state.weightsValid = false;
  }
  this->UpdateProgress(0.1);

  try
  {
    kerf::LaplacianWeightOptions options;
    options.weighting = toWeighting(this->Weighting);
    options.concaveBeta = this->ConcaveBeta;
    options.concavityQuantile = this->ConcavityQuantile;
    if (!state.weightsValid || options.weighting != state.weightOptions.weighting ||
      options.concaveBeta != state.weightOptions.concaveBeta ||
      options.concavityQuantile != state.weightOptions.concavityQuantile)
    {
      const bool needsCurvature = options.weighting == kerf::LaplacianWeighting::ConcavityAware ||
        options.weighting == kerf::LaplacianWeighting::SmoothConcavity;
      kerf::SurfaceDescriptors descriptors;
      if (needsCurvature)
      {
        descriptors = kerf::computeSurfaceDescriptors(mesh);
      }
      state.weights = kerf::computeLaplacianWeights(mesh, options, needsCurvature ? &descriptors : nullptr);
      state.meanDiagonal = kerf::laplacianMeanDiagonal(mesh, state.weights);
      state.weightOptions = options;
      state.weightsValid = true;
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot compute the Laplacian weights: " << e.what());
    return 0;
  }
  this->UpdateProgress(0.3);

  // Constraints.
  kerf::FieldConstraints constraints;
  constraints.softWeight = this->SoftConstraintWeight * state.meanDiagonal;
  if (this->UseHardValues && this->HardValueArrayName && *this->HardValueArrayName)
  {
    vtkDataArray* hard = input->GetPointData()->GetArray(this->HardValueArrayName);
    if (!hard || hard->GetNumberOfComponents() != 1)
    {
      vtkErrorMacro("The surface has no one-component point array named '" << this->HardValueArrayName
                                                                             << "' (HardValueArrayName).");
      return 0;
    }
    if (hard->GetNumberOfTuples() != input->GetNumberOfPoints())
    {
      vtkErrorMacro("The hard-value array '" << this->HardValueArrayName << "' has "
                                            << hard->GetNumberOfTuples() << " values for "
                                            << input->GetNumberOfPoints() << " points.");
      return 0;
    }
    std::vector<double> values(static_cast<std::size_t>(hard->GetNumberOfTuples()));
    for (vtkIdType i = 0; i < hard->GetNumberOfTuples(); ++i)
    {
      values[static_cast<std::size_t>(i)] = hard->GetComponent(i, 0);
    }
    for (std::size_t i = 0; i < values.size(); ++i)
    {
      const int vertex = state.surface.Representative(static_cast<int>(i));
      if (!std::isnan(values[i]) && !mesh.vertexFaces(vertex).empty())
      {
        constraints.dirichletVertices.push_back(vertex);
        constraints.dirichletValues.push_back(values[i]);
      }
    }
  }
  if (constraintPoints && constraintPoints->GetNumberOfPoints() > 0)
  {
    vtkDataArray* values = this->ConstraintValueArrayName
      ? constraintPoints->GetPointData()->GetArray(this->ConstraintValueArrayName)
      : nullptr;
    if (!values || values->GetNumberOfComponents() != 1)
    {
      vtkErrorMacro("The constraint points have no one-component point array named '"
        << (this->ConstraintValueArrayName ? this->ConstraintValueArrayName : "")
        << "' (ConstraintValueArrayName).");
      return 0;
    }
    if (values->GetNumberOfTuples() != constraintPoints->GetNumberOfPoints())
    {
      vtkErrorMacro("The constraint-value array '" << this->ConstraintValueArrayName << "' has "
                                                  << values->GetNumberOfTuples() << " values for "
                                                  << constraintPoints->GetNumberOfPoints() << " points.");
      return 0;
    }
    if (!std::isfinite(this->MaximumProjectionDistance))
    {
      vtkErrorMacro("MaximumProjectionDistance must be a number (0 for no limit).");
      return 0;
    }
    const double limit = this->MaximumProjectionDistance > 0.0
      ? this->MaximumProjectionDistance * mesh.boundingBoxDiagonal()
      : std::numeric_limits<double>::infinity();
    for (vtkIdType i = 0; i < constraintPoints->GetNumberOfPoints(); ++i)
    {
      kerf::Vector3 p;
      constraintPoints->GetPoint(i, p.data());
      const double value = values->GetComponent(i, 0);
      if (!p.allFinite() || !std::isfinite(value))
      {
        vtkErrorMacro("Constraint point " << i << " has a NaN or infinite coordinate or value.");
        return 0;
      }
      const kerf::ClosestPointLocator::Hit hit = state.locator->closest(p);
      if (hit.distance > limit)
      {
        vtkErrorMacro("Constraint point " << i << " is " << hit.distance
                                          << " away from the surface, farther than the allowed "
                                          << limit << " (MaximumProjectionDistance).");
        return 0;
      }
      if (this->HardConstraints)
      {
        int corner;
        hit.barycentric.maxCoeff(&corner);
        constraints.dirichletVertices.push_back(mesh.triangle(hit.face)[corner]);
        constraints.dirichletValues.push_back(value);
      }
      else
      {
        constraints.soft.push_back({ hit.face, hit.barycentric, value });
      }
    }
  }
  this->UpdateProgress(0.4);

  kerf::HarmonicFieldSolution solution;
  try
  {
    solution = state.solver.solve(mesh, state.weights, constraints);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot compute the harmonic field: " << e.what());
    return 0;
  }
  this->UpdateProgress(0.9);

  const std::vector<kerf::Vector3> gradients = kerf::computeFaceGradients(mesh, solution.field);
  std::vector<double> magnitudes(gradients.size());
  for (std::size_t f = 0; f < gradients.size(); ++f)
  {
    magnitudes[f] = gradients[f].norm();
  }
  const auto finite = [](const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
  };
  if (!finite(solution.field) || !finite(magnitudes) || !std::isfinite(solution.relativeResidual))
  {
    vtkErrorMacro("Cannot compute the harmonic field: the field or its gradient overflows (hard or "
                  "constraint values too large for double precision).");
    return 0;
  }
  state.surface.ExpandToInputPoints(solution.field);

  state.surface.MakeOutput(input, output);
  output->GetPointData()->AddArray(kerf::MakeArray(this->FieldArrayName, solution.field));
  output->GetPointData()->SetActiveScalars(this->FieldArrayName);
  output->GetCellData()->AddArray(kerf::MakeArray(this->GradientArrayName, gradients));
  output->GetCellData()->AddArray(kerf::MakeArray(this->GradientMagnitudeArrayName, magnitudes));
  vtkNew<vtkDoubleArray> residual;
  residual->SetName("RelativeResidual");
  residual->InsertNextValue(solution.relativeResidual);
  output->GetFieldData()->AddArray(residual);
  vtkNew<vtkStringArray> work;
  work->SetName("SolverWork");
  work->InsertNextValue(workName(solution.work));
  output->GetFieldData()->AddArray(work);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkHarmonicField::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << this->Weighting << "\n";
  os << indent << "ConcaveBeta: " << this->ConcaveBeta << "\n";
  os << indent << "ConcavityQuantile: " << this->ConcavityQuantile << "\n";
  os << indent << "SoftConstraintWeight: " << this->SoftConstraintWeight << "\n";
  os << indent << "HardConstraints: " << this->HardConstraints << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "HardValueArrayName: " << (this->HardValueArrayName ? this->HardValueArrayName : "(none)") << "\n";
  os << indent << "UseHardValues: " << this->UseHardValues << "\n";
  os << indent << "ConstraintValueArrayName: "
     << (this->ConstraintValueArrayName ? this->ConstraintValueArrayName : "(none)") << "\n";
  os << indent << "FieldArrayName: " << (this->FieldArrayName ? this->FieldArrayName : "(none)") << "\n";
  os << indent << "GradientArrayName: " << (this->GradientArrayName ? this->GradientArrayName : "(none)") << "\n";
  os << indent << "GradientMagnitudeArrayName: "
     << (this->GradientMagnitudeArrayName ? this->GradientMagnitudeArrayName : "(none)") << "\n";
}
