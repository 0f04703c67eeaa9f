// ROI Scissor (vtkROIScissor): the protrusion of a dumbbell against its known part (Rand index), the boundary in the
// crease, clicks as an input, kept click distances, errors.
#include "Evaluation/SegmentationMetrics.h"
#include "KerfTestUtilities.h"
#include "Mesh/MeshGenerators.h"
#include "vtkROIScissor.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkMath.h>
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
// The dumbbell of the Core's ROI Scissor tests: lobes of radii 1 (below) and 0.8 (above, the
// protrusion), the neck at z = 0.3 pinched by 0.65.
const double HalfLength = 2.2, NeckHeight = 0.3, NeckDepth = 0.65;
const std::array<double, 2> Radii{ { 1.0, 0.8 } };

// Height of the crease: where the profile is narrowest near the neck.
double creaseHeight()
{
  double best = NeckHeight, narrowest = 1e9;
  for (double z = NeckHeight - 0.5; z <= NeckHeight + 0.5; z += 1e-4)
  {
    const double r = kerf::dumbbellRadius(z, HalfLength, Radii, NeckHeight, NeckDepth);
    if (r < narrowest)
    {
      narrowest = r;
      best = z;
    }
  }
  return best;
}

double fieldValue(vtkPolyData* output, const char* name)
{
  return output->GetFieldData()->GetArray(name)->GetComponent(0, 0);
}

std::vector<int> labelsOf(vtkPolyData* output)
{
  vtkDataArray* region = output->GetCellData()->GetArray("RoiRegion");
  std::vector<int> labels(static_cast<std::size_t>(output->GetNumberOfCells()));
  for (vtkIdType c = 0; region && c < output->GetNumberOfCells(); ++c)
  {
    labels[static_cast<std::size_t>(c)] = static_cast<int>(region->GetComponent(c, 0));
  }
  return labels;
}
} // namespace

int TestROIScissorFilter(int, char*[])
{
  bool ok = true;
  const kerf::TriangleMesh mesh = kerf::makeDumbbell(HalfLength, Radii, NeckHeight, NeckDepth, 5);
  vtkSmartPointer<vtkPolyData> dumbbell = kerf::test::ToPolyData(mesh);
  const vtkMTimeType inputTime = dumbbell->GetMTime();
  const double crease = creaseHeight();
  std::vector<int> protrusion(static_cast<std::size_t>(mesh.faceCount()));
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const kerf::Triangle& t = mesh.triangle(f);
    protrusion[f] = (mesh.point(t[0]).z() + mesh.point(t[1]).z() + mesh.point(t[2]).z()) / 3.0 > crease ? 1 : 0;
  }

  // One click at the protrusion's tip, radius half the diagonal (2.6): the region is the
  // protrusion.
  vtkNew<vtkROIScissor> roi;
  roi->SetInputData(0, dumbbell);
  const double tip = HalfLength - 0.05;
  roi->SetClickPoint(kerf::dumbbellRadius(tip, HalfLength, Radii, NeckHeight, NeckDepth), 0.0, tip);
  roi->SetRadius(0.5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).empty());
  vtkPolyData* output = roi->GetOutput();
  const std::vector<int> labels = labelsOf(output);
  ok &= KERF_CHECK(static_cast<int>(labels.size()) == mesh.faceCount());
  const kerf::SegmentationScores scores = kerf::compareSegmentations(mesh, labels, protrusion);
  std::cout << "Rand index " << 1.0 - scores.randIndexError << ", Hamming distance " << scores.hammingDistance << " ("
            << mesh.faceCount() << " triangles)" << std::endl;
  ok &= KERF_CHECK(1.0 - scores.randIndexError >= 0.97);
  ok &= KERF_CHECK(output->GetCellData()->GetScalars() == output->GetCellData()->GetArray("RoiRegion"));
  ok &= KERF_CHECK(output->GetPointData()->GetArray("RoiField") && output->GetPointData()->GetArray("RoiCandidate"));
  ok &= KERF_CHECK(fieldValue(output, "ClickDistanceFields") == 1.0);
  ok &= KERF_CHECK(fieldValue(output, "BoundaryEncloses") == 1.0);

  // The boundary: one closed loop without self-crossings, in the crease.
  vtkPolyData* boundary = roi->GetBoundary();
  ok &= KERF_CHECK(boundary->GetNumberOfCells() == 1);
  ok &= KERF_CHECK(boundary->GetCellData()->GetArray("Closed")->GetComponent(0, 0) == 1.0);
  ok &= KERF_CHECK(boundary->GetCellData()->GetArray("SelfCrossings")->GetComponent(0, 0) == 0.0);
  double farthest = 0.0;
  for (vtkIdType i = 0; i < boundary->GetNumberOfPoints(); ++i)
  {
    farthest = std::max(farthest, std::abs(boundary->GetPoint(i)[2] - crease));
  }
  std::cout << "boundary within " << farthest << " of the crease's height " << crease << std::endl;
  ok &= KERF_CHECK(farthest <= 0.1);

  // A wider disc reuses the click's distance and finds the same protrusion.
  roi->SetRadius(0.55);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).empty());
  ok &= KERF_CHECK(fieldValue(roi->GetOutput(), "ClickDistanceFields") == 1.0);
  ok &=
    KERF_CHECK(1.0 - kerf::compareSegmentations(mesh, labelsOf(roi->GetOutput()), protrusion).randIndexError >= 0.97);

  // The radius in the input's units (ParaView's sphere widget) gives the same output as the
  // same radius as a fraction of the diagonal, field for field; a NaN is refused.
  roi->SetRadius(0.5);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).empty());
  vtkNew<vtkPolyData> byFraction;
  byFraction->DeepCopy(roi->GetOutput());
  roi->SetRadius(0.9);
  roi->SetAbsoluteRadius(0.5 * mesh.boundingBoxDiagonal());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).empty());
  ok &= KERF_CHECK(labelsOf(roi->GetOutput()) == labels);
  vtkDataArray* field = roi->GetOutput()->GetPointData()->GetArray("RoiField");
  vtkDataArray* fractionField = byFraction->GetPointData()->GetArray("RoiField");
  bool sameField = field && fractionField && field->GetNumberOfTuples() == fractionField->GetNumberOfTuples();
  for (vtkIdType v = 0; sameField && v < field->GetNumberOfTuples(); ++v)
  {
    const double a = field->GetComponent(v, 0), b = fractionField->GetComponent(v, 0);
    sameField = (std::isnan(a) && std::isnan(b)) || a == b;
  }
  ok &= KERF_CHECK(sameField);
  roi->SetAbsoluteRadius(std::numeric_limits<double>::quiet_NaN());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).find("AbsoluteRadius must be a number") != std::string::npos);
  roi->SetAbsoluteRadius(0.0);

  // The click as input 1 gives the same region as the Click Point.
  roi->SetRadius(0.5);
  vtkNew<vtkPolyData> clicks;
  vtkNew<vtkPoints> clickPoints;
  clickPoints->InsertNextPoint(roi->GetClickPoint());
  clicks->SetPoints(clickPoints);
  roi->SetInputData(1, clicks);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).empty());
  ok &= KERF_CHECK(labelsOf(roi->GetOutput()) == labels);
  ok &= KERF_CHECK(dumbbell->GetMTime() == inputTime && dumbbell->GetPointData()->GetNumberOfArrays() == 0);

  // Clicks with their own radius: the Radius array wins over the filter's Radius.
  vtkNew<vtkDoubleArray> radii;
  radii->SetName("Radius");
  radii->InsertNextValue(0.5);
  clicks->GetPointData()->AddArray(radii);
  roi->SetRadius(0.9);
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).empty());
  ok &= KERF_CHECK(labelsOf(roi->GetOutput()) == labels);
  // A second click that subtracts its disc (radius 0.1 of the diagonal) on the large lobe just
  // below the crease: the candidate region loses the vertices near it, the region stays the
  // protrusion.
  const double below = crease - 0.45;
  clickPoints->InsertNextPoint(kerf::dumbbellRadius(below, HalfLength, Radii, NeckHeight, NeckDepth), 0.0, below);
  radii->InsertNextValue(0.1);
  vtkNew<vtkIntArray> subtract;
  subtract->SetName("Subtract");
  subtract->InsertNextValue(0);
  subtract->InsertNextValue(1);
  clicks->GetPointData()->AddArray(subtract);
  clicks->Modified();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).empty());
  vtkDataArray* candidate = roi->GetOutput()->GetPointData()->GetArray("RoiCandidate");
  int removedNear = 0, keptFar = 0;
  const double* subtracted = clickPoints->GetPoint(1);
  for (vtkIdType v = 0; candidate && v < dumbbell->GetNumberOfPoints(); ++v)
  {
    const double* p = dumbbell->GetPoint(v);
    const double d = std::sqrt(vtkMath::Distance2BetweenPoints(p, subtracted));
    if (d < 0.2)
    {
      removedNear += candidate->GetComponent(v, 0) == 0.0 ? 1 : 0;
      ok &= KERF_CHECK(candidate->GetComponent(v, 0) == 0.0);
    }
    else if (p[2] > crease + 0.2)
    {
      keptFar += candidate->GetComponent(v, 0) == 1.0 ? 1 : 0;
      ok &= KERF_CHECK(candidate->GetComponent(v, 0) == 1.0);
    }
  }
  std::cout << "subtracted disc: " << removedNear << " vertices near it out of the candidate region, " << keptFar
            << " of the protrusion in it" << std::endl;
  ok &= KERF_CHECK(removedNear > 10 && keptFar > 100);
  ok &=
    KERF_CHECK(1.0 - kerf::compareSegmentations(mesh, labelsOf(roi->GetOutput()), protrusion).randIndexError >= 0.97);
  // Errors of the click arrays: only subtracting clicks, a radius that is not positive.
  subtract->SetValue(0, 1);
  subtract->Modified();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).find("every click subtracts its disc") != std::string::npos);
  subtract->SetValue(0, 0);
  radii->SetValue(1, -0.1);
  radii->Modified();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).find("click 1 has the radius") != std::string::npos);
  clicks->GetPointData()->RemoveArray("Radius");
  clicks->GetPointData()->RemoveArray("Subtract");
  clickPoints->SetNumberOfPoints(1);
  roi->SetRadius(0.5);

  // Errors: a click off the surface, a disc covering the whole surface.
  clickPoints->SetPoint(0, 0.0, 0.0, 5.0);
  clickPoints->Modified();
  std::string error = kerf::test::UpdateAndCaptureError(roi);
  std::cout << error << std::endl;
  ok &= KERF_CHECK(error.find("a click lies off the surface") != std::string::npos);
  ok &= KERF_CHECK(roi->GetOutput()->GetNumberOfPoints() == 0 && roi->GetBoundary()->GetNumberOfPoints() == 0);
  roi->SetInputData(1, nullptr);
  roi->SetRadius(5.0);
  error = kerf::test::UpdateAndCaptureError(roi);
  std::cout << error << std::endl;
  ok &= KERF_CHECK(!error.empty());
  roi->SetInputData(1, vtkSmartPointer<vtkPolyData>::New());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(roi).find("holds no point") != std::string::npos);
  return ok ? 0 : 1;
}
