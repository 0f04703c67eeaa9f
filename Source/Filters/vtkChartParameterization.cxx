// vtkChartParameterization: reads the chart labels, runs kerf::parameterizeCharts, writes the cut surface and its
// layout.
#include "vtkChartParameterization.h"

#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfParameterChecks.h"
#include "KerfSurfaceInput.h"
#include "Parameterization/ChartParameterization.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <array>

vtkStandardNewMacro(vtkChartParameterization);

struct vtkChartParameterization::Internals
{
  kerf::SurfaceInput surface;
};

namespace
{
// The cut surface with the input's arrays carried to its points and triangles, and the result's arrays.
void writeSurface(const kerf::ChartParameterizationResult& result, const kerf::SurfaceInput& surface,
  vtkPolyData* input, const char* uvName, vtkPolyData* output)
{
  const kerf::TriangleMesh& mesh = result.split.mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.vertexCount());
  vtkPointData* inputPoints = input->GetPointData();
  output->GetPointData()->CopyAllocate(inputPoints, mesh.vertexCount());
  // Texture coordinates in single precision, as renderers, VTK's readers and writers (the PLY
  // writer reads them as floats whatever their type) and file formats hold them.
  vtkNew<vtkFloatArray> uv;
  uv->SetName(uvName);
  uv->SetNumberOfComponents(2);
  uv->SetNumberOfTuples(mesh.vertexCount());
  vtkNew<vtkIdTypeArray> originalIds;
  originalIds->SetName("OriginalPointId");
  originalIds->SetNumberOfTuples(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    points->SetPoint(v, mesh.point(v).data());
    const int original = result.split.originalPoint[static_cast<std::size_t>(v)];
    output->GetPointData()->CopyData(inputPoints, original, v);
    const kerf::Vector2& texture = result.uv[static_cast<std::size_t>(v)];
    uv->SetTypedTuple(
      v, std::array<float, 2>{ { static_cast<float>(texture.x()), static_cast<float>(texture.y()) } }.data());
    originalIds->SetValue(v, original);
  }
  output->SetPoints(points);

  vtkNew<vtkCellArray> polys;
  vtkCellData* inputCells = input->GetCellData();
  output->GetCellData()->CopyAllocate(inputCells, mesh.faceCount());
  std::vector<double> stretch(static_cast<std::size_t>(mesh.faceCount()));
  std::vector<double> shear(stretch.size());
  std::vector<unsigned char> flipped(stretch.size());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    const kerf::Triangle& t = mesh.triangle(f);
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
    output->GetCellData()->CopyData(inputCells, surface.SourceCells()[static_cast<std::size_t>(f)], f);
    const kerf::FaceDistortion& distortion = result.faces[static_cast<std::size_t>(f)];
    stretch[static_cast<std::size_t>(f)] = distortion.stretch;
    shear[static_cast<std::size_t>(f)] = distortion.shear;
    flipped[static_cast<std::size_t>(f)] = distortion.flipped ? 1 : 0;
  }
  output->SetPolys(polys);
  output->GetPointData()->SetTCoords(uv);
  output->GetPointData()->AddArray(originalIds);
  output->GetCellData()->AddArray(kerf::MakeIntArray("Chart", result.split.faceLabel));
  output->GetCellData()->AddArray(kerf::MakeArray("Stretch", stretch));
  output->GetCellData()->AddArray(kerf::MakeArray("Shear", shear));
  output->GetCellData()->AddArray(kerf::MakeArray("Flipped", flipped));
}

void writeSummaries(const kerf::ChartParameterizationResult& result, vtkFieldData* field)
{
  const kerf::DistortionSummary& total = result.distortion;
  field->AddArray(kerf::MakeFieldValue("MeanStretch", total.meanStretch));
  field->AddArray(kerf::MakeFieldValue("L2Stretch", total.surfaceStretch));
  field->AddArray(kerf::MakeFieldValue("MaxStretch", total.maxStretch));
  field->AddArray(kerf::MakeFieldValue("MeanShear", total.meanShear));
  field->AddArray(kerf::MakeFieldValue("MaxShear", total.maxShear));
  field->AddArray(kerf::MakeFieldValue("FlippedFaces", total.flippedFaces));
  field->AddArray(kerf::MakeFieldValue("OverlappingChartPairs", result.overlappingChartPairs));
  field->AddArray(kerf::MakeFieldValue("ChartCount", static_cast<double>(result.charts.size())));
  field->AddArray(kerf::MakeFieldValue("TexelScale", result.texelScale));
  field->AddArray(kerf::MakeFieldValue("CutCharts", result.cutCharts));
  std::vector<int> labels, flipped, cutEdges, seams;
  std::vector<double> meanStretch, l2Stretch, maxStretch, meanShear, maxShear, cutLength, seamLength;
  for (const kerf::ChartSummary& chart : result.charts)
  {
    labels.push_back(chart.label);
    flipped.push_back(chart.distortion.flippedFaces);
    meanStretch.push_back(chart.distortion.meanStretch);
    l2Stretch.push_back(chart.distortion.surfaceStretch);
    maxStretch.push_back(chart.distortion.maxStretch);
    meanShear.push_back(chart.distortion.meanShear);
    maxShear.push_back(chart.distortion.maxShear);
    cutEdges.push_back(chart.cutEdgeCount);
    cutLength.push_back(chart.cutLength);
    seams.push_back(chart.seams);
    seamLength.push_back(chart.seamLength);
  }
  field->AddArray(kerf::MakeIntArray("ChartLabel", labels));
  field->AddArray(kerf::MakeArray("ChartMeanStretch", meanStretch));
  field->AddArray(kerf::MakeArray("ChartL2Stretch", l2Stretch));
  field->AddArray(kerf::MakeArray("ChartMaxStretch", maxStretch));
  field->AddArray(kerf::MakeArray("ChartMeanShear", meanShear));
  field->AddArray(kerf::MakeArray("ChartMaxShear", maxShear));
  field->AddArray(kerf::MakeIntArray("ChartFlippedFaces", flipped));
  field->AddArray(kerf::MakeIntArray("ChartCutEdges", cutEdges));
  field->AddArray(kerf::MakeArray("ChartCutLength", cutLength));
  field->AddArray(kerf::MakeIntArray("ChartSeams", seams));
  field->AddArray(kerf::MakeArray("ChartSeamLength", seamLength));
}

// The triangles of `surface` at their texture coordinates in z = 0, with its arrays.
void writeLayout(const kerf::ChartParameterizationResult& result, vtkPolyData* surface, vtkPolyData* layout)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(result.uv.size()));
  // At the texture coordinates as output 0 holds them (in single precision).
  vtkDataArray* uv = surface->GetPointData()->GetTCoords();
  for (vtkIdType v = 0; v < static_cast<vtkIdType>(result.uv.size()); ++v)
  {
    points->SetPoint(v, uv->GetComponent(v, 0), uv->GetComponent(v, 1), 0.0);
  }
  layout->SetPoints(points);
  layout->SetPolys(surface->GetPolys());
  layout->GetPointData()->ShallowCopy(surface->GetPointData());
  layout->GetCellData()->ShallowCopy(surface->GetCellData());
  layout->GetFieldData()->ShallowCopy(surface->GetFieldData());
}
} // namespace

vtkChartParameterization::vtkChartParameterization()
  : State(new Internals)
{
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Chart");
  this->SetTextureCoordinatesName("UV");
}

vtkChartParameterization::~vtkChartParameterization()
{
  this->SetTextureCoordinatesName(nullptr);
}

int vtkChartParameterization::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return kerf::RunGuarded(this, "Cannot parameterize the charts", [&]() {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    vtkPolyData* layout = vtkPolyData::GetData(outputVector, 1);
    kerf::CheckOutputNames({ this->TextureCoordinatesName });
    kerf::MeshRequirements requirements;
    requirements.allowZeroAreaFaces = false;
    kerf::LoadSurface(this->State->surface, input, requirements);
    const std::vector<int> labels =
      kerf::ReadTriangleLabels(this, 0, this->State->surface, input->GetNumberOfCells(), "the surface's chart labels");

    kerf::ChartParameterizationOptions options;
    options.method = this->Method == LINABF ? kerf::ChartMethod::LinABF : kerf::ChartMethod::LSCM;
    options.margin = this->Margin;
    options.cutToDisks = this->CutToDisks;
    options.maximumSeams = this->MaximumSeams;
    options.seamStretchTarget = this->SeamStretchTarget;
    const kerf::ChartParameterizationResult result =
      kerf::parameterizeCharts(this->State->surface.Mesh(), labels, options);

    writeSurface(result, this->State->surface, input, this->TextureCoordinatesName, output);
    output->GetFieldData()->ShallowCopy(input->GetFieldData());
    writeSummaries(result, output->GetFieldData());
    writeLayout(result, output, layout);
  });
}

void vtkChartParameterization::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << (this->Method == LINABF ? "LinABF" : "LSCM") << "\n";
  os << indent << "Margin: " << this->Margin << "\n";
  os << indent << "CutToDisks: " << this->CutToDisks << "\n";
  os << indent << "MaximumSeams: " << this->MaximumSeams << "\n";
  os << indent << "SeamStretchTarget: " << this->SeamStretchTarget << "\n";
  os << indent << "TextureCoordinatesName: " << (this->TextureCoordinatesName ? this->TextureCoordinatesName : "(none)")
     << "\n";
}
