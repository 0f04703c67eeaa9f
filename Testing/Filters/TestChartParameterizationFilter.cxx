// vtkChartParameterization as a VTK filter: the Core's texture coordinates with either method (LSCM, LinABF), the
// arrays, the layout, the errors, the input untouched.
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "Parameterization/ChartParameterization.h"
#include "vtkChartParameterization.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <sstream>
#include <string>

namespace
{
// `mesh` with the cell array `name` holding `labels`.
vtkSmartPointer<vtkPolyData> labelled(const kerf::TriangleMesh& mesh, const std::vector<int>& labels, const char* name)
{
  vtkSmartPointer<vtkPolyData> surface = kerf::test::ToPolyData(mesh);
  vtkNew<vtkIntArray> array;
  array->SetName(name);
  for (int label : labels)
  {
    array->InsertNextValue(label);
  }
  surface->GetCellData()->AddArray(array);
  return surface;
}

double fieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return array ? array->GetTuple1(0) : std::nan("");
}

kerf::ChartMethod coreMethod(int method)
{
  return method == vtkChartParameterization::LINABF ? kerf::ChartMethod::LinABF : kerf::ChartMethod::LSCM;
}

bool developableCylinder(int method)
{
  bool ok = true;
  const kerf::TriangleMesh cylinder = kerf::makeSlitCylinder(1.0, 2.0, 32, 8);
  vtkSmartPointer<vtkPolyData> input =
    labelled(cylinder, std::vector<int>(static_cast<std::size_t>(cylinder.faceCount()), 4), "Chart");
  const vtkMTimeType inputTime = input->GetMTime();
  vtkNew<vtkChartParameterization> filter;
  filter->SetInputData(input);
  filter->SetMethod(method);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(filter).empty());
  vtkPolyData* output = filter->GetOutput(0);
  vtkDataArray* uv = output->GetPointData()->GetTCoords();
  ok &= KERF_CHECK(uv && std::string(uv->GetName()) == "UV" && uv->GetNumberOfComponents() == 2);
  ok &= KERF_CHECK(uv && uv->GetDataType() == VTK_FLOAT);
  ok &= KERF_CHECK(
    output->GetNumberOfPoints() == cylinder.vertexCount() && output->GetNumberOfCells() == cylinder.faceCount());
  vtkDataArray* stretch = output->GetCellData()->GetArray("Stretch");
  vtkDataArray* shear = output->GetCellData()->GetArray("Shear");
  vtkDataArray* flipped = output->GetCellData()->GetArray("Flipped");
  vtkDataArray* chart = output->GetCellData()->GetArray("Chart");
  ok &= KERF_CHECK(stretch && shear && flipped && chart && output->GetPointData()->GetArray("OriginalPointId"));
  for (vtkIdType c = 0; stretch && shear && flipped && chart && c < output->GetNumberOfCells(); ++c)
  {
    ok &= KERF_CHECK(std::abs(stretch->GetTuple1(c) - 1.0) < 1e-6 && std::abs(shear->GetTuple1(c) - 1.0) < 1e-6);
    ok &= KERF_CHECK(flipped->GetTuple1(c) == 0 && chart->GetTuple1(c) == 4);
  }
  ok &= KERF_CHECK(fieldValue(output, "FlippedFaces") == 0 && fieldValue(output, "OverlappingChartPairs") == 0);
  ok &= KERF_CHECK(std::abs(fieldValue(output, "MeanStretch") - 1.0) < 1e-6);
  ok &= KERF_CHECK(input->GetMTime() == inputTime && input->GetPointData()->GetNumberOfArrays() == 0);
  ok &= KERF_CHECK(input->GetCellData()->GetNumberOfArrays() == 1);
  return ok;
}

bool segmentsMatchTheCore(int method)
{
  bool ok = true;
  const kerf::TriangleMesh sphere = kerf::makeIcosphere(1.0, 3);
  const std::vector<int> labels = kerf::octantLabels(sphere);
  vtkSmartPointer<vtkPolyData> input = labelled(sphere, labels, "Segment");
  vtkNew<vtkChartParameterization> filter;
  filter->SetInputData(input);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Segment");
  filter->SetMargin(0.03);
  filter->SetMethod(method);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(filter).empty());
  kerf::ChartParameterizationOptions options;
  options.margin = 0.03;
  options.method = coreMethod(method);
  const kerf::ChartParameterizationResult core = kerf::parameterizeCharts(sphere, labels, options);
  vtkPolyData* output = filter->GetOutput(0);
  vtkPolyData* layout = filter->GetOutput(1);
  vtkDataArray* uv = output->GetPointData()->GetArray("UV");
  ok &= KERF_CHECK(uv && uv->GetNumberOfTuples() == static_cast<vtkIdType>(core.uv.size()));
  ok &= KERF_CHECK(layout->GetNumberOfPoints() == output->GetNumberOfPoints() &&
    layout->GetNumberOfCells() == output->GetNumberOfCells());
  for (vtkIdType v = 0; uv && v < uv->GetNumberOfTuples(); ++v)
  {
    const kerf::Vector2& expected = core.uv[static_cast<std::size_t>(v)];
    // Single precision, as textures are.
    const double u = static_cast<float>(expected.x());
    const double w = static_cast<float>(expected.y());
    ok &= KERF_CHECK(uv->GetComponent(v, 0) == u && uv->GetComponent(v, 1) == w);
    double p[3];
    layout->GetPoint(v, p);
    ok &= KERF_CHECK(p[0] == u && p[1] == w && p[2] == 0.0);
  }
  ok &= KERF_CHECK(fieldValue(output, "ChartCount") == 8 && fieldValue(layout, "ChartCount") == 8);
  ok &= KERF_CHECK(output->GetCellData()->GetArray("Segment") != nullptr);
  vtkDataArray* perChart = vtkDataArray::SafeDownCast(output->GetFieldData()->GetAbstractArray("ChartMeanStretch"));
  ok &= KERF_CHECK(
    perChart && perChart->GetNumberOfTuples() == 8 && perChart->GetTuple1(3) == core.charts[3].distortion.meanStretch);
  ok &= KERF_CHECK(fieldValue(output, "FlippedFaces") == 0 && fieldValue(output, "OverlappingChartPairs") == 0);
  return ok;
}

// The method: LSCM by default, clamped to the two methods, and a LinABF map that differs from LSCM's.
bool methodProperty()
{
  bool ok = true;
  vtkNew<vtkChartParameterization> filter;
  ok &= KERF_CHECK(filter->GetMethod() == vtkChartParameterization::LSCM);
  filter->SetMethodToLinABF();
  ok &= KERF_CHECK(filter->GetMethod() == vtkChartParameterization::LINABF);
  filter->SetMethod(7);
  ok &= KERF_CHECK(filter->GetMethod() == vtkChartParameterization::LINABF);
  filter->SetMethodToLSCM();
  ok &= KERF_CHECK(filter->GetMethod() == vtkChartParameterization::LSCM);
  std::ostringstream printed;
  filter->SetMethodToLinABF();
  filter->Print(printed);
  ok &= KERF_CHECK(printed.str().find("Method: LinABF") != std::string::npos);
  // On the octants of a sphere the two maps differ, and LinABF's worst shear is the lower.
  const kerf::TriangleMesh sphere = kerf::makeIcosphere(1.0, 3);
  filter->SetInputData(labelled(sphere, kerf::octantLabels(sphere), "Chart"));
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(filter).empty());
  const double angularShear = fieldValue(filter->GetOutput(0), "MaxShear");
  filter->SetMethodToLSCM();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(filter).empty());
  const double conformalShear = fieldValue(filter->GetOutput(0), "MaxShear");
  ok &= KERF_CHECK(angularShear != conformalShear && angularShear < conformalShear);
  return ok;
}

bool errors()
{
  bool ok = true;
  struct Case
  {
    vtkSmartPointer<vtkPolyData> input;
    std::string expected;
  };
  const kerf::TriangleMesh sphere = kerf::makeIcosphere(1.0, 2);
  const kerf::TriangleMesh torus = kerf::makeTorus(1.0, 0.3, 24, 12);
  const Case cases[] = {
    { labelled(sphere, std::vector<int>(static_cast<std::size_t>(sphere.faceCount()), 2), "Chart"),
      "chart 2: it has 0 boundary loops and genus 0" },
    { labelled(torus, std::vector<int>(static_cast<std::size_t>(torus.faceCount()), 0), "Chart"), "genus 1" },
    { labelled(sphere, std::vector<int>(static_cast<std::size_t>(sphere.faceCount()), 0), "Other"),
      "no one-component cell array named 'Chart'" },
    { labelled(sphere, std::vector<int>(static_cast<std::size_t>(sphere.faceCount()), -3), "Chart"), "not a label" },
  };
  for (int method : { vtkChartParameterization::LSCM, vtkChartParameterization::LINABF })
  {
    for (const Case& c : cases)
    {
      vtkNew<vtkChartParameterization> filter;
      filter->SetInputData(c.input);
      filter->SetMethod(method);
      filter->CutToDisksOff();
      const vtkMTimeType inputTime = c.input->GetMTime();
      const std::string error = kerf::test::UpdateAndCaptureError(filter);
      ok &= KERF_CHECK(error.find(c.expected) != std::string::npos);
      if (error.find(c.expected) == std::string::npos)
      {
        std::cerr << "expected '" << c.expected << "' in: " << error << "\n";
      }
      ok &=
        KERF_CHECK(filter->GetOutput(0)->GetNumberOfPoints() == 0 && filter->GetOutput(1)->GetNumberOfPoints() == 0);
      ok &= KERF_CHECK(c.input->GetMTime() == inputTime && c.input->GetPointData()->GetNumberOfArrays() == 0);
    }
  }
  return ok;
}

// A torus (genus 1) as one chart: cut into a disk by default, the cut reported in the field data.
bool torusCutIntoADisk()
{
  bool ok = true;
  const kerf::TriangleMesh torus = kerf::makeTorus(1.0, 0.3, 24, 12);
  vtkSmartPointer<vtkPolyData> input =
    labelled(torus, std::vector<int>(static_cast<std::size_t>(torus.faceCount()), 6), "Chart");
  vtkNew<vtkChartParameterization> filter;
  filter->SetInputData(input);
  ok &= KERF_CHECK(filter->GetCutToDisks());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(filter).empty());
  const kerf::ChartParameterizationResult core =
    kerf::parameterizeCharts(torus, std::vector<int>(static_cast<std::size_t>(torus.faceCount()), 6));
  vtkPolyData* output = filter->GetOutput(0);
  ok &= KERF_CHECK(output->GetNumberOfPoints() == core.split.mesh.vertexCount());
  ok &= KERF_CHECK(output->GetNumberOfPoints() > torus.vertexCount());
  vtkFieldData* field = output->GetFieldData();
  ok &= KERF_CHECK(field->GetArray("CutCharts")->GetTuple1(0) == 1.0);
  ok &= KERF_CHECK(field->GetArray("ChartCutEdges")->GetTuple1(0) == core.charts[0].cutEdgeCount);
  ok &= KERF_CHECK(field->GetArray("ChartCutLength")->GetTuple1(0) == core.charts[0].cutLength);
  ok &= KERF_CHECK(field->GetArray("OverlappingChartPairs")->GetTuple1(0) == 0.0);
  // Every output point copies the input point it names.
  vtkDataArray* ids = output->GetPointData()->GetArray("OriginalPointId");
  for (vtkIdType v = 0; v < output->GetNumberOfPoints(); ++v)
  {
    double p[3], q[3];
    output->GetPoint(v, p);
    input->GetPoint(static_cast<vtkIdType>(ids->GetTuple1(v)), q);
    ok &= KERF_CHECK(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
  }
  return ok;
}
} // namespace

int TestChartParameterizationFilter(int, char*[])
{
  bool ok = true;
  for (int method : { vtkChartParameterization::LSCM, vtkChartParameterization::LINABF })
  {
    ok &= developableCylinder(method);
    ok &= segmentsMatchTheCore(method);
  }
  ok &= methodProperty();
  ok &= errors();
  ok &= torusCutIntoADisk();
  return ok ? 0 : 1;
}
