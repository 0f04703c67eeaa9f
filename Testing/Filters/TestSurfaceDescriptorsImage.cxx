// Regression image: the bundled camel coloured by mean curvature with minimum-curvature directions.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "vtkKerfMeshFileReader.h"
#include "vtkSurfaceDescriptors.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <iostream>

int TestSurfaceDescriptorsImage(int argc, char* argv[])
{
  vtkNew<vtkKerfMeshFileReader> reader;
  reader->SetFileName(kerf::test::SourcePath(argc, argv, "Data/camel.off").c_str());
  vtkNew<vtkSurfaceDescriptors> descriptors;
  descriptors->SetInputConnection(reader->GetOutputPort());
  descriptors->Update();

  kerf::SceneOptions options;
  options.colorArray = "MeanCurvature";
  options.legendTitle = "Mean\ncurvature";
  options.rangeFraction = 0.85;
  options.directionArray = "MinimumCurvatureDirection";
  options.directionCount = 4000;
  options.width = 600;
  options.height = 450;
  options.azimuth = 35.0;
  options.elevation = 15.0;
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderScene(descriptors->GetOutput(), options, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
