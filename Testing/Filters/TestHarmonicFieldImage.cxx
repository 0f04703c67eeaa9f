// Regression image: a concavity-aware harmonic field between the tips of a two-lobe shape, with isolines.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkHarmonicField.h"

#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <cmath>
#include <iostream>
#include <limits>

int TestHarmonicFieldImage(int argc, char* argv[])
{
  const double halfLength = 2.2;
  vtkSmartPointer<vtkPolyData> shape =
    kerf::test::ToPolyData(kerf::makeDumbbell(halfLength, { { 1.0, 0.8 } }, 0.3, 0.65, 4));
  vtkNew<vtkDoubleArray> tips;
  tips->SetName("Tips");
  for (vtkIdType i = 0; i < shape->GetNumberOfPoints(); ++i)
  {
    const double z = shape->GetPoint(i)[2];
    tips->InsertNextValue(
      std::abs(z) > 0.9 * halfLength ? (z > 0 ? 1.0 : 0.0) : std::numeric_limits<double>::quiet_NaN());
  }
  shape->GetPointData()->AddArray(tips);
  vtkNew<vtkHarmonicField> field;
  field->SetInputData(shape);
  field->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Tips");
  field->UseHardValuesOn();
  field->SetWeightingToSmoothConcavity();
  field->Update();

  kerf::SceneOptions options;
  options.colorArray = "HarmonicField";
  options.colorMap = kerf::SceneOptions::ColorMap::Sequential;
  options.rangeFraction = 1.0;
  options.isolineCount = 19;
  options.legendTitle = "Field";
  options.width = 600;
  options.height = 450;
  options.azimuth = 90.0;
  options.elevation = 0.0;
  options.zoom = 1.0;
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderScene(field->GetOutput(), options, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  return vtkRegressionTestImage(window) == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
