// Geodesic Seam (vtkGeodesicSeam): axial seams on a cylinder, their metric length, regrowth on the kept field,
// anchoring, errors.
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkGeodesicSeam.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>

namespace
{
constexpr double Pi = 3.14159265358979323846;

std::array<double, 3> point(vtkPolyData* data, vtkIdType id)
{
  std::array<double, 3> p;
  data->GetPoint(id, p.data());
  return p;
}

std::string seamWork(vtkGeodesicSeam* filter)
{
  return vtkStringArray::SafeDownCast(filter->GetOutput()->GetFieldData()->GetAbstractArray("SeamWork"))->GetValue(0);
}

// The largest distance of the seam's points from the meridian at `angle` (in radians around the axis).
double meridianDeviation(vtkPolyData* seam, double angle)
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < seam->GetNumberOfPoints(); ++i)
  {
    const double* p = seam->GetPoint(i);
    worst = std::max(worst, std::abs(std::remainder(std::atan2(p[1], p[0]) - angle, 2.0 * Pi)));
  }
  return worst;
}
} // namespace

int TestGeodesicSeamFilter(int, char*[])
{
  bool ok = true;
  // An open cylinder of radius 1 and height 4 (18,432 triangles), the cut the circle z = 1.5.
  vtkSmartPointer<vtkPolyData> cylinder = kerf::test::ToPolyData(kerf::makeCylinder(1.0, 4.0, 96, 97));
  const vtkMTimeType inputTime = cylinder->GetMTime();
  vtkNew<vtkGeodesicSeam> seam;
  seam->SetInputData(0, cylinder);
  seam->SetInputData(1, kerf::test::CirclePolyline(1.0, 1.5, 12));
  seam->SetGamma(0.0);
  const double angle = 0.4;
  seam->SetTargetPoint(std::cos(angle), std::sin(angle), 3.5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(seam).empty());
  ok &= KERF_CHECK(seamWork(seam) == "field");

  // Isotropic: the seam is the meridian from the circle to the target, of length 2, and the
  // distance from the circle is |z - 1.5|.
  vtkPolyData* line = seam->GetSeam();
  ok &= KERF_CHECK(line->GetNumberOfCells() == 1 && line->GetNumberOfPoints() >= 2);
  // (GetPoint's pointer is overwritten by the next call: copy.)
  const std::array<double, 3> first = point(line, 0);
  const std::array<double, 3> last = point(line, line->GetNumberOfPoints() - 1);
  ok &= KERF_CHECK(std::abs(first[2] - 1.5) <= 1e-9);
  ok &= KERF_CHECK(std::abs(last[2] - 3.5) <= 1e-9);
  double deviation = meridianDeviation(line, angle);
  double length = line->GetCellData()->GetArray("Length")->GetComponent(0, 0);
  std::cout << "isotropic seam: deviation " << deviation << " rad, length " << length << std::endl;
  ok &= KERF_CHECK(deviation <= 0.02);
  ok &= KERF_CHECK(std::abs(length - 2.0) <= 0.01 * 2.0);
  vtkDataArray* distance = seam->GetOutput()->GetPointData()->GetArray("SeamDistance");
  double worst = 0.0;
  for (vtkIdType i = 0; i < cylinder->GetNumberOfPoints(); ++i)
  {
    const double z = cylinder->GetPoint(i)[2];
    if (std::abs(z - 1.5) > 0.2)
    {
      worst = std::max(worst, std::abs(distance->GetComponent(i, 0) - std::abs(z - 1.5)) / std::abs(z - 1.5));
    }
  }
  std::cout << "distance from the circle: maximum relative error " << worst << std::endl;
  ok &= KERF_CHECK(worst <= 0.02);

  // Regrowth: a new target reuses the field.
  seam->SetTargetPoint(std::cos(-2.0), std::sin(-2.0), 0.5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(seam).empty());
  ok &= KERF_CHECK(seamWork(seam) == "regrowth");
  deviation = meridianDeviation(seam->GetSeam(), -2.0);
  length = seam->GetSeam()->GetCellData()->GetArray("Length")->GetComponent(0, 0);
  ok &= KERF_CHECK(deviation <= 0.02 && std::abs(length - 1.0) <= 0.01);

  // Anisotropic (gamma = 1): on a cylinder |k1| = 1 and k2 = 0 everywhere, so lambda1 = 2 around
  // the axis and 1/2 along it; the seam stays on the meridian, and its metric length is the
  // Euclidean length times sqrt(1/2).
  seam->SetGamma(1.0);
  seam->SetTargetPoint(std::cos(angle), std::sin(angle), 3.5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(seam).empty());
  ok &= KERF_CHECK(seamWork(seam) == "field");
  deviation = meridianDeviation(seam->GetSeam(), angle);
  length = seam->GetSeam()->GetCellData()->GetArray("Length")->GetComponent(0, 0);
  std::cout << "anisotropic seam: deviation " << deviation << " rad, length " << length << std::endl;
  ok &= KERF_CHECK(deviation <= 0.05);
  ok &= KERF_CHECK(std::abs(length - 2.0 * std::sqrt(0.5)) <= 0.02 * 2.0 * std::sqrt(0.5));

  // Anchoring: the seam meets the circle at the anchor.
  const double anchorAngle = 1.2;
  seam->UseAnchorOn();
  seam->SetAnchorPoint(std::cos(anchorAngle), std::sin(anchorAngle), 1.5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(seam).empty());
  ok &= KERF_CHECK(seamWork(seam) == "regrowth");
  const std::array<double, 3> start = point(seam->GetSeam(), 0);
  const std::array<double, 3> end = point(seam->GetSeam(), seam->GetSeam()->GetNumberOfPoints() - 1);
  std::cout << "anchored seam from " << start[0] << " " << start[1] << " " << start[2] << std::endl;
  ok &= KERF_CHECK(std::hypot(start[0] - std::cos(anchorAngle), start[1] - std::sin(anchorAngle)) <= 0.01);
  ok &= KERF_CHECK(std::abs(start[2] - 1.5) <= 1e-9 && std::abs(end[2] - 3.5) <= 1e-9);
  ok &= KERF_CHECK(cylinder->GetMTime() == inputTime && cylinder->GetPointData()->GetNumberOfArrays() == 0);

  // A target far off the surface (on the axis, as ParaView's handle can start) is moved to the
  // nearest surface point.
  seam->UseAnchorOff();
  seam->SetTargetPoint(0.0, 0.0, 3.0);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(seam).empty());
  const std::array<double, 3> moved = point(seam->GetSeam(), seam->GetSeam()->GetNumberOfPoints() - 1);
  ok &= KERF_CHECK(std::abs(std::hypot(moved[0], moved[1]) - 1.0) <= 1e-3 && std::abs(moved[2] - 3.0) <= 1e-9);

  // Errors: a NaN target, a line off the surface, no line.
  seam->SetTargetPoint(std::nan(""), 0.0, 3.0);
  std::string error = kerf::test::UpdateAndCaptureError(seam);
  std::cout << error << std::endl;
  ok &= KERF_CHECK(error.find("the target point has a NaN") != std::string::npos);
  ok &= KERF_CHECK(seam->GetOutput()->GetNumberOfPoints() == 0 && seam->GetSeam()->GetNumberOfPoints() == 0);
  seam->SetTargetPoint(1.0, 0.0, 3.0);
  seam->SetInputData(1, kerf::test::CirclePolyline(1.5, 1.5, 12));
  error = kerf::test::UpdateAndCaptureError(seam);
  std::cout << error << std::endl;
  ok &= KERF_CHECK(error.find("the cut input line 0") != std::string::npos);
  seam->SetInputData(1, nullptr);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(seam).find("there is no cut line") != std::string::npos);
  seam->SetInputData(1, vtkSmartPointer<vtkPolyData>::New());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(seam).find("holds no line") != std::string::npos);
  return ok ? 0 : 1;
}
