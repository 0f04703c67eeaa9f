// Regression image: the camel split by scissor along its neck cut, charts coloured and the cut edges drawn.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "vtkCurveExport.h"
#include "vtkKerfMeshFileReader.h"
#include "vtkStrokeCut.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <iostream>

int TestCurveExportImage(int argc, char* argv[])
{
  const kerf::test::CamelWithNeckStroke files = kerf::test::ReadCamelWithNeckStroke(argc, argv);
  vtkKerfMeshFileReader* camel = files.camel;
  vtkKerfMeshFileReader* stroke = files.stroke;
  vtkNew<vtkStrokeCut> cut;
  cut->SetInputConnection(0, camel->GetOutputPort());
  cut->SetInputConnection(1, stroke->GetOutputPort());
  vtkNew<vtkCurveExport> scissor;
  scissor->SetInputConnection(0, camel->GetOutputPort());
  scissor->SetInputConnection(1, cut->GetOutputPort(1));
  scissor->Update();

  kerf::SceneOptions options;
  options.colorArray = "Chart";
  options.colorMap = kerf::SceneOptions::ColorMap::Categorical;
  options.outlineSegments = false;
  options.zoom = 1.2;
  options.caption = "camel: scissor export of the neck cut (cut edges in red)";
  vtkSmartPointer<vtkPolyData> edges = vtkSmartPointer<vtkPolyData>::New();
  edges->ShallowCopy(scissor->GetCutEdges());
  options.overlays.push_back({ edges, { { 0.9, 0.1, 0.1 } }, 5.0 });
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderScene(scissor->GetOutput(), options, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  return vtkRegressionTestImage(window) == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
