// vtkGeometrySeamCarving: reads the preprocessed surface and the handle transform, runs a kerf::GeometrySeamCarving
// session, writes the deformed surface.
#include "vtkGeometrySeamCarving.h"

#include "Error.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfSurfaceInput.h"
#include "SeamCarving/GeometrySeamCarving.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkLinearTransform.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cmath>

vtkStandardNewMacro(vtkGeometrySeamCarving);

struct vtkGeometrySeamCarving::Internals
{
  kerf::SurfaceInput surface;
  vtkSmartPointer<vtkLinearTransform> transform;
  // The session and what it was made from: a new surface, new arrays or new options start afresh.
  std::unique_ptr<kerf::GeometrySeamCarving> session;
  std::shared_ptr<const kerf::Surface> sessionSurface;
  std::array<double, 4> sessionOptions{ { NAN, NAN, NAN, NAN } };
  std::vector<double> sessionArrays;
};

vtkGeometrySeamCarving::vtkGeometrySeamCarving()
  : State(new Internals)
{
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Region");
  this->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "RingSeam");
  this->SetInputArrayToProcess(2, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Sector");
  this->SetInputArrayToProcess(3, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "EdgeCost");
}

vtkGeometrySeamCarving::~vtkGeometrySeamCarving() = default;

void vtkGeometrySeamCarving::SetHandleTransform(vtkLinearTransform* transform)
{
  if (this->State->transform != transform)
  {
    this->State->transform = transform;
    this->Modified();
  }
}

vtkLinearTransform* vtkGeometrySeamCarving::GetHandleTransform()
{
  return this->State->transform;
}

vtkMTimeType vtkGeometrySeamCarving::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->State->transform)
  {
    time = std::max(time, this->State->transform->GetMTime());
  }
  return time;
}

namespace
{
// The handle transform's matrix; the identity without a transform.
Eigen::Matrix4d handleMatrix(vtkLinearTransform* transform)
{
  Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
  if (transform)
  {
    vtkMatrix4x4* m = transform->GetMatrix();
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        matrix(r, c) = m->GetElement(r, c);
      }
    }
  }
  return matrix;
}

// The deformed surface with OriginalPointId, the region array (named as the input's; new points
// are modeling points), RingSeam, Sector, and the session's counts as field data.
void writeCarving(const kerf::SeamCarvingResult& result, int salientSegments, const std::vector<double>& inputRegion,
  const char* regionName, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(result.points.size()));
  for (std::size_t i = 0; i < result.points.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), result.points[i].data());
  }
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(
    static_cast<vtkIdType>(result.triangles.size()), 3 * static_cast<vtkIdType>(result.triangles.size()));
  for (const kerf::Triangle& t : result.triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  output->SetPoints(points);
  output->SetPolys(triangles);
  std::vector<double> region;
  for (int origin : result.pointOrigin)
  {
    region.push_back(origin >= 0 ? inputRegion[static_cast<std::size_t>(origin)] : 1.0);
  }
  output->GetPointData()->AddArray(kerf::MakeIntArray("OriginalPointId", result.pointOrigin));
  output->GetPointData()->AddArray(kerf::MakeArray(regionName, region));
  output->GetCellData()->AddArray(kerf::MakeIntArray("RingSeam", result.faceRing));
  output->GetCellData()->AddArray(kerf::MakeIntArray("Sector", result.faceSector));
  output->GetCellData()->SetActiveScalars("RingSeam");
  output->GetFieldData()->AddArray(kerf::MakeIntArray("SectorState", result.sectorState));
  output->GetFieldData()->AddArray(kerf::MakeFieldValue("SplitSegments", static_cast<double>(result.splitSegments)));
  output->GetFieldData()->AddArray(
    kerf::MakeFieldValue("CollapsedSegments", static_cast<double>(result.collapsedSegments)));
  output->GetFieldData()->AddArray(
    kerf::MakeFieldValue("SkippedOperations", static_cast<double>(result.skippedOperations)));
  output->GetFieldData()->AddArray(kerf::MakeFieldValue("SalientSegments", static_cast<double>(salientSegments)));
}
} // namespace

int vtkGeometrySeamCarving::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot carve geometry seams", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    kerf::MeshRequirements requirements;
    requirements.manifold = true;
    requirements.consistentOrientation = true;
    kerf::SurfaceInput& surface = this->State->surface;
    kerf::LoadSurface(surface, input, requirements);
    if (surface.Rebuilt() || surface.WeldedPointCount() > 0)
    {
      throw kerf::Error("the surface must hold triangles only, each point once (run Triangulate and Clean, then "
                        "Geometry Seams, first)");
    }
    const kerf::TriangleMesh& mesh = surface.Mesh();
    // The arrays Geometry Seams writes; a message says to run it when one is missing or wrong.
    const auto fromGeometrySeams = [](const char* what, const auto& readArray) {
      try
      {
        return readArray();
      }
      catch (const kerf::Error& e)
      {
        throw kerf::Error(std::string(e.what()) + " (the " + what + " array that Geometry Seams writes; run it first)");
      }
    };
    const vtkIdType cells = input->GetNumberOfCells();
    kerf::SeamCarvingInput in;
    in.mesh = &mesh;
    in.region = fromGeometrySeams(
      "region", [&] { return kerf::ReadInputArray(this, 0, input->GetNumberOfPoints(), "the surface"); });
    in.faceRing =
      fromGeometrySeams("ring seam", [&] { return kerf::ReadTriangleLabels(this, 1, surface, cells, "the surface"); });
    in.faceSector =
      fromGeometrySeams("sector", [&] { return kerf::ReadTriangleLabels(this, 2, surface, cells, "the surface"); });
    in.faceCost = fromGeometrySeams("edge cost", [&] { return kerf::ReadInputArray(this, 3, cells, "the surface"); });
    in.normalConeAngle = surface.GetSurface().descriptors().normalConeAngle;

    kerf::SeamCarvingOptions options;
    options.stiffnessScale = this->StiffnessScale;
    options.stiffnessEpsilon = this->StiffnessEpsilon;
    options.plastic = this->Plastic;
    options.salientThreshold = this->SalientThreshold;
    const std::array<double, 4> optionKey{ { options.stiffnessScale, options.stiffnessEpsilon,
      options.plastic ? 1.0 : 0.0, options.salientThreshold } };
    std::vector<double> arrayKey = in.region;
    arrayKey.insert(arrayKey.end(), in.faceRing.begin(), in.faceRing.end());
    arrayKey.insert(arrayKey.end(), in.faceSector.begin(), in.faceSector.end());
    arrayKey.insert(arrayKey.end(), in.faceCost.begin(), in.faceCost.end());
    Internals& state = *this->State;
    if (!state.session || state.sessionSurface != surface.SharedSurface() || state.sessionOptions != optionKey ||
      state.sessionArrays != arrayKey)
    {
      state.session.reset();
      state.session = std::make_unique<kerf::GeometrySeamCarving>(in, options);
      state.sessionSurface = surface.SharedSurface();
      state.sessionOptions = optionKey;
      state.sessionArrays = std::move(arrayKey);
    }
    this->UpdateProgress(0.2);

    const kerf::SeamCarvingResult& result = state.session->deform(handleMatrix(state.transform));
    vtkDataArray* regionArray = this->GetInputArrayToProcess(0, input);
    writeCarving(result, state.session->salientSegmentCount(), in.region,
      regionArray && regionArray->GetName() ? regionArray->GetName() : "Region", output);
  });
}

void vtkGeometrySeamCarving::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HandleTransform: " << this->State->transform.Get() << "\n";
  os << indent << "StiffnessScale: " << this->StiffnessScale << "\n";
  os << indent << "StiffnessEpsilon: " << this->StiffnessEpsilon << "\n";
  os << indent << "Plastic: " << this->Plastic << "\n";
  os << indent << "SalientThreshold: " << this->SalientThreshold << "\n";
}
