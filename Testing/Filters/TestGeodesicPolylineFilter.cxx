// Geodesic Polyline (vtkGeodesicPolyline): lengths against the distance field and great circles, paths across faces,
// simple closed loops, both metrics, errors.
#include "Geodesic/SurfacePoint.h"
#include "Geometry/ClosestPoint.h"
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkGeodesicDistance.h"
#include "vtkGeodesicPolyline.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

kerf::Vector3 pointOf(vtkPolyData* data, vtkIdType id)
{
  double p[3];
  data->GetPoint(id, p);
  return kerf::Vector3(p[0], p[1], p[2]);
}

double fieldValue(vtkPolyData* data, const char* name)
{
  return data->GetFieldData()->GetArray(name)->GetComponent(0, 0);
}

vtkSmartPointer<vtkPolyData> pointSet(const std::vector<kerf::Vector3>& positions)
{
  auto points = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataTypeToDouble();
  for (const kerf::Vector3& p : positions)
  {
    coordinates->InsertNextPoint(p.data());
  }
  points->SetPoints(coordinates);
  return points;
}

void setPathPoints(vtkGeodesicPolyline* filter, const std::vector<kerf::Vector3>& positions)
{
  filter->SetNumberOfPathPoints(static_cast<int>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    filter->SetPathPoint(static_cast<int>(i), positions[i].x(), positions[i].y(), positions[i].z());
  }
}

// The path's structure: one polyline, every point on the triangle its Face array names, the arc
// length rising from 0 to TotalLength; returns the fraction of segments whose midpoint lies
// strictly inside its triangle (0 for a path along edges).
double checkPathOnSurface(vtkPolyData* path, const kerf::TriangleMesh& mesh, bool& ok)
{
  ok &= KERF_CHECK(path->GetNumberOfLines() == 1);
  vtkDataArray* faces = path->GetPointData()->GetArray("Face");
  vtkDataArray* arc = path->GetPointData()->GetArray("ArcLength");
  ok &= KERF_CHECK(faces && arc && path->GetPointData()->GetArray("PathPoint"));
  if (!faces || !arc)
  {
    return 0.0;
  }
  const vtkIdType count = path->GetNumberOfPoints();
  const bool closed = path->GetCellData()->GetArray("Closed")->GetComponent(0, 0) == 1.0;
  const vtkIdType segments = closed ? count : count - 1;
  int inside = 0;
  double worst = 0.0;
  for (vtkIdType i = 0; i < segments; ++i)
  {
    const kerf::Triangle& t = mesh.triangle(static_cast<int>(faces->GetComponent(i, 0)));
    const kerf::Vector3 a = pointOf(path, i), b = pointOf(path, (i + 1) % count);
    for (const kerf::Vector3& p : { a, b })
    {
      kerf::Vector3 barycentric;
      const kerf::Vector3 q =
        kerf::closestPointOnTriangle(p, mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), barycentric);
      worst = std::max(worst, (q - p).norm());
    }
    kerf::Vector3 barycentric;
    kerf::closestPointOnTriangle(0.5 * (a + b), mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), barycentric);
    inside += barycentric.minCoeff() > 1e-6 ? 1 : 0;
    ok &= KERF_CHECK(arc->GetComponent((i + 1) % count, 0) >= arc->GetComponent(i, 0) || (closed && i + 1 == count));
  }
  ok &= KERF_CHECK(worst <= 1e-9);
  ok &= KERF_CHECK(arc->GetComponent(0, 0) == 0.0);
  const double total = fieldValue(path, "TotalLength");
  ok &= KERF_CHECK(total == path->GetCellData()->GetArray("Length")->GetComponent(0, 0));
  const double last = arc->GetComponent(count - 1, 0);
  const double closing = closed ? (pointOf(path, 0) - pointOf(path, count - 1)).norm() : 0.0;
  ok &= KERF_CHECK(std::abs(last + closing - total) <= 1e-9 * total || !closed);
  ok &= KERF_CHECK(closed || last == total);
  return static_cast<double>(inside) / static_cast<double>(segments);
}

// The distance field `name` of `surface` at a point of the path, interpolated in its triangle.
double distanceAt(
  vtkPolyData* surface, const char* name, const kerf::TriangleMesh& mesh, int face, const kerf::Vector3& p)
{
  vtkDataArray* distance = surface->GetPointData()->GetArray(name);
  const kerf::Vector3 b = kerf::barycentricInFace(mesh, face, p);
  const kerf::Triangle& t = mesh.triangle(face);
  return b[0] * distance->GetComponent(t[0], 0) + b[1] * distance->GetComponent(t[1], 0) +
    b[2] * distance->GetComponent(t[2], 0);
}

// The length of `path` against the distance from its first point (vtkGeodesicDistance with
// `gamma`) at its last point: the relative difference.
double lengthAgainstField(vtkPolyData* path, vtkPolyData* surface, const kerf::TriangleMesh& mesh, double gamma)
{
  vtkNew<vtkGeodesicDistance> distance;
  distance->SetInputData(surface);
  const kerf::Vector3 start = pointOf(path, 0);
  distance->SetSourcePoint(start.x(), start.y(), start.z());
  distance->SetGamma(gamma);
  if (!kerf::test::UpdateAndCaptureError(distance).empty())
  {
    return std::numeric_limits<double>::infinity();
  }
  const vtkIdType last = path->GetNumberOfPoints() - 1;
  const int face = static_cast<int>(path->GetPointData()->GetArray("Face")->GetComponent(last, 0));
  const double atEnd = distanceAt(distance->GetOutput(), "GeodesicDistance", mesh, face, pointOf(path, last));
  return std::abs(fieldValue(path, "TotalLength") - atEnd) / atEnd;
}
} // namespace

int TestGeodesicPolylineFilter(int, char*[])
{
  bool ok = true;
  // The unit icosphere, 20,480 triangles; two points given in space, moved onto its facets.
  const kerf::TriangleMesh sphereMesh = kerf::makeIcosphere(1.0, 5);
  vtkSmartPointer<vtkPolyData> sphere = kerf::test::ToPolyData(sphereMesh);
  const vtkMTimeType inputTime = sphere->GetMTime();
  const kerf::Vector3 a = kerf::Vector3(0.3, 0.2, 1.0).normalized();
  const kerf::Vector3 b = kerf::Vector3(-0.5, 0.8, -0.4).normalized();
  vtkNew<vtkGeodesicPolyline> path;
  path->SetInputData(0, sphere);
  setPathPoints(path, { a, b });
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(path).empty());
  vtkPolyData* line = path->GetOutput();
  const double acrossFaces = checkPathOnSurface(line, sphereMesh, ok);
  const kerf::Vector3 start = pointOf(line, 0), end = pointOf(line, line->GetNumberOfPoints() - 1);
  const double greatCircle = std::acos(std::clamp(start.normalized().dot(end.normalized()), -1.0, 1.0));
  const double isotropicLength = fieldValue(line, "TotalLength");
  const double isotropicField = lengthAgainstField(line, sphere, sphereMesh, 0.0);
  std::cout << "isotropic path: " << line->GetNumberOfPoints() << " points, " << acrossFaces
            << " of the segments inside a triangle, length " << isotropicLength << " (great circle " << greatCircle
            << "), relative difference from the heat distance at its end " << isotropicField << std::endl;
  ok &= KERF_CHECK((start - a).norm() <= 0.01 && (end - b).norm() <= 0.01);
  ok &= KERF_CHECK(acrossFaces >= 0.5);
  ok &= KERF_CHECK(isotropicField <= 0.01);
  ok &= KERF_CHECK(std::abs(isotropicLength - greatCircle) <= 0.01 * greatCircle);
  ok &= KERF_CHECK(line->GetPointData()->GetArray("PathPoint")->GetComponent(0, 0) == 0.0);
  ok &= KERF_CHECK(line->GetPointData()->GetArray("PathPoint")->GetComponent(line->GetNumberOfPoints() - 1, 0) == 1.0);
  ok &= KERF_CHECK(fieldValue(line, "SelfCrossings") == 0.0);

  // The same points as input 1 give the same path, bit for bit, and so does a second run.
  vtkNew<vtkGeodesicPolyline> fromInput;
  fromInput->SetInputData(0, sphere);
  fromInput->SetInputData(1, pointSet({ a, b }));
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(fromInput).empty());
  bool same = fromInput->GetOutput()->GetNumberOfPoints() == line->GetNumberOfPoints();
  for (vtkIdType i = 0; same && i < line->GetNumberOfPoints(); ++i)
  {
    same = pointOf(fromInput->GetOutput(), i) == pointOf(line, i);
  }
  ok &= KERF_CHECK(same);
  ok &= KERF_CHECK(fieldValue(fromInput->GetOutput(), "LegsTraced") == 1.0);

  // Four points: moving the third retraces its two legs only (a drag in ParaView), and the path
  // equals a fresh filter's, bit for bit.
  const kerf::Vector3 c = kerf::Vector3(-0.9, -0.1, 0.3).normalized(), d = kerf::Vector3(0.2, -0.9, -0.3).normalized();
  vtkNew<vtkGeodesicPolyline> dragged;
  dragged->SetInputData(0, sphere);
  setPathPoints(dragged, { a, b, c, d });
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(dragged).empty());
  ok &= KERF_CHECK(fieldValue(dragged->GetOutput(), "LegsTraced") == 3.0);
  const kerf::Vector3 c2 = kerf::Vector3(-0.9, 0.1, 0.35).normalized();
  setPathPoints(dragged, { a, b, c2, d });
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(dragged).empty());
  ok &= KERF_CHECK(fieldValue(dragged->GetOutput(), "LegsTraced") == 2.0);
  vtkNew<vtkGeodesicPolyline> fresh;
  fresh->SetInputData(0, sphere);
  setPathPoints(fresh, { a, b, c2, d });
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(fresh).empty());
  same = fresh->GetOutput()->GetNumberOfPoints() == dragged->GetOutput()->GetNumberOfPoints();
  for (vtkIdType i = 0; same && i < fresh->GetOutput()->GetNumberOfPoints(); ++i)
  {
    same = pointOf(fresh->GetOutput(), i) == pointOf(dragged->GetOutput(), i);
  }
  ok &= KERF_CHECK(same);

  // The anisotropic metric with Gamma = 0 (Vector Dijkstra, Euclidean) agrees with the heat
  // method's path within 1%, and its length with its own field at its end.
  path->SetMetricToAnisotropic();
  path->SetGamma(0.0);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(path).empty());
  const double euclideanLength = fieldValue(path->GetOutput(), "TotalLength");
  checkPathOnSurface(path->GetOutput(), sphereMesh, ok);
  std::cout << "anisotropic path, Gamma = 0: length " << euclideanLength << std::endl;
  ok &= KERF_CHECK(std::abs(euclideanLength - isotropicLength) <= 0.01 * isotropicLength);

  // Gamma = 1 on a cylinder of radius 1 (18,432 triangles): lambda1 = 2 around the axis, 1/2
  // along it. The path's metric length against the anisotropic distance at its end.
  const kerf::TriangleMesh cylinderMesh = kerf::makeCylinder(1.0, 4.0, 96, 97);
  vtkSmartPointer<vtkPolyData> cylinder = kerf::test::ToPolyData(cylinderMesh);
  vtkNew<vtkGeodesicPolyline> onCylinder;
  onCylinder->SetInputData(0, cylinder);
  onCylinder->SetMetricToAnisotropic();
  onCylinder->SetGamma(1.0);
  setPathPoints(onCylinder, { { 1.0, 0.0, 0.5 }, { std::cos(1.5), std::sin(1.5), 3.0 } });
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(onCylinder).empty());
  const double cylinderAcross = checkPathOnSurface(onCylinder->GetOutput(), cylinderMesh, ok);
  const double anisotropicField = lengthAgainstField(onCylinder->GetOutput(), cylinder, cylinderMesh, 1.0);
  std::cout << "anisotropic path on the cylinder: length " << fieldValue(onCylinder->GetOutput(), "TotalLength") << ", "
            << cylinderAcross << " of the segments inside a triangle, relative difference from the "
            << "Vector Dijkstra distance at its end " << anisotropicField << std::endl;
  ok &= KERF_CHECK(anisotropicField <= 0.01);
  ok &= KERF_CHECK(cylinderAcross >= 0.5);

  // A closed loop through four points at latitude 30 degrees, in order: closed, through every
  // point, and simple: its longitude turns once around the axis, always the same way.
  std::vector<kerf::Vector3> ring;
  for (int i = 0; i < 4; ++i)
  {
    const double angle = 2.0 * Pi * (i + 0.1) / 4.0;
    ring.push_back(kerf::Vector3(std::cos(angle), std::sin(angle), 1.1547).normalized());
  }
  for (int metric : { vtkGeodesicPolyline::ISOTROPIC, vtkGeodesicPolyline::ANISOTROPIC })
  {
    vtkNew<vtkGeodesicPolyline> loop;
    loop->SetInputData(0, sphere);
    loop->SetInputData(1, pointSet(ring));
    loop->ClosedLoopOn();
    loop->SetMetric(metric);
    ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(loop).empty());
    vtkPolyData* closed = loop->GetOutput();
    checkPathOnSurface(closed, sphereMesh, ok);
    ok &= KERF_CHECK(closed->GetCellData()->GetArray("Closed")->GetComponent(0, 0) == 1.0);
    vtkIdType cellSize = 0;
    const vtkIdType* ids = nullptr;
    closed->GetLines()->InitTraversal();
    closed->GetLines()->GetNextCell(cellSize, ids);
    ok &= KERF_CHECK(cellSize == closed->GetNumberOfPoints() + 1 && ids[0] == ids[cellSize - 1]);
    ok &= KERF_CHECK(fieldValue(closed, "SelfCrossings") == 0.0);
    double turning = 0.0;
    bool monotone = true;
    const vtkIdType count = closed->GetNumberOfPoints();
    for (vtkIdType i = 0; i < count; ++i)
    {
      const kerf::Vector3 p = pointOf(closed, i), q = pointOf(closed, (i + 1) % count);
      const double step = std::remainder(std::atan2(q.y(), q.x()) - std::atan2(p.y(), p.x()), 2.0 * Pi);
      monotone &= step > 0.0;
      turning += step;
    }
    int waypoints = 0;
    for (vtkIdType i = 0; i < count; ++i)
    {
      const double index = closed->GetPointData()->GetArray("PathPoint")->GetComponent(i, 0);
      if (index >= 0.0)
      {
        ok &= KERF_CHECK(index == waypoints);
        ok &= KERF_CHECK((pointOf(closed, i) - ring[waypoints]).norm() <= 0.01);
        ++waypoints;
      }
    }
    std::cout << "loop (metric " << metric << "): " << count << " points, length " << fieldValue(closed, "TotalLength")
              << ", turning " << turning / (2.0 * Pi) << " times around the axis" << std::endl;
    ok &= KERF_CHECK(monotone && std::abs(turning - 2.0 * Pi) <= 1e-9);
    ok &= KERF_CHECK(waypoints == 4);
  }
  // Given in a crossing order, the loop reports its crossing.
  vtkNew<vtkGeodesicPolyline> bowTie;
  bowTie->SetInputData(0, sphere);
  bowTie->SetInputData(1, pointSet({ ring[0], ring[2], ring[1], ring[3] }));
  bowTie->ClosedLoopOn();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(bowTie).empty());
  ok &= KERF_CHECK(fieldValue(bowTie->GetOutput(), "SelfCrossings") >= 1.0);

  // A panel point far off the surface is moved onto it (ParaView's points start at the bounds).
  vtkNew<vtkGeodesicPolyline> fromBounds;
  fromBounds->SetInputData(0, sphere);
  setPathPoints(fromBounds, { { 0.0, 0.0, 5.0 }, { 5.0, 0.0, 0.0 } });
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(fromBounds).empty());
  vtkPolyData* snapped = fromBounds->GetOutput();
  const kerf::Vector3 top = pointOf(snapped, 0), side = pointOf(snapped, snapped->GetNumberOfPoints() - 1);
  const double arc = std::acos(std::clamp(top.normalized().dot(side.normalized()), -1.0, 1.0));
  std::cout << "from points off the surface: " << top.transpose() << " to " << side.transpose() << ", length "
            << fieldValue(snapped, "TotalLength") << " (great circle " << arc << ")" << std::endl;
  ok &= KERF_CHECK(top.z() >= 0.99 && side.x() >= 0.99);
  ok &= KERF_CHECK(std::abs(fieldValue(snapped, "TotalLength") - arc) <= 0.01 * arc);

  // Errors, each leaving the output empty and the input untouched.
  const auto refused = [&](vtkGeodesicPolyline* filter, const std::string& phrase) {
    const std::string error = kerf::test::UpdateAndCaptureError(filter);
    std::cout << error << std::endl;
    return KERF_CHECK(error.find(phrase) != std::string::npos) &&
      KERF_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  };
  vtkNew<vtkGeodesicPolyline> bad;
  bad->SetInputData(0, sphere);
  ok &= refused(bad, "there are no path points");
  bad->SetInputData(1, pointSet({}));
  ok &= refused(bad, "the point input holds no point");
  bad->SetInputData(1, pointSet({ a, { 0.0, 0.0, 3.0 } }));
  ok &= refused(bad, "path point 1 lies off the surface");
  bad->SetInputData(1, pointSet({ a, b }));
  bad->ClosedLoopOn();
  ok &= refused(bad, "needs at least 3 points, got 2");
  bad->ClosedLoopOff();
  bad->SetInputData(1, pointSet({ a, a, b }));
  ok &= refused(bad, "path points 0 and 1 are the same point");
  bad->SetInputData(1, nullptr);
  setPathPoints(bad, { a, { std::nan(""), 0.0, 0.0 } });
  ok &= refused(bad, "path point 1");
  ok &= KERF_CHECK(sphere->GetMTime() == inputTime && sphere->GetPointData()->GetNumberOfArrays() == 0);

  // Two spheres: points on different components have no path.
  kerf::TriangleMesh two = kerf::makeIcosphere(1.0, 3);
  std::vector<kerf::Vector3> points = two.points();
  std::vector<kerf::Triangle> triangles = two.triangles();
  const int offset = static_cast<int>(points.size());
  for (const kerf::Vector3& p : two.points())
  {
    points.push_back(p + kerf::Vector3(5.0, 0.0, 0.0));
  }
  for (const kerf::Triangle& t : two.triangles())
  {
    triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  vtkNew<vtkGeodesicPolyline> apart;
  apart->SetInputData(0, kerf::test::ToPolyData(kerf::TriangleMesh(points, triangles)));
  apart->SetInputData(1, pointSet({ { 0.0, 0.0, 1.0 }, { 0.0, 1.0, 0.0 }, { 5.0, 0.0, 1.0 } }));
  ok &= refused(apart, "path point 2 lies on another connected component of the mesh than path point 0");
  return ok ? 0 : 1;
}
