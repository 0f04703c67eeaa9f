// vtkHarmonicField: reads the constraints, solves with the surface's HarmonicCutSession, writes the field.
#include "vtkHarmonicField.h"

#include "Harmonic/HarmonicCutSession.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Numerics/FieldGradient.h"

#include <vtkCellData.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>

#include <algorithm>

vtkStandardNewMacro(vtkHarmonicField);

// The filter's weighting codes are the Core enumeration's values.
static_assert(static_cast<int>(kerf::LaplacianWeighting::Uniform) == vtkHarmonicField::UNIFORM &&
    static_cast<int>(kerf::LaplacianWeighting::Cotangent) == vtkHarmonicField::COTANGENT &&
    static_cast<int>(kerf::LaplacianWeighting::ConcavityAware) == vtkHarmonicField::CONCAVITY_AWARE &&
    static_cast<int>(kerf::LaplacianWeighting::SmoothConcavity) == vtkHarmonicField::SMOOTH_CONCAVITY &&
    static_cast<int>(kerf::LaplacianWeighting::IntrinsicDelaunay) == vtkHarmonicField::INTRINSIC_DELAUNAY,
  "vtkHarmonicField's Weightings follow kerf::LaplacianWeighting");
// Its first two formulation codes are the Core enumeration's values (`kerf cut` relies on it).
static_assert(static_cast<int>(kerf::SoftConstraintFormulation::PointValues) == vtkHarmonicField::POINT_VALUES &&
    static_cast<int>(kerf::SoftConstraintFormulation::LeastSquares) == vtkHarmonicField::LEAST_SQUARES,
  "vtkHarmonicField's Formulations follow kerf::SoftConstraintFormulation");

struct vtkHarmonicField::Internals
{
  kerf::SurfaceInput surface;
  std::unique_ptr<kerf::HarmonicCutSession> session;
};

vtkHarmonicField::vtkHarmonicField()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetFieldArrayName("HarmonicField");
  this->SetGradientArrayName("FieldGradient");
  this->SetGradientMagnitudeArrayName("FieldGradientMagnitude");
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "HardValue");
  this->SetConstraintValueArrayName("ConstraintValue");
}

vtkHarmonicField::~vtkHarmonicField()
{
  this->SetConstraintValueArrayName(nullptr);
  this->SetFieldArrayName(nullptr);
  this->SetGradientArrayName(nullptr);
  this->SetGradientMagnitudeArrayName(nullptr);
}

int vtkHarmonicField::FillInputPortInformation(int port, vtkInformation* info)
{
  return kerf::FillSurfaceAndOptionalPointsPorts(port, info);
}

int vtkHarmonicField::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot compute the harmonic field", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPointSet* constraintPoints = vtkPointSet::GetData(inputVector[1], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->FieldArrayName, this->GradientArrayName, this->GradientMagnitudeArrayName });
    kerf::CheckDifferentNames(
      this->GradientArrayName, this->GradientMagnitudeArrayName, "the gradient and its magnitude");

    kerf::MeshRequirements requirements;
    requirements.manifold = true;
    requirements.consistentOrientation = true;
    kerf::LoadSurface(this->State->surface, input, requirements);
    kerf::HarmonicCutSession& session = this->State->surface.SessionFor(this->State->session);
    const double diagonal = session.mesh().boundingBoxDiagonal();
    this->UpdateProgress(0.1);

    kerf::FieldConstraints constraints;
    if (this->UseHardValues)
    {
      const std::vector<double> values = kerf::ReadInputArray(this, 0, input->GetNumberOfPoints(), "the surface");
      std::vector<int> vertices(values.size());
      for (std::size_t i = 0; i < values.size(); ++i)
      {
        vertices[i] = this->State->surface.Representative(static_cast<int>(i));
      }
      session.addHardValues(vertices, values, constraints);
    }
    if (constraintPoints && constraintPoints->GetNumberOfPoints() > 0)
    {
      kerf::ConstraintPlacement placement;
      placement.hard = this->HardConstraints;
      placement.maximumDistance =
        kerf::RelativeDistance(this->MaximumProjectionDistance, diagonal, "MaximumProjectionDistance");
      session.projectConstraints(kerf::ReadPoints(constraintPoints),
        kerf::ReadNamedPointArray(constraintPoints, this->ConstraintValueArrayName, "the constraint points"), placement,
        constraints);
    }
    this->UpdateProgress(0.3);

    kerf::HarmonicFieldOptions options;
    options.weights.weighting = kerf::LaplacianWeighting(this->Weighting);
    options.weights.concaveBeta = kerf::Finite(this->ConcaveBeta, "ConcaveBeta");
    options.weights.concavityQuantile = kerf::Finite(this->ConcavityQuantile, "ConcavityQuantile");
    options.softWeight = kerf::Finite(this->SoftConstraintWeight, "SoftConstraintWeight");
    options.formulation = kerf::FilterFormulation(this->Formulation, session);
    kerf::HarmonicFieldSolution solution = session.solve(constraints, options);
    this->UpdateProgress(0.9);

    const std::vector<kerf::Vector3> gradients = kerf::computeFaceGradients(session.mesh(), solution.field);
    std::vector<double> magnitudes(gradients.size());
    std::transform(
      gradients.begin(), gradients.end(), magnitudes.begin(), [](const kerf::Vector3& g) { return g.norm(); });
    kerf::CheckFinite({ &solution.field, &magnitudes }, solution.relativeResidual,
      "the field or its gradient overflows (hard or constraint values too large for double precision)");
    this->State->surface.MakeOutput(input, output);
    kerf::WriteField(this->State->surface, solution, constraints, this->FieldArrayName, output);
    output->GetPointData()->SetActiveScalars(kerf::ClampedFieldName(this->FieldArrayName).c_str());
    output->GetCellData()->AddArray(kerf::MakeArray(this->GradientArrayName, gradients));
    output->GetCellData()->AddArray(kerf::MakeArray(this->GradientMagnitudeArrayName, magnitudes));
  });
}

void vtkHarmonicField::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << this->Weighting << "\n";
  os << indent << "Formulation: " << this->Formulation << "\n";
  os << indent << "ConcaveBeta: " << this->ConcaveBeta << "\n";
  os << indent << "ConcavityQuantile: " << this->ConcavityQuantile << "\n";
  os << indent << "SoftConstraintWeight: " << this->SoftConstraintWeight << "\n";
  os << indent << "HardConstraints: " << this->HardConstraints << "\n";
  os << indent << "MaximumProjectionDistance: " << this->MaximumProjectionDistance << "\n";
  os << indent << "UseHardValues: " << this->UseHardValues << "\n";
  os << indent
     << "ConstraintValueArrayName: " << (this->ConstraintValueArrayName ? this->ConstraintValueArrayName : "(none)")
     << "\n";
  os << indent << "FieldArrayName: " << (this->FieldArrayName ? this->FieldArrayName : "(none)") << "\n";
  os << indent << "GradientArrayName: " << (this->GradientArrayName ? this->GradientArrayName : "(none)") << "\n";
  os << indent << "GradientMagnitudeArrayName: "
     << (this->GradientMagnitudeArrayName ? this->GradientMagnitudeArrayName : "(none)") << "\n";
}
