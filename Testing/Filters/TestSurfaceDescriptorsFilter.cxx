// vtkSurfaceDescriptors as a VTK filter: arrays and names, polygons and strips, untouched input,
// determinism, and agreement with the Core on a sphere.
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkSurfaceDescriptors.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkStripper.h>
#include <vtkTriangleFilter.h>

#include <cmath>

namespace
{
bool sameValues(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      if (a->GetComponent(i, c) != b->GetComponent(i, c))
      {
        return false;
      }
    }
  }
  return true;
}
} // namespace

int TestSurfaceDescriptorsFilter(int, char*[])
{
  bool ok = true;
  const double radius = 3.0;
  vtkSmartPointer<vtkPolyData> sphere = kerf::test::ToPolyData(kerf::makeIcosphere(radius, 4));
  vtkNew<vtkIntArray> marker;
  marker->SetName("Marker");
  marker->SetNumberOfValues(sphere->GetNumberOfCells());
  for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
  {
    marker->SetValue(c, static_cast<int>(c % 7));
  }
  sphere->GetCellData()->AddArray(marker);
  const vtkMTimeType inputTime = sphere->GetMTime();

  vtkNew<vtkSurfaceDescriptors> filter;
  filter->SetInputData(sphere);
  filter->SetMeanCurvatureArrayName("H");
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(filter).empty());
  vtkPolyData* output = filter->GetOutput();
  const char* expected[] = { "Normals", "MaximumCurvature", "MinimumCurvature", "MaximumCurvatureDirection",
    "MinimumCurvatureDirection", "H", "GaussianCurvature", "Concave", "NormalConeAngle" };
  for (const char* name : expected)
  {
    ok &= KERF_CHECK(output->GetPointData()->GetArray(name) != nullptr);
  }
  ok &= KERF_CHECK(output->GetPointData()->GetArray("MeanCurvature") == nullptr);
  ok &= KERF_CHECK(output->GetPointData()->GetNormals() == output->GetPointData()->GetArray("Normals"));
  // The input's arrays pass through; the input itself is untouched.
  ok &= KERF_CHECK(output->GetCellData()->GetArray("Marker") != nullptr);
  ok &= KERF_CHECK(sphere->GetPointData()->GetNumberOfArrays() == 0);
  ok &= KERF_CHECK(sphere->GetMTime() == inputTime);
  ok &= KERF_CHECK(output->GetPolys() == sphere->GetPolys());

  vtkDataArray* h = output->GetPointData()->GetArray("H");
  double meanError = 0.0;
  for (vtkIdType i = 0; i < h->GetNumberOfTuples(); ++i)
  {
    meanError += std::abs(h->GetComponent(i, 0) * radius - 1.0);
  }
  meanError /= static_cast<double>(h->GetNumberOfTuples());
  ok &= KERF_CHECK(meanError < 0.01);

  // Deterministic: a second run gives the same bits.
  vtkNew<vtkSurfaceDescriptors> again;
  again->SetInputData(sphere);
  again->SetMeanCurvatureArrayName("H");
  again->Update();
  for (const char* name : expected)
  {
    ok &= KERF_CHECK(
      sameValues(output->GetPointData()->GetArray(name), again->GetOutput()->GetPointData()->GetArray(name)));
  }

  // Triangle strips give the same values as the triangles they encode.
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(40);
  source->SetPhiResolution(30);
  vtkNew<vtkStripper> stripper;
  stripper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkSurfaceDescriptors> fromStrips;
  fromStrips->SetInputConnection(stripper->GetOutputPort());
  vtkNew<vtkSurfaceDescriptors> fromTriangles;
  fromTriangles->SetInputConnection(source->GetOutputPort());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(fromStrips).empty());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(fromTriangles).empty());
  vtkDataArray* hs = fromStrips->GetOutput()->GetPointData()->GetArray("MeanCurvature");
  vtkDataArray* ht = fromTriangles->GetOutput()->GetPointData()->GetArray("MeanCurvature");
  for (vtkIdType i = 0; i < ht->GetNumberOfTuples(); ++i)
  {
    if (std::abs(hs->GetComponent(i, 0) - ht->GetComponent(i, 0)) > 1e-9)
    {
      ok &= KERF_CHECK(false && "strip and triangle curvature differ");
      break;
    }
  }
  ok &= KERF_CHECK(fromStrips->GetOutput()->GetNumberOfStrips() == 0);
  ok &= KERF_CHECK(fromStrips->GetOutput()->GetNumberOfPolys() == fromTriangles->GetOutput()->GetNumberOfPolys());

  // Quads are triangulated, each triangle keeping its quad's cell data.
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(4, 3);
  plane->Update();
  vtkSmartPointer<vtkPolyData> quads = plane->GetOutput();
  vtkNew<vtkDoubleArray> quadId;
  quadId->SetName("QuadId");
  for (vtkIdType c = 0; c < quads->GetNumberOfCells(); ++c)
  {
    quadId->InsertNextValue(static_cast<double>(c));
  }
  quads->GetCellData()->AddArray(quadId);
  vtkNew<vtkSurfaceDescriptors> onQuads;
  onQuads->SetInputData(quads);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(onQuads).empty());
  vtkPolyData* triangulated = onQuads->GetOutput();
  ok &= KERF_CHECK(triangulated->GetNumberOfPolys() == 2 * quads->GetNumberOfPolys());
  vtkDataArray* mapped = triangulated->GetCellData()->GetArray("QuadId");
  ok &= KERF_CHECK(mapped && mapped->GetNumberOfTuples() == 24);
  if (mapped)
  {
    for (vtkIdType t = 0; t < 24; ++t)
    {
      ok &= KERF_CHECK(mapped->GetComponent(t, 0) == static_cast<double>(t / 2));
    }
  }
  vtkDataArray* k1 = triangulated->GetPointData()->GetArray("MaximumCurvature");
  for (vtkIdType i = 0; i < k1->GetNumberOfTuples(); ++i)
  {
    ok &= KERF_CHECK(std::abs(k1->GetComponent(i, 0)) < 1e-12);
  }
  ok &= KERF_CHECK(quads->GetNumberOfPolys() == 12 && quads->GetPolys()->GetMaxCellSize() == 4);

  // An empty output array name is refused.
  vtkNew<vtkSurfaceDescriptors> unnamed;
  unnamed->SetInputData(sphere);
  unnamed->SetConcaveArrayName("");
  ok &= KERF_CHECK(!kerf::test::UpdateAndCaptureError(unnamed).empty());

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
