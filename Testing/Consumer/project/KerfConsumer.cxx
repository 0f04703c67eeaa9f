// Computes Kerf's surface descriptors on a sphere; fails unless the mean curvature is 1/R.
#include <vtkSurfaceDescriptors.h>

#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

int main()
{
  const double radius = 2.0;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  vtkNew<vtkSurfaceDescriptors> descriptors;
  descriptors->SetInputConnection(sphere->GetOutputPort());
  if (descriptors->GetExecutive()->Update() != 1)
  {
    std::cerr << "vtkSurfaceDescriptors failed" << std::endl;
    return EXIT_FAILURE;
  }
  vtkDataArray* mean = descriptors->GetOutput()->GetPointData()->GetArray("MeanCurvature");
  if (!mean || mean->GetNumberOfTuples() != descriptors->GetOutput()->GetNumberOfPoints() ||
    mean->GetNumberOfTuples() == 0)
  {
    std::cerr << "no MeanCurvature array with one value per point" << std::endl;
    return EXIT_FAILURE;
  }
  double error = 0.0;
  for (vtkIdType i = 0; i < mean->GetNumberOfTuples(); ++i)
  {
    error += std::abs(mean->GetTuple1(i) * radius - 1.0);
  }
  error /= static_cast<double>(mean->GetNumberOfTuples());
  std::cout << "mean |H R - 1| = " << error << " over " << mean->GetNumberOfTuples() << " points" << std::endl;
  return error < 0.01 ? EXIT_SUCCESS : EXIT_FAILURE;
}
