// Regression image: the camel cut along the bundled neck stroke, field and segments side by side.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "vtkHarmonicField.h"
#include "vtkIsolineCut.h"
#include "vtkKerfMeshFileReader.h"
#include "vtkStrokeConstraints.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <iostream>

int TestHarmonicCutImage(int argc, char* argv[])
{
  const kerf::test::CamelWithNeckStroke files = kerf::test::ReadCamelWithNeckStroke(argc, argv);
  vtkKerfMeshFileReader* camel = files.camel;
  vtkKerfMeshFileReader* stroke = files.stroke;
  vtkNew<vtkStrokeConstraints> constraints;
  constraints->SetInputConnection(0, camel->GetOutputPort());
  constraints->SetInputConnection(1, stroke->GetOutputPort());
  vtkNew<vtkHarmonicField> field;
  field->SetInputConnection(0, camel->GetOutputPort());
  field->SetInputConnection(1, constraints->GetOutputPort());
  vtkNew<vtkIsolineCut> cut;
  cut->SetInputConnection(0, field->GetOutputPort());
  cut->SetInputConnection(1, stroke->GetOutputPort());
  cut->SetModeToNearStroke();
  cut->Update();

  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderCutScene(cut->GetLabelledSurface(), stroke->GetOutput(),
    constraints->GetOutput(), cut->GetOutput(), "camel: a cut from one stroke", error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  return vtkRegressionTestImage(window) == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
