// Regression image: the bundled camel in eight segments by consensus cuts.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "vtkConsensusCutSegmentation.h"
#include "vtkMeshFileReader.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <iostream>

int TestConsensusCutSegmentationImage(int argc, char* argv[])
{
  vtkNew<vtkMeshFileReader> reader;
  reader->SetFileName(kerf::test::SourcePath(argc, argv, "Data/camel.off").c_str());
  vtkNew<vtkConsensusCutSegmentation> segmentation;
  segmentation->SetInputConnection(reader->GetOutputPort());
  segmentation->SetSegmentCount(8);
  segmentation->Update();

  kerf::SceneOptions options;
  options.colorArray = "Segment";
  options.colorMap = kerf::SceneOptions::ColorMap::Categorical;
  options.legendTitle = "Segment";
  options.width = 600;
  options.height = 450;
  options.azimuth = 35.0;
  options.elevation = 15.0;
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderScene(segmentation->GetOutput(), options, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
