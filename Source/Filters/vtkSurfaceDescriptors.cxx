// vtkSurfaceDescriptors: converts, validates, calls kerf::computeSurfaceDescriptors, writes arrays.
#include "vtkSurfaceDescriptors.h"

#include "Geometry/SurfaceDescriptors.h"
#include "KerfSurfaceInput.h"

#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <new>

vtkStandardNewMacro(vtkSurfaceDescriptors);

vtkSurfaceDescriptors::vtkSurfaceDescriptors()
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

int vtkSurfaceDescriptors::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);

  const char* names[] = { this->NormalsArrayName, this->MaximumCurvatureArrayName,
    this->MinimumCurvatureArrayName, this->MaximumDirectionArrayName,
    this->MinimumDirectionArrayName, this->MeanCurvatureArrayName,
    this->GaussianCurvatureArrayName, this->ConcaveArrayName, this->NormalConeAngleArrayName };
  for (const char* name : names)
  {
    if (!name || !*name)
    {
      vtkErrorMacro("Every output array needs a non-empty name.");
      return 0;
    }
  }

  kerf::MeshRequirements requirements;
  requirements.manifold = true;
  requirements.consistentOrientation = true;
  requirements.allowZeroAreaFaces = true;
  requirements.allowBoundary = true;
  requirements.allowSeveralComponents = true;

  kerf::SurfaceInput surface;
  std::string error;
  if (!surface.Load(input, requirements, error))
  {
    vtkErrorMacro("Cannot compute surface descriptors: " << error);
    return 0;
  }
  this->UpdateProgress(0.2);

  kerf::SurfaceDescriptors descriptors;
  try
  {
    descriptors = kerf::computeSurfaceDescriptors(surface.Mesh());
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot compute surface descriptors: " << e.what());
    return 0;
  }
  this->UpdateProgress(0.9);
  surface.ExpandToInputPoints(descriptors.normals);
  surface.ExpandToInputPoints(descriptors.maximumCurvature);
  surface.ExpandToInputPoints(descriptors.minimumCurvature);
  surface.ExpandToInputPoints(descriptors.maximumDirections);
  surface.ExpandToInputPoints(descriptors.minimumDirections);
  surface.ExpandToInputPoints(descriptors.meanCurvature);
  surface.ExpandToInputPoints(descriptors.gaussianCurvature);
  surface.ExpandToInputPoints(descriptors.concave);
  surface.ExpandToInputPoints(descriptors.normalConeAngle);

  surface.MakeOutput(input, output);
  vtkPointData* pointData = output->GetPointData();
  auto normals = kerf::MakeArray(this->NormalsArrayName, descriptors.normals);
  pointData->SetNormals(normals);
  pointData->AddArray(kerf::MakeArray(this->MaximumCurvatureArrayName, descriptors.maximumCurvature));
  pointData->AddArray(kerf::MakeArray(this->MinimumCurvatureArrayName, descriptors.minimumCurvature));
  pointData->AddArray(kerf::MakeArray(this->MaximumDirectionArrayName, descriptors.maximumDirections));
  pointData->AddArray(kerf::MakeArray(this->MinimumDirectionArrayName, descriptors.minimumDirections));
  pointData->AddArray(kerf::MakeArray(this->MeanCurvatureArrayName, descriptors.meanCurvature));
  pointData->AddArray(kerf::MakeArray(this->GaussianCurvatureArrayName, descriptors.gaussianCurvature));
  pointData->AddArray(kerf::MakeArray(this->ConcaveArrayName, descriptors.concave));
  pointData->AddArray(kerf::MakeArray(this->NormalConeAngleArrayName, descriptors.normalConeAngle));
  this->UpdateProgress(1.0);
  return 1;
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
