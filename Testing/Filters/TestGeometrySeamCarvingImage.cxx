// Regression image: a bumpy cylinder stretched by half its modeling region, plain Laplace editing (left) beside
// geometry seam carving (right), coloured by ring seam.
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkGeometrySeamCarving.h"
#include "vtkGeometrySeams.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>

#include <iostream>

int TestGeometrySeamCarvingImage(int argc, char* argv[])
{
  // The Core tests' cylinder: six bumps at z = 2, handle z <= 0.5, fixed z >= 3.5, 20 rings.
  const kerf::TriangleMesh mesh = kerf::makeBumpyCylinder(1.0, 4.0, 48, 49, 6, 2.0, 0.3, 0.15);
  vtkSmartPointer<vtkPolyData> surface = kerf::test::WithRegions(mesh, kerf::heightBandRegions(mesh, 0.5, 3.5));
  vtkNew<vtkGeometrySeams> seams;
  seams->SetInputData(surface);
  seams->SetNumberOfRings(20);
  seams->SetNumberOfSectors(6);
  vtkNew<vtkTransform> handle;
  vtkSmartPointer<vtkPolyData> results[2];
  for (int plastic = 0; plastic < 2; ++plastic)
  {
    vtkNew<vtkGeometrySeamCarving> carving;
    carving->SetInputConnection(seams->GetOutputPort());
    carving->SetHandleTransform(handle);
    carving->SetPlastic(plastic == 1);
    carving->SetStiffnessScale(plastic == 1 ? 10.0 : 0.0);
    for (int step = 1; step <= 5; ++step)
    {
      handle->Identity();
      handle->Translate(0.0, 0.0, -1.5 * step / 5.0);
      if (!kerf::test::UpdateAndCaptureError(carving).empty())
      {
        return EXIT_FAILURE;
      }
    }
    results[plastic] = carving->GetOutput();
  }

  return kerf::test::SeamCarvingPairImageTest(argc, argv, results[0], "Laplace editing", results[1], "Seam carving");
}
