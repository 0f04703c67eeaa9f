// vtkSegmentationMetrics as a VTK filter: one input with two arrays, two inputs, polygons, and
// the errors for wrong arrays and different meshes.
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkSegmentationMetrics.h"

#include <vtkCellData.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <cmath>
#include <functional>
#include <iostream>

namespace
{
vtkSmartPointer<vtkIntArray> columnLabels(const char* name, const std::vector<int>& perColumn)
{
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(name);
  for (int label : perColumn)
  {
    array->InsertNextValue(label); // two triangles per grid cell
    array->InsertNextValue(label);
  }
  return array;
}

double value(vtkTable* table, const char* column)
{
  return table->GetValueByName(0, column).ToDouble();
}
} // namespace

int TestSegmentationMetricsFilter(int, char*[])
{
  bool ok = true;
  // The 4 x 1 strip of Testing/Core's hand-computed case: S1 cut at x = 2, S2 at x = 1.
  vtkSmartPointer<vtkPolyData> strip = kerf::test::ToPolyData(kerf::makeGrid(4.0, 1.0, 4, 1));
  strip->GetCellData()->AddArray(columnLabels("Segment", { 0, 0, 1, 1 }));
  strip->GetCellData()->AddArray(columnLabels("Human", { 5, 9, 9, 9 }));

  vtkNew<vtkSegmentationMetrics> oneInput;
  oneInput->SetInputData(strip);
  oneInput->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Human");
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(oneInput).empty());
  vtkTable* table = oneInput->GetOutput();
  ok &= KERF_CHECK(table->GetNumberOfRows() == 1);
  ok &= KERF_CHECK(value(table, "MissingRate") == 0.25);
  ok &= KERF_CHECK(value(table, "FalseAlarmRate") == 0.25);
  ok &= KERF_CHECK(value(table, "HammingDistance") == 0.25);
  ok &= KERF_CHECK(std::abs(value(table, "RandIndexError") - 12.0 / 28.0) < 1e-15);
  ok &= KERF_CHECK(value(table, "GlobalConsistencyError") == 0.25);
  ok &= KERF_CHECK(value(table, "LocalConsistencyError") == 0.125);
  const double radius = (2.0 * std::sqrt(4.25) + 2.0 * std::sqrt(1.25) + 0.5) / 5.0;
  ok &= KERF_CHECK(std::abs(value(table, "CutDiscrepancy") - 2.0 / radius) < 1e-12);
  ok &= KERF_CHECK(value(table, "EvaluatedSegments") == 2 && value(table, "ReferenceSegments") == 2);
  ok &= KERF_CHECK(value(table, "ComparedFaces") == 8 && value(table, "CutsCompared") == 1);

  // The same comparison with the reference on a second input.
  vtkNew<vtkPolyData> second;
  second->DeepCopy(strip);
  second->GetCellData()->RemoveArray("Segment");
  second->GetCellData()->GetArray("Human")->SetName("Segment");
  vtkNew<vtkSegmentationMetrics> twoInputs;
  twoInputs->SetInputData(0, strip);
  twoInputs->SetInputData(1, second);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(twoInputs).empty());
  ok &= KERF_CHECK(value(twoInputs->GetOutput(), "RandIndexError") == value(table, "RandIndexError"));
  ok &= KERF_CHECK(value(twoInputs->GetOutput(), "CutDiscrepancy") == value(table, "CutDiscrepancy"));

  // Quads: each triangle takes its quad's label; identical labellings score 0.
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(6, 2);
  plane->Update();
  vtkNew<vtkPolyData> quads;
  quads->ShallowCopy(plane->GetOutput());
  vtkNew<vtkIntArray> quadLabels;
  quadLabels->SetName("Segment");
  for (vtkIdType c = 0; c < quads->GetNumberOfCells(); ++c)
  {
    quadLabels->InsertNextValue(static_cast<int>(c % 6 < 3));
  }
  quads->GetCellData()->AddArray(quadLabels);
  vtkNew<vtkSegmentationMetrics> onQuads;
  onQuads->SetInputData(quads);
  onQuads->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Segment");
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(onQuads).empty());
  ok &= KERF_CHECK(value(onQuads->GetOutput(), "ComparedFaces") == 24);
  ok &= KERF_CHECK(value(onQuads->GetOutput(), "RandIndexError") == 0.0);

  // Errors: no second input, a missing array, wrong length, a non-integral label, two meshes.
  struct Case
  {
    const char* name;
    std::function<void(vtkSegmentationMetrics*)> setup;
    const char* expected;
  };
  vtkSmartPointer<vtkPolyData> bigger = kerf::test::ToPolyData(kerf::makeGrid(4.0, 1.0, 5, 1));
  vtkNew<vtkPolyData> shortArray;
  shortArray->DeepCopy(strip);
  vtkNew<vtkIntArray> tooShort;
  tooShort->SetName("Human");
  tooShort->InsertNextValue(1);
  shortArray->GetCellData()->AddArray(tooShort);
  vtkNew<vtkPolyData> fractional;
  fractional->DeepCopy(strip);
  vtkNew<vtkDoubleArray> halves;
  halves->SetName("Human");
  for (int c = 0; c < 8; ++c)
  {
    halves->InsertNextValue(c * 0.5);
  }
  fractional->GetCellData()->AddArray(halves);
  const Case cases[] = {
    { "second input missing", [&](vtkSegmentationMetrics* m) { m->SetInputData(strip); },
      "input 1, which is not connected" },
    { "missing array",
      [&](vtkSegmentationMetrics* m) {
        m->SetInputData(strip);
        m->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Nope");
      },
      "the reference segmentation has no one-component cell array named 'Nope'" },
    { "wrong length",
      [&](vtkSegmentationMetrics* m) {
        m->SetInputData(shortArray);
        m->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Human");
      },
      "has 1 values for 8 cells" },
    { "fractional label",
      [&](vtkSegmentationMetrics* m) {
        m->SetInputData(fractional);
        m->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Human");
      },
      "not a label" },
    { "empty mesh",
      [&](vtkSegmentationMetrics* m) {
        m->SetInputData(vtkSmartPointer<vtkPolyData>::New());
        m->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Human");
      },
      "no triangles" },
    { "NaN point",
      [&](vtkSegmentationMetrics* m) {
        auto broken = vtkSmartPointer<vtkPolyData>::New();
        broken->DeepCopy(strip);
        broken->GetPoints()->SetPoint(3, std::nan(""), 0.0, 0.0);
        m->SetInputData(broken);
        m->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Human");
      },
      "NaN" },
    { "different meshes",
      [&](vtkSegmentationMetrics* m) {
        m->SetInputData(0, strip);
        m->SetInputData(1, bigger);
      },
      "different meshes" },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkSegmentationMetrics> metrics;
    c.setup(metrics);
    int succeeded = 1;
    const std::string error = kerf::test::UpdateAndCaptureError(metrics, &succeeded);
    std::cout << c.name << ": " << error << std::endl;
    ok &= KERF_CHECK(succeeded == 0 && error.find(c.expected) != std::string::npos);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
