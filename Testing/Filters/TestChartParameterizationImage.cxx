// Regression image: a sphere cut into its eight octants, checkerboard-textured through Chart Parameterization's UV,
// beside the UV layout.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkChartParameterization.h"

#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <iostream>

int TestChartParameterizationImage(int argc, char* argv[])
{
  const kerf::TriangleMesh sphere = kerf::makeIcosphere(1.0, 4);
  vtkSmartPointer<vtkPolyData> surface = kerf::test::ToPolyData(sphere);
  vtkNew<vtkIntArray> charts;
  charts->SetName("Chart");
  for (int label : kerf::octantLabels(sphere))
  {
    charts->InsertNextValue(label);
  }
  surface->GetCellData()->AddArray(charts);
  vtkNew<vtkChartParameterization> atlas;
  atlas->SetInputData(surface);
  atlas->SetMargin(0.02);
  if (!kerf::test::UpdateAndCaptureError(atlas).empty())
  {
    std::cerr << "Chart Parameterization failed" << std::endl;
    return EXIT_FAILURE;
  }

  kerf::SceneOptions left;
  left.checkerboardSquares = 40;
  left.width = 1200;
  left.height = 600;
  left.zoom = 1.3;
  left.caption = "sphere in 8 charts: LSCM, checkerboard texture";
  kerf::SceneOptions right = left;
  right.azimuth = 0.0;
  right.elevation = 0.0;
  right.zoom = 1.1;
  right.caption = "the UV layout in the unit square";
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window =
    kerf::RenderPair(atlas->GetOutput(0), left, atlas->GetOutput(1), right, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  return vtkRegressionTestImage(window) == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
