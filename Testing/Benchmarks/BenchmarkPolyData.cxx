// Builds vtkPolyData from kerf::TriangleMesh by filling VTK's arrays directly.
#include "BenchmarkPolyData.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace kerf
{
namespace benchmarks
{

vtkSmartPointer<vtkPolyData> MakePolyData(const TriangleMesh& mesh)
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    coordinates->SetTypedTuple(v, mesh.point(v).data());
  }
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);

  // vtkIdTypeArray offsets and connectivity are adopted by vtkCellArray without a copy.
  const vtkIdType faces = mesh.faceCount();
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(faces + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * faces);
  for (vtkIdType f = 0; f < faces; ++f)
  {
    const Triangle& t = mesh.triangle(static_cast<int>(f));
    offsets->SetValue(f, 3 * f);
    connectivity->SetValue(3 * f, t[0]);
    connectivity->SetValue(3 * f + 1, t[1]);
    connectivity->SetValue(3 * f + 2, t[2]);
  }
  offsets->SetValue(faces, 3 * faces);
  vtkNew<vtkCellArray> triangles;
  triangles->SetData(offsets, connectivity);

  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(triangles);
  return polyData;
}

} // namespace benchmarks
} // namespace kerf
