// Regression image: ROI Scissor on the camel from one click on a hoof, the field with the boundary beside the region.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "vtkKerfMeshFileReader.h"
#include "vtkROIScissor.h"

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <iostream>

int TestROIScissorImage(int argc, char* argv[])
{
  vtkNew<vtkKerfMeshFileReader> camel;
  camel->SetFileName(kerf::test::SourcePath(argc, argv, "Data/camel.off").c_str());
  camel->Update();
  // The click: the camel's point of least y (a front hoof), radius 0.2 of the diagonal.
  vtkPolyData* surface = camel->GetOutput();
  vtkIdType tip = 0;
  for (vtkIdType i = 1; i < surface->GetNumberOfPoints(); ++i)
  {
    tip = surface->GetPoint(i)[1] < surface->GetPoint(tip)[1] ? i : tip;
  }
  vtkNew<vtkPolyData> click;
  vtkNew<vtkPoints> clickPoints;
  clickPoints->InsertNextPoint(surface->GetPoint(tip));
  click->SetPoints(clickPoints);
  vtkNew<vtkROIScissor> roi;
  roi->SetInputConnection(0, camel->GetOutputPort());
  roi->SetInputData(1, click);
  roi->SetRadius(0.2);
  if (!kerf::test::UpdateAndCaptureError(roi).empty())
  {
    std::cerr << "ROI Scissor failed" << std::endl;
    return EXIT_FAILURE;
  }

  kerf::SceneOptions left;
  left.colorArray = "RoiField";
  left.colorMap = kerf::SceneOptions::ColorMap::Sequential;
  left.rangeFraction = 1.0;
  left.legendTitle = "ROI\nfield";
  left.isolineCount = 10;
  left.width = 1200;
  left.height = 600;
  left.frameLongestAxis = true;
  left.zoom = 1.15;
  left.caption = "camel: ROI Scissor from one click";
  left.overlays = { { roi->GetBoundary(), { { 0.9, 0.1, 0.1 } }, 4.0 }, { click, { { 0.95, 0.85, 0.1 } }, 12.0 } };
  kerf::SceneOptions right = left;
  right.colorArray = "RoiRegion";
  right.colorMap = kerf::SceneOptions::ColorMap::Categorical;
  right.isolineCount = 0;
  right.caption = "the region and its boundary";
  right.overlays = { { roi->GetBoundary(), { { 0.9, 0.1, 0.1 } }, 4.0 } };
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderSideBySide(roi->GetOutput(), left, right, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  return vtkRegressionTestImage(window) == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
