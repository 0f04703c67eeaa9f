// The stroke pipeline (vtkStrokeConstraints -> vtkHarmonicField -> vtkIsolineCut): the cut
// follows the stroke, sliding moves it without solving again, and ROI Scissor's best score finds
// a neck.
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkHarmonicField.h"
#include "vtkIsolineCut.h"
#include "vtkStrokeConstraints.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <set>

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A half circle of radius r at height z around the z axis, as one polyline.
vtkSmartPointer<vtkPolyData> halfCircle(double r, double z, int points)
{
  auto stroke = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> line;
  line->InsertNextCell(points);
  for (int i = 0; i < points; ++i)
  {
    const double a = Pi * i / (points - 1);
    line->InsertCellPoint(pts->InsertNextPoint(r * std::cos(a), r * std::sin(a), z));
  }
  stroke->SetPoints(pts);
  stroke->SetLines(line);
  return stroke;
}

// Largest distance of the cut's points from the plane z = height, and their mean z.
void cutHeights(vtkPolyData* cut, double height, double& worst, double& mean)
{
  worst = 0.0;
  mean = 0.0;
  for (vtkIdType i = 0; i < cut->GetNumberOfPoints(); ++i)
  {
    worst = std::max(worst, std::abs(cut->GetPoint(i)[2] - height));
    mean += cut->GetPoint(i)[2];
  }
  mean /= std::max<vtkIdType>(1, cut->GetNumberOfPoints());
}
} // namespace

int TestHarmonicCut(int, char*[])
{
  bool ok = true;
  // An open cylinder (radius 1, height 4) and a stroke half way round it at mid height.
  vtkSmartPointer<vtkPolyData> cylinder = kerf::test::ToPolyData(kerf::makeCylinder(1.0, 4.0, 96, 97));
  vtkSmartPointer<vtkPolyData> stroke = halfCircle(1.0, 2.0, 7);

  vtkNew<vtkStrokeConstraints> constraints;
  constraints->SetInputData(0, cylinder);
  constraints->SetInputData(1, stroke);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(constraints).empty());
  vtkPolyData* points = constraints->GetOutput();
  ok &= KERF_CHECK(points->GetNumberOfPoints() == 2 * 4 * 6);
  vtkDataArray* values = points->GetPointData()->GetArray("ConstraintValue");
  const double offset = constraints->GetOffset() * std::sqrt(2.0 * 2.0 + 2.0 * 2.0 + 4.0 * 4.0);
  ok &= KERF_CHECK(constraints->GetOffset() == 0.005); // the default
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    // Pairs above and below the stroke, eps_C away along the cylinder.
    const double z = points->GetPoint(i)[2];
    ok &= KERF_CHECK(std::abs(std::abs(z - 2.0) - offset) < 0.02 * offset);
    ok &= KERF_CHECK(std::abs(values->GetComponent(i, 0)) == 1.0);
    ok &= KERF_CHECK((values->GetComponent(i, 0) > 0) == (i % 2 == 0));
  }
  ok &= KERF_CHECK(values->GetComponent(0, 0) * (points->GetPoint(0)[2] - 2.0) * values->GetComponent(1, 0) *
      (points->GetPoint(1)[2] - 2.0) >
    0.0);

  vtkNew<vtkHarmonicField> field;
  field->SetInputData(0, cylinder);
  field->SetInputConnection(1, constraints->GetOutputPort());
  vtkNew<vtkIsolineCut> cut;
  cut->SetInputConnection(field->GetOutputPort());
  cut->SetInputData(1, stroke);
  cut->SetModeToNearStroke();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(cut).empty());
  vtkPolyData* curve = cut->GetOutput();
  double worst, mean;
  cutHeights(curve, 2.0, worst, mean);
  std::cout << "cut: " << curve->GetNumberOfCells() << " curve(s), farthest point " << worst << " from z = 2"
            << std::endl;
  ok &= KERF_CHECK(curve->GetNumberOfCells() == 1);
  ok &= KERF_CHECK(curve->GetCellData()->GetArray("Closed")->GetComponent(0, 0) == 1);
  ok &= KERF_CHECK(worst < 0.1);
  ok &= KERF_CHECK(std::abs(curve->GetCellData()->GetArray("Length")->GetComponent(0, 0) - 2.0 * Pi) < 0.05 * 2.0 * Pi);
  vtkDataArray* segments = cut->GetLabelledSurface()->GetCellData()->GetArray("Segment");
  ok &= KERF_CHECK(segments && segments->GetRange()[0] == 0 && segments->GetRange()[1] == 1);

  // Sliding: a new iso-value re-runs only the isoline filter; the field stays bit for bit.
  vtkNew<vtkDoubleArray> before;
  before->DeepCopy(cut->GetLabelledSurface()->GetPointData()->GetArray("HarmonicField"));
  const vtkMTimeType fieldTime = field->GetOutput()->GetMTime();
  cut->SetIsoValue(0.5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(cut).empty());
  ok &= KERF_CHECK(field->GetOutput()->GetMTime() == fieldTime);
  vtkDataArray* after = cut->GetLabelledSurface()->GetPointData()->GetArray("HarmonicField");
  for (vtkIdType i = 0; i < before->GetNumberOfTuples(); ++i)
  {
    if (before->GetValue(i) != after->GetComponent(i, 0))
    {
      ok &= KERF_CHECK(false && "sliding changed the field");
      break;
    }
  }
  double slidMean;
  cutHeights(cut->GetOutput(), 2.0, worst, slidMean);
  std::cout << "slid cut: mean height " << slidMean << " (was " << mean << ")" << std::endl;
  ok &= KERF_CHECK(std::abs(slidMean - mean) > 0.005);

  // VALUE mode keeps every component; BEST_SCORE on a dumbbell with hard tips finds the neck.
  const double halfLength = 2.2, neckHeight = 0.3, depth = 0.65;
  vtkSmartPointer<vtkPolyData> dumbbell =
    kerf::test::ToPolyData(kerf::makeDumbbell(halfLength, { { 1.0, 0.8 } }, neckHeight, depth, 5));
  vtkNew<vtkDoubleArray> tips;
  tips->SetName("Tips");
  for (vtkIdType i = 0; i < dumbbell->GetNumberOfPoints(); ++i)
  {
    const double z = dumbbell->GetPoint(i)[2];
    tips->InsertNextValue(
      std::abs(z) > 0.9 * halfLength ? (z > 0 ? 1.0 : 0.0) : std::numeric_limits<double>::quiet_NaN());
  }
  dumbbell->GetPointData()->AddArray(tips);
  vtkNew<vtkHarmonicField> neckField;
  neckField->SetInputData(dumbbell);
  neckField->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Tips");
  neckField->UseHardValuesOn();
  neckField->SetWeightingToConcavityAware();
  vtkNew<vtkIsolineCut> best;
  best->SetInputConnection(neckField->GetOutputPort());
  best->SetModeToBestScore();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(best).empty());
  vtkTable* candidates = best->GetCandidates();
  ok &= KERF_CHECK(candidates->GetNumberOfRows() == 50);
  double bestScore = -1.0, bestValue = 0.0;
  for (vtkIdType r = 0; r < candidates->GetNumberOfRows(); ++r)
  {
    const double score = candidates->GetValueByName(r, "Score").ToDouble();
    if (score > bestScore)
    {
      bestScore = score;
      bestValue = candidates->GetValueByName(r, "IsoValue").ToDouble();
    }
  }
  ok &= KERF_CHECK(best->GetOutput()->GetCellData()->GetArray("IsoValue")->GetComponent(0, 0) == bestValue);
  double zNeck = 0.0, rNeck = 1e300;
  for (double z = -0.5 * halfLength; z <= 0.5 * halfLength; z += 1e-4)
  {
    const double r = kerf::dumbbellRadius(z, halfLength, { { 1.0, 0.8 } }, neckHeight, depth);
    if (r < rNeck)
    {
      rNeck = r;
      zNeck = z;
    }
  }
  cutHeights(best->GetOutput(), zNeck, worst, mean);
  std::cout << "best score: iso-value " << bestValue << ", farthest point " << worst << " from the neck" << std::endl;
  ok &= KERF_CHECK(worst < 0.08);
  std::set<int> labels;
  vtkDataArray* neckSegments = best->GetLabelledSurface()->GetCellData()->GetArray("Segment");
  for (vtkIdType c = 0; c < neckSegments->GetNumberOfTuples(); ++c)
  {
    labels.insert(static_cast<int>(neckSegments->GetComponent(c, 0)));
  }
  ok &= KERF_CHECK(labels.size() == 2);

  // With no array name selected, the field is the active point scalars: the same field under
  // another name, made active, gives the same best isoline.
  vtkNew<vtkPolyData> renamed;
  renamed->ShallowCopy(neckField->GetOutput());
  vtkNew<vtkDoubleArray> activeField;
  activeField->DeepCopy(renamed->GetPointData()->GetArray("HarmonicField"));
  activeField->SetName("Potential");
  renamed->GetPointData()->RemoveArray("HarmonicField");
  renamed->GetPointData()->SetScalars(activeField);
  vtkNew<vtkIsolineCut> unnamed;
  unnamed->SetInputData(renamed);
  unnamed->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "");
  unnamed->SetModeToBestScore();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(unnamed).empty());
  ok &= KERF_CHECK(unnamed->GetOutput()->GetCellData()->GetArray("IsoValue")->GetComponent(0, 0) == bestValue);
  renamed->GetPointData()->SetActiveScalars(nullptr);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(unnamed).find("no active point scalars") != std::string::npos);

  // Errors.
  vtkNew<vtkIsolineCut> noStroke;
  noStroke->SetInputConnection(field->GetOutputPort());
  noStroke->SetModeToNearStroke();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(noStroke).find("needs a stroke") != std::string::npos);
  vtkNew<vtkIsolineCut> noField;
  noField->SetInputData(cylinder);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(noField).find("one-component point array") != std::string::npos);
  vtkNew<vtkDoubleArray> constant;
  constant->SetName("HarmonicField");
  constant->SetNumberOfValues(cylinder->GetNumberOfPoints());
  constant->Fill(3.0);
  vtkNew<vtkPolyData> flat;
  flat->ShallowCopy(cylinder);
  flat->GetPointData()->AddArray(constant);
  vtkNew<vtkIsolineCut> flatScore;
  flatScore->SetInputData(flat);
  flatScore->SetModeToBestScore();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(flatScore).find("constant") != std::string::npos);
  vtkNew<vtkStrokeConstraints> farStroke;
  farStroke->SetInputData(0, cylinder);
  farStroke->SetInputData(1, halfCircle(3.0, 2.0, 5));
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(farStroke).find("away from the surface") != std::string::npos);
  vtkNew<vtkStrokeConstraints> noStrokeAtAll;
  noStrokeAtAll->SetInputData(0, cylinder);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(noStrokeAtAll).find("there is no stroke") != std::string::npos);
  vtkNew<vtkStrokeConstraints> onePoint;
  onePoint->SetInputData(0, cylinder);
  onePoint->SetNumberOfStrokePoints(2);
  onePoint->SetStrokePoint(0, 1, 0, 2);
  onePoint->SetStrokePoint(1, 1, 0, 2);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(onePoint).find("two distinct points") != std::string::npos);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
