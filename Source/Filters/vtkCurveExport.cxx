// vtkCurveExport: the curves placed on the surface, exported by kerf::exportCurves, the mesh and its cut edges written
// out.
#include "vtkCurveExport.h"

#include "Error.h"
#include "Export/CurveExport.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Mesh/SplitAlongFaceLabels.h"
#include "Surface/Surface.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(vtkCurveExport);

struct vtkCurveExport::Internals
{
  kerf::SurfaceInput surface;
};

namespace
{

double meanEdgeLength(const kerf::TriangleMesh& mesh)
{
  double total = 0.0;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    total += (mesh.point(mesh.edgeVertices(e)[0]) - mesh.point(mesh.edgeVertices(e)[1])).norm();
  }
  return mesh.edgeCount() > 0 ? total / mesh.edgeCount() : 0.0;
}

// Output 0: the exported mesh, with the input's point data (interpolated at new vertices) and
// cell data (from each triangle's input cell).
void writeSurface(
  const kerf::CurveExportResult& result, const kerf::SurfaceInput& surface, vtkPolyData* input, vtkPolyData* output)
{
  const kerf::TriangleMesh& original = surface.Mesh();
  const kerf::TriangleMesh& mesh = kerf::exportedMesh(result, original);
  const bool split = !result.originalPointIds.empty(); // scissor: new points and triangles
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    points->SetPoint(v, mesh.point(v).data());
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(mesh.faceCount(), 3 * mesh.faceCount());
  for (const kerf::Triangle& t : mesh.triangles())
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  output->SetPoints(points);
  output->SetPolys(polys);

  vtkPointData* inPoints = input->GetPointData();
  vtkPointData* outPoints = output->GetPointData();
  outPoints->InterpolateAllocate(inPoints, mesh.vertexCount());
  vtkNew<vtkIdList> corners;
  corners->SetNumberOfIds(3);
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const int id = split ? result.originalPointIds[static_cast<std::size_t>(v)] : v;
    if (id >= 0)
    {
      outPoints->CopyData(inPoints, id, v);
      continue;
    }
    const kerf::SurfacePoint& origin = result.pointOrigins[static_cast<std::size_t>(v)];
    double weights[3];
    for (int k = 0; k < 3; ++k)
    {
      corners->SetId(k, original.triangle(origin.face)[k]);
      weights[k] = origin.barycentric[k];
    }
    outPoints->InterpolatePoint(inPoints, v, corners, weights);
  }
  vtkCellData* inCells = input->GetCellData();
  vtkCellData* outCells = output->GetCellData();
  outCells->CopyAllocate(inCells, mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const int face = split ? result.originalFaces[static_cast<std::size_t>(f)] : f;
    outCells->CopyData(inCells, surface.SourceCells()[static_cast<std::size_t>(face)], f);
  }

  vtkNew<vtkIntArray> charts;
  charts->SetName("Chart");
  charts->SetNumberOfValues(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    charts->SetValue(f, result.charts[static_cast<std::size_t>(f)]);
  }
  outCells->AddArray(charts);
  outCells->SetActiveScalars("Chart");
  vtkNew<vtkIdTypeArray> originalIds;
  originalIds->SetName("OriginalPointId");
  originalIds->SetNumberOfValues(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    originalIds->SetValue(v, split ? result.originalPointIds[static_cast<std::size_t>(v)] : v);
  }
  outPoints->AddArray(originalIds);
  vtkFieldData* field = output->GetFieldData();
  field->AddArray(kerf::MakeFieldValue("ChartCount", result.chartCount));
  field->AddArray(kerf::MakeFieldValue("MovedVertices", result.movedVertices));
  field->AddArray(kerf::MakeFieldValue("DroppedPoints", result.droppedPoints));
  field->AddArray(kerf::MakeFieldValue("RefusedFlips", result.refusedFlips));
}

// Output 0 cut open where charts meet (kerf::splitAlongFaceLabels): its points copied once per
// chart around them, with their point data; its triangles and cell data as they were.
kerf::SplitMesh splitOpen(const kerf::CurveExportResult& result, const kerf::TriangleMesh& mesh, vtkPolyData* output)
{
  kerf::SplitMesh split = kerf::splitAlongFaceLabels(mesh, result.charts);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(split.mesh.vertexCount());
  vtkNew<vtkPointData> pointData;
  pointData->CopyAllocate(output->GetPointData(), split.mesh.vertexCount());
  for (int v = 0; v < split.mesh.vertexCount(); ++v)
  {
    points->SetPoint(v, split.mesh.point(v).data());
    pointData->CopyData(output->GetPointData(), split.originalPoint[static_cast<std::size_t>(v)], v);
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(split.mesh.faceCount(), 3 * split.mesh.faceCount());
  for (const kerf::Triangle& t : split.mesh.triangles())
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->ShallowCopy(pointData);
  return split;
}

// Output 1: each cut edge as a line between output 0's points; on a mesh cut open, once per side.
void writeCutEdges(const kerf::CurveExportResult& result, const kerf::TriangleMesh& mesh,
  const kerf::TriangleMesh& written, vtkPolyData* output, vtkPolyData* edges)
{
  std::vector<char> cut(static_cast<std::size_t>(written.edgeCount()), 0);
  for (int f = 0; f < mesh.faceCount(); ++f) // faces keep their order and corners when cut open
  {
    for (int k = 0; k < 3; ++k)
    {
      const int e = mesh.faceEdge(f, k);
      if (e >= 0 && result.cutEdges[static_cast<std::size_t>(e)] && written.faceEdge(f, k) >= 0)
      {
        cut[static_cast<std::size_t>(written.faceEdge(f, k))] = 1;
      }
    }
  }
  edges->SetPoints(output->GetPoints());
  vtkNew<vtkCellArray> lines;
  for (int e = 0; e < written.edgeCount(); ++e)
  {
    if (cut[static_cast<std::size_t>(e)])
    {
      const vtkIdType ids[2] = { written.edgeVertices(e)[0], written.edgeVertices(e)[1] };
      lines->InsertNextCell(2, ids);
    }
  }
  edges->SetLines(lines);
}

} // namespace

vtkCurveExport::vtkCurveExport()
  : State(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

vtkCurveExport::~vtkCurveExport() = default;

vtkPolyData* vtkCurveExport::GetCutEdges()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkCurveExport::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkCurveExport::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot export the curves", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::LoadSurface(this->State->surface, input, kerf::MeshRequirements());
    const kerf::Surface& surface = this->State->surface.GetSurface();
    vtkPolyData* lines = vtkPolyData::GetData(inputVector[1], 0);
    if (!lines)
    {
      throw kerf::Error("there is no curve: connect polylines on the surface to input 1 (for example Stroke "
                        "Cut's cut or Geodesic Seam's seam)");
    }
    const double tolerance = kerf::Finite(this->Tolerance, "Tolerance") *
      surface.derived<double>("mean edge length", [&]() { return meanEdgeLength(surface.mesh()); });
    const std::vector<kerf::SurfaceCurve> curves =
      kerf::PlaceLinesOnSurface(surface, lines, tolerance, "the curve input");
    this->UpdateProgress(0.2);

    kerf::CurveExportOptions options;
    options.mode = static_cast<kerf::CurveExportMode>(this->Mode);
    const kerf::CurveExportResult result = kerf::exportCurves(surface.mesh(), curves, options);
    writeSurface(result, this->State->surface, input, output);
    const kerf::TriangleMesh& exported = kerf::exportedMesh(result, surface.mesh());
    vtkPolyData* cutEdges = vtkPolyData::GetData(outputVector, 1);
    if (this->SplitOpen)
    {
      const kerf::SplitMesh split = splitOpen(result, exported, output);
      writeCutEdges(result, exported, split.mesh, output, cutEdges);
    }
    else
    {
      writeCutEdges(result, exported, exported, output, cutEdges);
    }
  });
}

void vtkCurveExport::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "SplitOpen: " << this->SplitOpen << "\n";
}
