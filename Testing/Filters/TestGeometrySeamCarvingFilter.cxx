// vtkGeometrySeamCarving as a VTK filter: Core's result value for value, the session kept between runs (identity gives
// the input back), the input untouched, errors.
#include "Geometry/SurfaceDescriptors.h"
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "SeamCarving/GeometrySeamCarving.h"
#include "SeamCarving/GeometrySeams.h"
#include "vtkGeometrySeamCarving.h"
#include "vtkGeometrySeams.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
double fieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetComponent(0, 0) : -1e300;
}

// The output against Core's result: points bit for bit, triangles, ring and sector arrays.
bool sameAsCore(vtkPolyData* output, const kerf::SeamCarvingResult& core)
{
  if (output->GetNumberOfPoints() != static_cast<vtkIdType>(core.points.size()) ||
    output->GetNumberOfCells() != static_cast<vtkIdType>(core.triangles.size()))
  {
    return false;
  }
  vtkDataArray* origin = output->GetPointData()->GetArray("OriginalPointId");
  vtkDataArray* ring = output->GetCellData()->GetArray("RingSeam");
  vtkDataArray* sector = output->GetCellData()->GetArray("Sector");
  if (!origin || !ring || !sector)
  {
    return false;
  }
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    const kerf::Vector3& q = core.points[static_cast<std::size_t>(i)];
    if (p[0] != q.x() || p[1] != q.y() || p[2] != q.z() ||
      origin->GetComponent(i, 0) != core.pointOrigin[static_cast<std::size_t>(i)])
    {
      return false;
    }
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
  {
    output->GetCellPoints(c, ids);
    const kerf::Triangle& t = core.triangles[static_cast<std::size_t>(c)];
    if (ids->GetNumberOfIds() != 3 || ids->GetId(0) != t[0] || ids->GetId(1) != t[1] || ids->GetId(2) != t[2] ||
      ring->GetComponent(c, 0) != core.faceRing[static_cast<std::size_t>(c)] ||
      sector->GetComponent(c, 0) != core.faceSector[static_cast<std::size_t>(c)])
    {
      return false;
    }
  }
  return true;
}
// The knob and the ridge of the Core tests through both filters with their defaults: the knob,
// which the rings go around, keeps its shape much better than with Plastic off (a stretch of 25%
// of the modeling region's height in four moves); the ridge, which every ring crosses, has its
// segments left alone (SalientSegments) and loses no point to a squash.
bool testFeatureTubes()
{
  bool ok = true;
  for (kerf::TubeFeature feature : { kerf::TubeFeature::Knob, kerf::TubeFeature::Ridge })
  {
    const kerf::TriangleMesh mesh = kerf::makeFeatureTube(feature, 64, 81);
    const std::vector<int> features = kerf::featureTubePoints(mesh);
    vtkNew<vtkGeometrySeams> seams;
    seams->SetInputData(kerf::test::WithRegions(mesh, kerf::heightBandRegions(mesh, 0.8, 4.2)));
    double change[2];
    int lost = 0;
    for (int plastic = 0; plastic < 2; ++plastic)
    {
      vtkNew<vtkGeometrySeamCarving> carving;
      carving->SetInputConnection(seams->GetOutputPort());
      carving->SetPlastic(plastic == 1);
      vtkNew<vtkTransform> handle;
      carving->SetHandleTransform(handle);
      const double move = feature == kerf::TubeFeature::Knob ? -0.85 : 0.85;
      for (int step = 1; step <= 4; ++step)
      {
        handle->Identity();
        handle->Translate(0.0, 0.0, move * step / 4.0);
        ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(carving).empty());
      }
      vtkPolyData* output = carving->GetOutput();
      const std::vector<vtkIdType> outputOf = kerf::test::OutputPointOfInput(output, mesh.vertexCount());
      std::vector<char> isFeature(static_cast<std::size_t>(mesh.vertexCount()), 0);
      lost = 0;
      for (int v : features)
      {
        isFeature[static_cast<std::size_t>(v)] = 1;
        lost += outputOf[static_cast<std::size_t>(v)] < 0 ? 1 : 0;
      }
      double sum = 0.0;
      int count = 0;
      for (int e = 0; e < mesh.edgeCount(); ++e)
      {
        const auto& ends = mesh.edgeVertices(e);
        const vtkIdType a = outputOf[static_cast<std::size_t>(ends[0])],
                        b = outputOf[static_cast<std::size_t>(ends[1])];
        if (isFeature[static_cast<std::size_t>(ends[0])] && isFeature[static_cast<std::size_t>(ends[1])] && a >= 0 &&
          b >= 0)
        {
          double p[3], q[3];
          output->GetPoint(a, p);
          output->GetPoint(b, q);
          const double ratio = (kerf::Vector3(p[0], p[1], p[2]) - kerf::Vector3(q[0], q[1], q[2])).norm() /
            (mesh.point(ends[0]) - mesh.point(ends[1])).norm();
          sum += (ratio - 1.0) * (ratio - 1.0);
          ++count;
        }
      }
      change[plastic] = std::sqrt(sum / std::max(1, count));
      if (plastic == 1 && feature == kerf::TubeFeature::Ridge)
      {
        ok &= KERF_CHECK(fieldValue(output, "SalientSegments") >= 15.0);
      }
    }
    const bool knob = feature == kerf::TubeFeature::Knob;
    std::cout << (knob ? "knob stretched" : "ridge squashed") << " by 25%: feature change " << change[0] << " elastic, "
              << change[1] << " seam carving" << std::endl;
    ok &= KERF_CHECK(lost == 0);
    ok &= KERF_CHECK(knob ? change[1] < 0.5 * change[0] : change[1] < 1.1 * change[0]);
  }
  return ok;
}
} // namespace

int TestGeometrySeamCarvingFilter(int, char*[])
{
  bool ok = true;
  // The Core tests' bumpy cylinder: handle z <= 0.5, fixed z >= 3.5, 20 rings, 6 sectors.
  const kerf::TriangleMesh mesh = kerf::makeBumpyCylinder(1.0, 4.0, 48, 49, 6, 2.0, 0.3, 0.15);
  const std::vector<double> regions = kerf::heightBandRegions(mesh, 0.5, 3.5);
  vtkSmartPointer<vtkPolyData> surface = kerf::test::WithRegions(mesh, regions);
  vtkNew<vtkGeometrySeams> seams;
  seams->SetInputData(surface);
  seams->SetNumberOfRings(20);
  seams->SetNumberOfSectors(6);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(seams).empty());
  vtkPolyData* preprocessed = seams->GetOutput();
  const vtkMTimeType inputTime = preprocessed->GetMTime();
  const int inputArrays =
    preprocessed->GetPointData()->GetNumberOfArrays() + preprocessed->GetCellData()->GetNumberOfArrays();

  // Core on the same input, the same moves.
  kerf::GeometrySeamsOptions seamOptions;
  seamOptions.ringCount = 20;
  seamOptions.sectorCount = 6;
  const std::vector<double> angle = kerf::computeSurfaceDescriptors(mesh).normalConeAngle;
  const kerf::GeometrySeamsResult coreSeams = kerf::computeGeometrySeams(mesh, regions, angle, seamOptions);
  kerf::SeamCarvingInput in;
  in.mesh = &mesh;
  in.region = regions;
  in.faceRing = coreSeams.ring;
  in.faceSector = coreSeams.faceSector;
  in.faceCost = coreSeams.faceCost;
  in.normalConeAngle = angle;
  kerf::GeometrySeamCarving core(in, kerf::SeamCarvingOptions());

  vtkNew<vtkGeometrySeamCarving> carving;
  carving->SetInputConnection(seams->GetOutputPort());
  vtkNew<vtkTransform> handle;
  carving->SetHandleTransform(handle);
  int split = 0;
  for (double dz : { -0.75, -1.5 })
  {
    handle->Identity();
    handle->Translate(0.0, 0.0, dz); // the handle is below: the modeling region stretches
    ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(carving).empty());
    Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
    matrix(2, 3) = dz;
    ok &= KERF_CHECK(sameAsCore(carving->GetOutput(), core.deform(matrix)));
    split = static_cast<int>(fieldValue(carving->GetOutput(), "SplitSegments"));
  }
  std::cout << "stretched by 1.5: " << split << " ring segments split, " << carving->GetOutput()->GetNumberOfPoints()
            << " points" << std::endl;
  ok &= KERF_CHECK(split > 0);
  ok &= KERF_CHECK(carving->GetOutput()->GetNumberOfPoints() > mesh.vertexCount());
  ok &= KERF_CHECK(fieldValue(carving->GetOutput(), "CollapsedSegments") == 0.0);
  vtkDataArray* state = carving->GetOutput()->GetFieldData()->GetArray("SectorState");
  ok &= KERF_CHECK(state && state->GetNumberOfTuples() == 6);
  ok &= KERF_CHECK(
    carving->GetOutput()->GetCellData()->GetScalars() == carving->GetOutput()->GetCellData()->GetArray("RingSeam"));

  // Back to the identity in steps: the input's points and triangles.
  for (double dz : { -0.75, 0.0 })
  {
    handle->Identity();
    handle->Translate(0.0, 0.0, dz);
    ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(carving).empty());
  }
  vtkPolyData* back = carving->GetOutput();
  ok &= KERF_CHECK(fieldValue(back, "SplitSegments") == 0.0 && fieldValue(back, "CollapsedSegments") == 0.0);
  ok &= KERF_CHECK(back->GetNumberOfPoints() == mesh.vertexCount() && back->GetNumberOfCells() == mesh.faceCount());
  double worst = 0.0;
  bool sameTriangles = back->GetNumberOfCells() == mesh.faceCount();
  vtkNew<vtkIdList> ids;
  for (vtkIdType i = 0; i < back->GetNumberOfPoints() && i < mesh.vertexCount(); ++i)
  {
    double p[3];
    back->GetPoint(i, p);
    worst = std::max(worst, (kerf::Vector3(p[0], p[1], p[2]) - mesh.point(static_cast<int>(i))).norm());
  }
  for (vtkIdType c = 0; sameTriangles && c < back->GetNumberOfCells(); ++c)
  {
    back->GetCellPoints(c, ids);
    const kerf::Triangle& t = mesh.triangle(static_cast<int>(c));
    sameTriangles = ids->GetId(0) == t[0] && ids->GetId(1) == t[1] && ids->GetId(2) == t[2];
  }
  std::cout << "back at the identity: largest point error " << worst << std::endl;
  ok &= KERF_CHECK(worst < 1e-9 && sameTriangles);

  // No transform is the identity too; plastic off gives the elastic result (no seam executed).
  carving->SetHandleTransform(nullptr);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(carving).empty());
  ok &= KERF_CHECK(carving->GetOutput()->GetNumberOfPoints() == mesh.vertexCount());
  carving->SetHandleTransform(handle);
  handle->Identity();
  handle->Translate(0.0, 0.0, -1.5);
  carving->PlasticOff();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(carving).empty());
  ok &= KERF_CHECK(fieldValue(carving->GetOutput(), "SplitSegments") == 0.0);
  ok &= KERF_CHECK(carving->GetOutput()->GetNumberOfPoints() == mesh.vertexCount());
  carving->PlasticOn();

  // The input is untouched.
  ok &= KERF_CHECK(preprocessed->GetMTime() == inputTime);
  ok &=
    KERF_CHECK(preprocessed->GetPointData()->GetNumberOfArrays() + preprocessed->GetCellData()->GetNumberOfArrays() ==
      inputArrays);

  // Errors: a clear sentence, an empty output.
  handle->Identity();
  handle->Scale(1.0, 1.0, 0.0);
  std::string error = kerf::test::UpdateAndCaptureError(carving);
  ok &= KERF_CHECK(error.find("singular") != std::string::npos);
  ok &= KERF_CHECK(carving->GetOutput()->GetNumberOfPoints() == 0);
  handle->Identity();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(carving).empty());
  vtkNew<vtkGeometrySeamCarving> unprepared;
  unprepared->SetInputData(surface); // regions only: no rings yet
  error = kerf::test::UpdateAndCaptureError(unprepared);
  ok &= KERF_CHECK(error.find("run it first") != std::string::npos);
  carving->SetStiffnessEpsilon(0.0);
  error = kerf::test::UpdateAndCaptureError(carving);
  ok &= KERF_CHECK(error.find("stiffness") != std::string::npos);
  carving->SetStiffnessEpsilon(0.1);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(carving).empty());
  carving->SetSalientThreshold(NAN);
  error = kerf::test::UpdateAndCaptureError(carving);
  ok &= KERF_CHECK(error.find("salient threshold") != std::string::npos);
  carving->SetSalientThreshold(0.5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(carving).empty());
  ok &= KERF_CHECK(fieldValue(carving->GetOutput(), "SalientSegments") == 0.0); // the rings go around the bumps
  ok &= testFeatureTubes();
  return ok ? 0 : 1;
}
