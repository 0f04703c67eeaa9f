// Regression image: geodesic discs on the camel, two clicks adding their discs and one subtracting, the distance to the
// nearest click beside the region.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "vtkGeodesicDisc.h"
#include "vtkKerfMeshFileReader.h"

#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <iostream>

int TestGeodesicDiscImage(int argc, char* argv[])
{
  vtkNew<vtkKerfMeshFileReader> camel;
  camel->SetFileName(kerf::test::SourcePath(argc, argv, "Data/camel.off").c_str());
  camel->Update();
  // The clicks: the camel's points of least y (a front hoof) and of greatest z (the head), adding discs of 0.2 and 0.15
  // of the diagonal, and the hoof's point again subtracting a disc of 0.07: a ring around the hoof.
  vtkPolyData* surface = camel->GetOutput();
  vtkIdType hoof = 0, far = 0;
  for (vtkIdType i = 1; i < surface->GetNumberOfPoints(); ++i)
  {
    hoof = surface->GetPoint(i)[1] < surface->GetPoint(hoof)[1] ? i : hoof;
    far = surface->GetPoint(i)[2] > surface->GetPoint(far)[2] ? i : far;
  }
  vtkNew<vtkPolyData> clicks;
  vtkNew<vtkPoints> clickPoints;
  clickPoints->InsertNextPoint(surface->GetPoint(hoof));
  clickPoints->InsertNextPoint(surface->GetPoint(far));
  clickPoints->InsertNextPoint(surface->GetPoint(hoof));
  clicks->SetPoints(clickPoints);
  vtkNew<vtkDoubleArray> radii;
  radii->SetName("Radius");
  radii->InsertNextValue(0.2);
  radii->InsertNextValue(0.15);
  radii->InsertNextValue(0.07);
  clicks->GetPointData()->AddArray(radii);
  vtkNew<vtkIntArray> subtract;
  subtract->SetName("Subtract");
  subtract->InsertNextValue(0);
  subtract->InsertNextValue(0);
  subtract->InsertNextValue(1);
  clicks->GetPointData()->AddArray(subtract);
  vtkNew<vtkGeodesicDisc> disc;
  disc->SetInputConnection(0, camel->GetOutputPort());
  disc->SetInputData(1, clicks);
  if (!kerf::test::UpdateAndCaptureError(disc).empty())
  {
    std::cerr << "the geodesic discs failed" << std::endl;
    return EXIT_FAILURE;
  }

  kerf::SceneOptions left;
  left.colorArray = "ClickDistance";
  left.colorMap = kerf::SceneOptions::ColorMap::Sequential;
  left.rangeFraction = 1.0;
  left.legendTitle = "distance\nto a click";
  left.isolineCount = 12;
  left.width = 1200;
  left.height = 600;
  left.frameLongestAxis = true;
  left.zoom = 0.95;
  left.caption = "camel: geodesic distance to the nearest adding click";
  left.overlays = { { clicks, { { 0.95, 0.85, 0.1 } }, 12.0 } };
  kerf::SceneOptions right = left;
  right.colorArray = "GeodesicDisc";
  right.colorMap = kerf::SceneOptions::ColorMap::Categorical;
  right.isolineCount = 0;
  right.caption = "their discs, the hoof's minus a smaller one";
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderSideBySide(disc->GetOutput(), left, right, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  return vtkRegressionTestImage(window) == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
