// vtkGeometrySeams as a VTK filter: its arrays against Core on a bumpy cylinder, the contours, the input untouched,
// errors.
#include "Geometry/SurfaceDescriptors.h"
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "SeamCarving/GeometrySeams.h"
#include "vtkGeometrySeams.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <string>

int TestGeometrySeamsFilter(int, char*[])
{
  bool ok = true;
  const kerf::TriangleMesh mesh = kerf::makeBumpyCylinder(1.0, 4.0, 48, 49, 6, 2.0, 0.3, 0.15);
  const std::vector<double> regions = kerf::heightBandRegions(mesh, 1.0, 3.0);
  vtkSmartPointer<vtkPolyData> surface = kerf::test::WithRegions(mesh, regions);
  const vtkMTimeType inputTime = surface->GetMTime();

  vtkNew<vtkGeometrySeams> filter;
  filter->SetInputData(surface);
  filter->SetNumberOfRings(6);
  filter->SetNumberOfSectors(5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(filter).empty());
  vtkPolyData* output = filter->GetOutput();

  // The arrays are Core's, value for value.
  kerf::GeometrySeamsOptions options;
  options.ringCount = 6;
  options.sectorCount = 5;
  const kerf::GeometrySeamsResult core =
    kerf::computeGeometrySeams(mesh, regions, kerf::computeSurfaceDescriptors(mesh).normalConeAngle, options);
  vtkDataArray* field = output->GetPointData()->GetArray("HarmonicField");
  vtkDataArray* sector = output->GetPointData()->GetArray("Sector");
  vtkDataArray* ring = output->GetCellData()->GetArray("RingSeam");
  vtkDataArray* cost = output->GetCellData()->GetArray("EdgeCost");
  vtkDataArray* faceSector = output->GetCellData()->GetArray("Sector");
  ok &= KERF_CHECK(field && sector && ring && cost && faceSector);
  ok &= KERF_CHECK(field && field->GetNumberOfTuples() == mesh.vertexCount());
  ok &= KERF_CHECK(ring && ring->GetNumberOfTuples() == mesh.faceCount());
  int mismatches = 0, ringFaces = 0;
  for (int v = 0; field && sector && v < mesh.vertexCount(); ++v)
  {
    mismatches += field->GetComponent(v, 0) != core.harmonicField[v] ? 1 : 0;
    mismatches += sector->GetComponent(v, 0) != core.sector[v] ? 1 : 0;
  }
  for (int f = 0; ring && cost && faceSector && f < mesh.faceCount(); ++f)
  {
    mismatches += faceSector->GetComponent(f, 0) != core.faceSector[f] ? 1 : 0;
    mismatches += ring->GetComponent(f, 0) != core.ring[f] ? 1 : 0;
    mismatches += cost->GetComponent(f, 0) != core.faceCost[f] ? 1 : 0;
    ringFaces += ring->GetComponent(f, 0) >= 0 ? 1 : 0;
  }
  ok &= KERF_CHECK(mismatches == 0);
  ok &= KERF_CHECK(ringFaces >= 6 * 96); // six rings around 48 columns, two triangles each at least
  ok &= KERF_CHECK(output->GetFieldData()->GetArray("RingCount")->GetComponent(0, 0) == 6.0);

  // Output 1: iso-contours j = 0..10 (one loop each) and five sector contours.
  vtkPolyData* contours = filter->GetContours();
  vtkDataArray* kind = contours->GetCellData()->GetArray("Kind");
  vtkDataArray* index = contours->GetCellData()->GetArray("ContourIndex");
  ok &= KERF_CHECK(kind && index && contours->GetNumberOfLines() == 16);
  int iso = 0, sectors = 0;
  for (vtkIdType c = 0; kind && c < kind->GetNumberOfTuples(); ++c)
  {
    (kind->GetComponent(c, 0) == 0 ? iso : sectors) += 1;
  }
  ok &= KERF_CHECK(iso == 11 && sectors == 5);

  // The input is untouched.
  ok &= KERF_CHECK(surface->GetMTime() == inputTime);
  ok &= KERF_CHECK(surface->GetPointData()->GetNumberOfArrays() == 1);
  ok &= KERF_CHECK(surface->GetCellData()->GetNumberOfArrays() == 0);

  // Errors: a clear sentence, an empty output, the input untouched.
  std::vector<double> noHandle = regions;
  for (double& value : noHandle)
  {
    value = value == 2.0 ? 1.0 : value;
  }
  vtkSmartPointer<vtkPolyData> bad = kerf::test::WithRegions(mesh, noHandle);
  filter->SetInputData(bad);
  std::string error = kerf::test::UpdateAndCaptureError(filter);
  ok &= KERF_CHECK(error.find("no point is in the handle region") != std::string::npos);
  ok &= KERF_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  ok &= KERF_CHECK(bad->GetPointData()->GetNumberOfArrays() == 1);

  filter->SetInputData(surface);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Painted");
  error = kerf::test::UpdateAndCaptureError(filter);
  ok &= KERF_CHECK(error.find("Painted") != std::string::npos);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Region");
  filter->SetAlpha(-1.0);
  error = kerf::test::UpdateAndCaptureError(filter);
  ok &= KERF_CHECK(error.find("alpha, beta and gamma") != std::string::npos);
  filter->SetAlpha(1.0);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(filter).empty());
  return ok ? 0 : 1;
}
