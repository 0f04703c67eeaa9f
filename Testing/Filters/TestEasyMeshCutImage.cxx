// Regression image: Easy Mesh Cut on the camel from a foreground click on a front hoof and a background click on the
// top, grown parts beside the snake-refined ones.
#include "KerfScene.h"
#include "KerfTestUtilities.h"
#include "vtkEasyMeshCut.h"
#include "vtkKerfMeshFileReader.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>

#include <cmath>
#include <iostream>

int TestEasyMeshCutImage(int argc, char* argv[])
{
  vtkNew<vtkKerfMeshFileReader> camel;
  camel->SetFileName(kerf::test::SourcePath(argc, argv, "Data/camel.off").c_str());
  camel->Update();
  // Foreground: the point of least y (a front hoof); background: the point of greatest y.
  vtkPolyData* surface = camel->GetOutput();
  vtkIdType hoof = 0, top = 0;
  for (vtkIdType i = 1; i < surface->GetNumberOfPoints(); ++i)
  {
    hoof = surface->GetPoint(i)[1] < surface->GetPoint(hoof)[1] ? i : hoof;
    top = surface->GetPoint(i)[1] > surface->GetPoint(top)[1] ? i : top;
  }
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines, verts;
  vtkNew<vtkIntArray> labels;
  labels->SetName("Label");
  for (const auto& [point, label] : { std::pair<vtkIdType, int>{ hoof, 1 }, { top, 0 } })
  {
    const vtkIdType id = points->InsertNextPoint(surface->GetPoint(point));
    lines->InsertNextCell(1, &id);
    verts->InsertNextCell(1, &id);
    labels->InsertNextValue(label);
  }
  vtkNew<vtkPolyData> strokes;
  strokes->SetPoints(points);
  strokes->SetLines(lines);
  strokes->GetCellData()->AddArray(labels);
  // The clicks drawn as points just outside the surface: each is an extreme of y, where the
  // surface's normal is -y (hoof) or +y (top) and the point lies on the silhouette, so a marker
  // drawn at the surface itself would be hidden or not by the depth buffer's last bits.
  const double lift = 0.01 * std::sqrt(surface->GetLength2());
  vtkNew<vtkPoints> markers;
  for (const auto& [point, side] : { std::pair<vtkIdType, double>{ hoof, -1.0 }, { top, 1.0 } })
  {
    double p[3];
    surface->GetPoint(point, p);
    p[1] += side * lift;
    markers->InsertNextPoint(p);
  }
  vtkNew<vtkPolyData> clicks;
  clicks->SetPoints(markers);
  clicks->SetVerts(verts);

  vtkNew<vtkEasyMeshCut> grown, refined;
  for (vtkEasyMeshCut* cut : { grown.Get(), refined.Get() })
  {
    cut->SetInputConnection(0, camel->GetOutputPort());
    cut->SetInputData(1, strokes);
    cut->SetRefine(cut == refined.Get());
    if (!kerf::test::UpdateAndCaptureError(cut).empty())
    {
      std::cerr << "Easy Mesh Cut failed" << std::endl;
      return EXIT_FAILURE;
    }
  }
  vtkNew<vtkPolyData> both;
  both->ShallowCopy(refined->GetOutput());
  auto grownSegments = vtk::TakeSmartPointer(grown->GetOutput()->GetCellData()->GetArray("Segment")->NewInstance());
  grownSegments->DeepCopy(grown->GetOutput()->GetCellData()->GetArray("Segment"));
  grownSegments->SetName("GrownSegment");
  both->GetCellData()->AddArray(grownSegments);

  kerf::SceneOptions left;
  left.colorArray = "GrownSegment";
  left.colorMap = kerf::SceneOptions::ColorMap::Categorical;
  left.width = 1200;
  left.height = 600;
  left.frameLongestAxis = true;
  left.zoom = 1.15;
  left.caption = "camel: grown from two clicks (yellow)";
  left.overlays = { { grown->GetBoundary(), { { 0.9, 0.1, 0.1 } }, 4.0 }, { clicks, { { 0.95, 0.85, 0.1 } }, 12.0 } };
  kerf::SceneOptions right = left;
  right.colorArray = "Segment";
  right.caption = "the boundary refined as a snake";
  right.overlays = { { refined->GetBoundary(), { { 0.9, 0.1, 0.1 } }, 4.0 },
    { clicks, { { 0.95, 0.85, 0.1 } }, 12.0 } };
  std::string error;
  vtkSmartPointer<vtkRenderWindow> window = kerf::RenderSideBySide(both, left, right, error);
  if (!window)
  {
    std::cerr << "cannot render: " << error << std::endl;
    return EXIT_FAILURE;
  }
  return vtkRegressionTestImage(window) == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
