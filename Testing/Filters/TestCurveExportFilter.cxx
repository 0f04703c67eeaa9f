// vtkCurveExport: the camel cut along its neck stroke exported by scissor, snap and inverse snap; errors, input
// untouched.
#include "KerfTestUtilities.h"
#include "vtkCurveExport.h"
#include "vtkKerfMeshFileReader.h"
#include "vtkStrokeCut.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStaticPointLocator.h>
#include <vtkTriangle.h>

#include <cmath>
#include <set>
#include <vector>

namespace
{

double surfaceArea(vtkPolyData* surface)
{
  double area = 0.0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      surface->GetPoint(ids->GetId(k), p[k]);
    }
    area += vtkTriangle::TriangleArea(p[0], p[1], p[2]);
  }
  return area;
}

double fieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return array ? array->GetComponent(0, 0) : std::nan("");
}

} // namespace

int TestCurveExportFilter(int argc, char* argv[])
{
  bool ok = true;
  const kerf::test::CamelWithNeckStroke files = kerf::test::ReadCamelWithNeckStroke(argc, argv);
  vtkKerfMeshFileReader* camel = files.camel;
  vtkKerfMeshFileReader* stroke = files.stroke;
  vtkNew<vtkStrokeCut> cut;
  cut->SetInputConnection(0, camel->GetOutputPort());
  cut->SetInputConnection(1, stroke->GetOutputPort());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(cut).empty());
  vtkPolyData* surface = camel->GetOutput();
  vtkPolyData* curves = cut->GetCut();
  ok &= KERF_CHECK(curves->GetNumberOfLines() >= 1);
  const vtkMTimeType surfaceTime = surface->GetMTime();
  const vtkMTimeType curvesTime = curves->GetMTime();

  // Scissor: two charts, the area kept, every curve point a vertex of the output.
  vtkNew<vtkCurveExport> scissor;
  scissor->SetInputConnection(0, camel->GetOutputPort());
  scissor->SetInputConnection(1, cut->GetOutputPort(1));
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(scissor).empty());
  vtkPolyData* split = scissor->GetOutput();
  ok &= KERF_CHECK(fieldValue(split, "ChartCount") == 2.0);
  ok &= KERF_CHECK(std::abs(surfaceArea(split) - surfaceArea(surface)) <= 1e-12 * surfaceArea(surface));
  vtkDataArray* charts = split->GetCellData()->GetArray("Chart");
  vtkDataArray* originals = split->GetPointData()->GetArray("OriginalPointId");
  ok &= KERF_CHECK(charts && charts->GetNumberOfTuples() == split->GetNumberOfCells());
  ok &= KERF_CHECK(originals && originals->GetNumberOfTuples() == split->GetNumberOfPoints());
  std::set<double> chartValues;
  for (vtkIdType c = 0; charts && c < charts->GetNumberOfTuples(); ++c)
  {
    chartValues.insert(charts->GetComponent(c, 0));
  }
  ok &= KERF_CHECK((chartValues == std::set<double>{ 0.0, 1.0 }));
  int newPoints = 0;
  for (vtkIdType p = 0; originals && p < originals->GetNumberOfTuples(); ++p)
  {
    const double id = originals->GetComponent(p, 0);
    newPoints += id < 0 ? 1 : 0;
    ok &= KERF_CHECK(id < 0 || id == static_cast<double>(p));
  }
  ok &= KERF_CHECK(newPoints > 0 && split->GetNumberOfPoints() == surface->GetNumberOfPoints() + newPoints);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(split);
  locator->BuildLocator();
  double farthest = 0.0;
  for (vtkIdType i = 0; i < curves->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    curves->GetPoint(i, p);
    split->GetPoint(locator->FindClosestPoint(p), q);
    farthest = std::max(farthest, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  ok &= KERF_CHECK(farthest < 1e-9);
  // The cut edges: lines between output 0's points, as many as the cut's segments or more.
  vtkPolyData* edges = scissor->GetCutEdges();
  ok &= KERF_CHECK(edges->GetNumberOfLines() >= curves->GetNumberOfPoints() - 1);
  ok &= KERF_CHECK(edges->GetPoints() == split->GetPoints());

  // Split open: the triangles and the area kept, each point of the closed cut copied once more,
  // no point used by both charts, each cut edge once per side.
  const vtkIdType closedPoints = split->GetNumberOfPoints();
  const vtkIdType closedCells = split->GetNumberOfCells();
  const vtkIdType closedEdges = edges->GetNumberOfLines();
  const double closedArea = surfaceArea(split);
  scissor->SplitOpenOn();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(scissor).empty());
  vtkPolyData* open = scissor->GetOutput();
  ok &= KERF_CHECK(open->GetNumberOfCells() == closedCells);
  ok &= KERF_CHECK(open->GetNumberOfPoints() == closedPoints + closedEdges); // one loop: as many points as edges
  ok &= KERF_CHECK(std::abs(surfaceArea(open) - closedArea) <= 1e-12 * closedArea);
  ok &= KERF_CHECK(scissor->GetCutEdges()->GetNumberOfLines() == 2 * closedEdges);
  vtkDataArray* openCharts = open->GetCellData()->GetArray("Chart");
  vtkDataArray* openOriginals = open->GetPointData()->GetArray("OriginalPointId");
  ok &= KERF_CHECK(openCharts && openOriginals && openOriginals->GetNumberOfTuples() == open->GetNumberOfPoints());
  std::vector<double> pointChart(static_cast<std::size_t>(open->GetNumberOfPoints()), -1.0);
  vtkNew<vtkIdList> corners;
  for (vtkIdType c = 0; openCharts && c < open->GetNumberOfCells(); ++c)
  {
    open->GetCellPoints(c, corners);
    for (vtkIdType k = 0; k < corners->GetNumberOfIds(); ++k)
    {
      double& chart = pointChart[static_cast<std::size_t>(corners->GetId(k))];
      ok &= KERF_CHECK(chart < 0.0 || chart == openCharts->GetComponent(c, 0));
      chart = openCharts->GetComponent(c, 0);
    }
  }
  scissor->SplitOpenOff();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(scissor).empty());
  split = scissor->GetOutput();
  edges = scissor->GetCutEdges();

  // Snap: the mesh kept, two charts; inverse snap: the connectivity kept, counts reported.
  vtkNew<vtkCurveExport> snap;
  snap->SetInputConnection(0, camel->GetOutputPort());
  snap->SetInputConnection(1, cut->GetOutputPort(1));
  snap->SetModeToSnap();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(snap).empty());
  ok &= KERF_CHECK(snap->GetOutput()->GetNumberOfPoints() == surface->GetNumberOfPoints());
  ok &= KERF_CHECK(snap->GetOutput()->GetNumberOfCells() == surface->GetNumberOfCells());
  ok &= KERF_CHECK(fieldValue(snap->GetOutput(), "ChartCount") == 2.0);
  ok &= KERF_CHECK(fieldValue(snap->GetOutput(), "MovedVertices") == 0.0);
  snap->SetModeToInverseSnap();
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(snap).empty());
  ok &= KERF_CHECK(snap->GetOutput()->GetNumberOfCells() == surface->GetNumberOfCells());
  ok &= KERF_CHECK(fieldValue(snap->GetOutput(), "MovedVertices") > 0.0);
  ok &= KERF_CHECK(fieldValue(snap->GetOutput(), "MovedVertices") + fieldValue(snap->GetOutput(), "RefusedFlips") +
      fieldValue(snap->GetOutput(), "DroppedPoints") <=
    curves->GetNumberOfPoints());
  ok &= KERF_CHECK(fieldValue(snap->GetOutput(), "ChartCount") == 2.0);

  // Errors: no curve, an empty curve input, a curve off the surface (the point named).
  vtkNew<vtkCurveExport> none;
  none->SetInputConnection(0, camel->GetOutputPort());
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(none).find("there is no curve") != std::string::npos);
  vtkNew<vtkPolyData> empty;
  none->SetInputData(1, empty);
  ok &= KERF_CHECK(!kerf::test::UpdateAndCaptureError(none).empty());
  ok &= KERF_CHECK(none->GetOutput()->GetNumberOfPoints() == 0);
  none->SetInputData(1, kerf::test::CirclePolyline(5.0, 0.0, 12));
  const std::string off = kerf::test::UpdateAndCaptureError(none);
  ok &= KERF_CHECK(off.find("point 0") != std::string::npos && off.find("off the surface") != std::string::npos);

  ok &= KERF_CHECK(surface->GetMTime() == surfaceTime);
  ok &= KERF_CHECK(curves->GetMTime() == curvesTime);
  return ok ? 0 : 1;
}
