// Regression image: fifteen ring seams on a cylinder with a ring of bumps, with the iso- and sector contours.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkGeometrySeams.h"

#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <iostream>

int TestGeometrySeamsImage(int argc, char* argv[])
{
  const kerf::TriangleMesh mesh = kerf::makeBumpyCylinder(1.0, 4.0, 72, 73, 6, 2.0, 0.35, 0.2);
  vtkSmartPointer<vtkPolyData> surface = kerf::test::WithRegions(mesh, kerf::heightBandRegions(mesh, 0.8, 3.2));
  vtkNew<vtkGeometrySeams> seams;
  seams->SetInputData(surface);
  seams->Update();

  kerf::SceneOptions options;
  options.colorArray = "RingSeam";
  options.colorMap = kerf::SceneOptions::ColorMap::Categorical;
  options.legendTitle = "Ring";
  options.overlays.push_back({ seams->GetContours(), { { 0.1, 0.1, 0.1 } }, 1.5 });
  options.width = 600;
  options.height = 600;
  options.azimuth = 0.0;
  options.elevation = -90.0;
  options.zoom = 1.1;
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderScene(seams->GetOutput(), options, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  return vtkRegressionTestImage(window) == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
