// Stroke Cut (vtkStrokeCut): the same cut as the three-filter pipeline, stroke points from the
// panel moved onto the surface, the factorization kept, and its errors.
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkHarmonicField.h"
#include "vtkIsolineCut.h"
#include "vtkStrokeConstraints.h"
#include "vtkStrokeCut.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>

#include <cmath>
#include <string>

namespace
{
constexpr double Pi = 3.14159265358979323846;

// Equal to `tolerance` (0: exactly).
bool sameArrays(vtkDataArray* a, vtkDataArray* b, double tolerance = 0.0)
{
  if (!a || !b || a->GetNumberOfTuples() != b->GetNumberOfTuples())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    if (std::abs(a->GetComponent(i, 0) - b->GetComponent(i, 0)) > tolerance)
    {
      return false;
    }
  }
  return true;
}

std::string solverWork(vtkPolyData* output)
{
  return vtkStringArray::SafeDownCast(output->GetFieldData()->GetAbstractArray("SolverWork"))->GetValue(0);
}
} // namespace

int TestStrokeCutFilter(int, char*[])
{
  bool ok = true;
  // A closed tube (radius 1, height 4, capped) would need capping; an open cylinder is enough.
  vtkSmartPointer<vtkPolyData> cylinder = kerf::test::ToPolyData(kerf::makeCylinder(1.0, 4.0, 96, 97));
  vtkSmartPointer<vtkPolyData> stroke = kerf::test::CirclePolyline(1.0, 1.5, 12);

  // One filter and three filters give the same segments and the same field (to rounding: the
  // pipeline passes the constraint points as coordinates, projected again).
  vtkNew<vtkStrokeCut> cut;
  cut->SetInputData(0, cylinder);
  cut->SetInputData(1, stroke);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(cut).empty());
  vtkNew<vtkStrokeConstraints> constraints;
  constraints->SetInputData(0, cylinder);
  constraints->SetInputData(1, stroke);
  vtkNew<vtkHarmonicField> field;
  field->SetInputData(0, cylinder);
  field->SetInputConnection(1, constraints->GetOutputPort());
  vtkNew<vtkIsolineCut> isoline;
  isoline->SetInputConnection(0, field->GetOutputPort());
  isoline->SetInputData(1, stroke);
  isoline->SetModeToNearStroke();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(isoline).empty());
  ok &= KERF_CHECK(sameArrays(cut->GetOutput()->GetPointData()->GetArray("HarmonicField"),
    field->GetOutput()->GetPointData()->GetArray("HarmonicField"), 1e-9));
  ok &= KERF_CHECK(sameArrays(cut->GetOutput()->GetCellData()->GetArray("Segment"),
    isoline->GetLabelledSurface()->GetCellData()->GetArray("Segment")));
  ok &= KERF_CHECK(cut->GetCut()->GetNumberOfLines() == 1);
  for (vtkIdType i = 0; i < cut->GetCut()->GetNumberOfPoints(); ++i)
  {
    ok &= KERF_CHECK(std::abs(cut->GetCut()->GetPoint(i)[2] - 1.5) < 0.02);
  }

  // Panel points away from the surface are moved onto it first: a stroke of points outside
  // the cylinder at radius 1.5 cuts where one on it does.
  vtkNew<vtkStrokeCut> panel;
  panel->SetInputData(cylinder);
  for (int i = 0; i <= 12; ++i)
  {
    const double a = 2.0 * Pi * (i % 12) / 12.0;
    panel->SetStrokePoint(i, 1.5 * std::cos(a), 1.5 * std::sin(a), 2.5);
  }
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(panel).empty());
  ok &= KERF_CHECK(solverWork(panel->GetOutput()) == "factorization");
  double mean = 0.0;
  for (vtkIdType i = 0; i < panel->GetCut()->GetNumberOfPoints(); ++i)
  {
    mean += panel->GetCut()->GetPoint(i)[2] / panel->GetCut()->GetNumberOfPoints();
  }
  ok &= KERF_CHECK(std::abs(mean - 2.5) < 0.02);
  // Moving the stroke keeps the factorization; sliding the iso-value only moves the cut.
  panel->SetStrokePoint(0, 1.5, 0.0, 2.6);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(panel).empty());
  ok &= KERF_CHECK(solverWork(panel->GetOutput()) == "update");
  panel->SetIsoValue(0.5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(panel).empty());
  ok &= KERF_CHECK(solverWork(panel->GetOutput()) != "factorization");

  // Strokes drawn in the panel replace the typed stroke: the same twelve points drawn as two
  // strokes (sizes 6 and 7, the seventh point repeated) cut where the typed ones do.
  vtkNew<vtkStrokeCut> drawn;
  drawn->SetInputData(cylinder);
  drawn->SetStrokePoint(0, 0.0, 0.0, 0.5); // a typed stroke elsewhere, which the drawn ones replace
  drawn->SetStrokePoint(1, 0.0, 1.0, 0.5);
  vtkNew<vtkPoints> first, second;
  for (int i = 0; i <= 12; ++i)
  {
    const double a = 2.0 * Pi * (i % 12) / 12.0;
    (i <= 6 ? first : second)->InsertNextPoint(1.5 * std::cos(a), 1.5 * std::sin(a), 2.6);
    if (i == 6)
    {
      second->InsertNextPoint(1.5 * std::cos(a), 1.5 * std::sin(a), 2.6);
    }
  }
  drawn->AddDrawnStroke(first);
  drawn->AddDrawnStroke(second);
  ok &= KERF_CHECK(drawn->GetNumberOfDrawnStrokePoints() == 14 && drawn->GetNumberOfDrawnStrokeSizes() == 2);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(drawn).empty());
  vtkNew<vtkStrokeCut> typed;
  typed->SetInputData(cylinder);
  for (int i = 0; i <= 12; ++i)
  {
    const double a = 2.0 * Pi * (i % 12) / 12.0;
    typed->SetStrokePoint(i, 1.5 * std::cos(a), 1.5 * std::sin(a), 2.6);
  }
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(typed).empty());
  ok &= KERF_CHECK(sameArrays(
    drawn->GetOutput()->GetCellData()->GetArray("Segment"), typed->GetOutput()->GetCellData()->GetArray("Segment")));
  vtkDataArray* sizes = drawn->GetOutput()->GetFieldData()->GetArray("SegmentSizes");
  ok &= KERF_CHECK(sizes && sizes->GetNumberOfTuples() == 2 &&
    sizes->GetComponent(0, 0) + sizes->GetComponent(1, 0) == cylinder->GetNumberOfCells());
  // Forgetting them brings the typed stroke back; sizes that do not add up are refused.
  drawn->RemoveAllDrawnStrokes();
  ok &= KERF_CHECK(drawn->GetNumberOfDrawnStrokePoints() == 0 && kerf::test::UpdateAndCaptureError(drawn).empty());
  drawn->AddDrawnStroke(first);
  drawn->SetDrawnStrokeSize(0, 5);
  ok &= KERF_CHECK(
    kerf::test::UpdateAndCaptureError(drawn).find("add up to 5 points, but 7 are drawn") != std::string::npos);

  // On a surface of two components, a stroke on one cuts it and leaves the other whole.
  vtkSmartPointer<vtkPolyData> twoTubes = kerf::test::ToPolyData(kerf::makeCylinder(1.0, 5.0, 32, 21));
  {
    const vtkIdType pointCount = twoTubes->GetNumberOfPoints();
    vtkNew<vtkPoints> points;
    points->DeepCopy(twoTubes->GetPoints());
    vtkNew<vtkCellArray> triangles;
    triangles->DeepCopy(twoTubes->GetPolys());
    for (vtkIdType i = 0; i < pointCount; ++i)
    {
      double p[3];
      twoTubes->GetPoint(i, p);
      points->InsertNextPoint(p[0] + 4.0, p[1], p[2]);
    }
    for (vtkIdType c = 0; c < twoTubes->GetNumberOfPolys(); ++c)
    {
      vtkIdType size;
      const vtkIdType* ids;
      twoTubes->GetPolys()->GetCellAtId(c, size, ids);
      const vtkIdType shifted[3] = { ids[0] + pointCount, ids[1] + pointCount, ids[2] + pointCount };
      triangles->InsertNextCell(3, shifted);
    }
    twoTubes = vtkSmartPointer<vtkPolyData>::New();
    twoTubes->SetPoints(points);
    twoTubes->SetPolys(triangles);
  }
  vtkNew<vtkStrokeCut> one;
  one->SetInputData(twoTubes);
  one->AddDrawnStroke(first);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(one).empty());
  vtkDataArray* twoSizes = one->GetOutput()->GetFieldData()->GetArray("SegmentSizes");
  ok &= KERF_CHECK(twoSizes && twoSizes->GetNumberOfTuples() == 3);
  if (twoSizes && twoSizes->GetNumberOfTuples() == 3)
  {
    // The untouched tube is one segment of all its faces.
    const double tube = 0.5 * twoTubes->GetNumberOfCells();
    ok &= KERF_CHECK(twoSizes->GetComponent(0, 0) == tube || twoSizes->GetComponent(1, 0) == tube ||
      twoSizes->GetComponent(2, 0) == tube);
  }

  // Errors name the cause, in the panel's words.
  vtkNew<vtkStrokeCut> none;
  none->SetInputData(cylinder);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(none).find("hold Ctrl and drag") != std::string::npos);
  vtkNew<vtkStrokeCut> huge;
  huge->SetInputData(cylinder);
  huge->SetStrokePoint(0, 1e300, 0, 0);
  huge->SetStrokePoint(1, 1, 0, 0);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(huge).find("huge coordinate") != std::string::npos);
  vtkNew<vtkStrokeCut> nanIso;
  nanIso->SetInputData(0, cylinder);
  nanIso->SetInputData(1, stroke);
  nanIso->SetIsoValue(std::nan(""));
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(nanIso).find("must be finite") != std::string::npos);
  return ok ? 0 : 1;
}
