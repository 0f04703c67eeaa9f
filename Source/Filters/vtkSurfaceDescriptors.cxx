// vtkSurfaceDescriptors: converts and validates the surface, takes its descriptors from Core, writes arrays.
#include "vtkSurfaceDescriptors.h"

#include "Geometry/SurfaceDescriptors.h"
#include "KerfFilterBorder.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"

#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

vtkStandardNewMacro(vtkSurfaceDescriptors);

struct vtkSurfaceDescriptors::Internals
{
  kerf::SurfaceInput surface;
};

vtkSurfaceDescriptors::vtkSurfaceDescriptors()
  : State(new Internals)
{
  this->SetNormalsArrayName("Normals");
  this->SetMaximumCurvatureArrayName("MaximumCurvature");
  this->SetMinimumCurvatureArrayName("MinimumCurvature");
  this->SetMaximumDirectionArrayName("MaximumCurvatureDirection");
  this->SetMinimumDirectionArrayName("MinimumCurvatureDirection");
  this->SetMeanCurvatureArrayName("MeanCurvature");
  this->SetGaussianCurvatureArrayName("GaussianCurvature");
  this->SetConcaveArrayName("Concave");
  this->SetNormalConeAngleArrayName("NormalConeAngle");
}

vtkSurfaceDescriptors::~vtkSurfaceDescriptors()
{
  this->SetNormalsArrayName(nullptr);
  this->SetMaximumCurvatureArrayName(nullptr);
  this->SetMinimumCurvatureArrayName(nullptr);
  this->SetMaximumDirectionArrayName(nullptr);
  this->SetMinimumDirectionArrayName(nullptr);
  this->SetMeanCurvatureArrayName(nullptr);
  this->SetGaussianCurvatureArrayName(nullptr);
  this->SetConcaveArrayName(nullptr);
  this->SetNormalConeAngleArrayName(nullptr);
}

// The model of a Kerf filter (see Documentation/new-filter.md): RunGuarded is the border where
// every failure becomes a vtkErrorMacro and a 0 return; LoadSurface converts and validates the
// input against this algorithm's requirements (or reuses the conversion of the same geometry);
// the algorithm runs in Core; the output keeps the input's arrays and adds named ones.
int vtkSurfaceDescriptors::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot compute surface descriptors", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::CheckOutputNames({ this->NormalsArrayName, this->MaximumCurvatureArrayName, this->MinimumCurvatureArrayName,
      this->MaximumDirectionArrayName, this->MinimumDirectionArrayName, this->MeanCurvatureArrayName,
      this->GaussianCurvatureArrayName, this->ConcaveArrayName, this->NormalConeAngleArrayName });

    // What the algorithm accepts: the curvature tensor needs an oriented 2-manifold; boundaries,
    // several components and zero-area triangles are handled.
    kerf::MeshRequirements requirements;
    requirements.manifold = true;
    requirements.consistentOrientation = true;
    requirements.allowZeroAreaFaces = true;
    requirements.allowBoundary = true;
    requirements.allowSeveralComponents = true;
    kerf::SurfaceInput& surface = this->State->surface;
    kerf::LoadSurface(surface, input, requirements);
    this->UpdateProgress(0.2);

    // The Core algorithm, cached with the surface: a Harmonic Field downstream with concavity-aware
    // weights reuses these descriptors.
    const kerf::SurfaceDescriptors& d = surface.GetSurface().descriptors();
    this->UpdateProgress(0.9);

    surface.MakeOutput(input, output);
    vtkPointData* pointData = output->GetPointData();
    pointData->SetNormals(kerf::MakeArray(this->NormalsArrayName, surface.ToInputPoints(d.normals)));
    pointData->AddArray(kerf::MakeArray(this->MaximumCurvatureArrayName, surface.ToInputPoints(d.maximumCurvature)));
    pointData->AddArray(kerf::MakeArray(this->MinimumCurvatureArrayName, surface.ToInputPoints(d.minimumCurvature)));
    pointData->AddArray(kerf::MakeArray(this->MaximumDirectionArrayName, surface.ToInputPoints(d.maximumDirections)));
    pointData->AddArray(kerf::MakeArray(this->MinimumDirectionArrayName, surface.ToInputPoints(d.minimumDirections)));
    pointData->AddArray(kerf::MakeArray(this->MeanCurvatureArrayName, surface.ToInputPoints(d.meanCurvature)));
    pointData->AddArray(kerf::MakeArray(this->GaussianCurvatureArrayName, surface.ToInputPoints(d.gaussianCurvature)));
    pointData->AddArray(kerf::MakeArray(this->ConcaveArrayName, surface.ToInputPoints(d.concave)));
    pointData->AddArray(kerf::MakeArray(this->NormalConeAngleArrayName, surface.ToInputPoints(d.normalConeAngle)));
  });
}

void vtkSurfaceDescriptors::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto show = [](const char* s) { return s ? s : "(none)"; };
  os << indent << "NormalsArrayName: " << show(this->NormalsArrayName) << "\n";
  os << indent << "MaximumCurvatureArrayName: " << show(this->MaximumCurvatureArrayName) << "\n";
  os << indent << "MinimumCurvatureArrayName: " << show(this->MinimumCurvatureArrayName) << "\n";
  os << indent << "MaximumDirectionArrayName: " << show(this->MaximumDirectionArrayName) << "\n";
  os << indent << "MinimumDirectionArrayName: " << show(this->MinimumDirectionArrayName) << "\n";
  os << indent << "MeanCurvatureArrayName: " << show(this->MeanCurvatureArrayName) << "\n";
  os << indent << "GaussianCurvatureArrayName: " << show(this->GaussianCurvatureArrayName) << "\n";
  os << indent << "ConcaveArrayName: " << show(this->ConcaveArrayName) << "\n";
  os << indent << "NormalConeAngleArrayName: " << show(this->NormalConeAngleArrayName) << "\n";
}
