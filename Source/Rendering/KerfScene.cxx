// Scene building for the command-line program and the image tests.
#include "KerfScene.h"

#include "KerfDisplay.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkContourFilter.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDiscretizableColorTransferFunction.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace kerf
{

namespace
{
// The value below which `fraction` of the finite values lie.
double quantile(std::vector<double> values, double fraction)
{
  if (values.empty())
  {
    return 0.0;
  }
  const std::size_t k = std::min(
    values.size() - 1, static_cast<std::size_t>(std::floor(fraction * static_cast<double>(values.size() - 1))));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

// Twelve well-separated colours for labels.
const double LabelColors[12][3] = { { 0.122, 0.467, 0.706 }, { 1.000, 0.498, 0.055 }, { 0.173, 0.627, 0.173 },
  { 0.839, 0.153, 0.157 }, { 0.580, 0.404, 0.741 }, { 0.549, 0.337, 0.294 }, { 0.890, 0.467, 0.761 },
  { 0.498, 0.498, 0.498 }, { 0.737, 0.741, 0.133 }, { 0.090, 0.745, 0.812 }, { 0.682, 0.780, 0.910 },
  { 1.000, 0.733, 0.471 } };

// The edges between cells with different labels, as lines lifted slightly off the surface.
vtkSmartPointer<vtkPolyData> segmentBoundaries(vtkPolyData* surface, vtkDataArray* labels)
{
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> firstCell;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
  {
    surface->GetCellPoints(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = ids->GetId(k), b = ids->GetId((k + 1) % n);
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto found = firstCell.find(key);
      if (found == firstCell.end())
      {
        firstCell.emplace(key, c);
      }
      else if (labels->GetComponent(found->second, 0) != labels->GetComponent(c, 0))
      {
        const vtkIdType edge[2] = { a, b };
        lines->InsertNextCell(2, edge);
      }
    }
  }
  vtkNew<vtkPolyData> boundaries;
  boundaries->SetPoints(surface->GetPoints());
  boundaries->SetLines(lines);
  return boundaries;
}

vtkSmartPointer<vtkPolyData> directionStrokes(vtkPolyData* surface, vtkDataArray* directions, int count)
{
  const vtkIdType n = surface->GetNumberOfPoints();
  vtkDataArray* normals = surface->GetPointData()->GetNormals();
  double bounds[6];
  surface->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) + (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double length = 0.45 * diagonal / std::sqrt(static_cast<double>(std::max(count, 1)));
  const vtkIdType stride = std::max<vtkIdType>(1, n / std::max(count, 1));
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (vtkIdType i = 0; i < n; i += stride)
  {
    double p[3], d[3], normal[3] = { 0, 0, 0 };
    surface->GetPoint(i, p);
    directions->GetTuple(i, d);
    if (normals)
    {
      normals->GetTuple(i, normal);
    }
    const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(norm > 0.0))
    {
      continue;
    }
    double a[3], b[3];
    for (int k = 0; k < 3; ++k)
    {
      const double lift = p[k] + 0.002 * diagonal * normal[k];
      a[k] = lift - 0.5 * length * d[k] / norm;
      b[k] = lift + 0.5 * length * d[k] / norm;
    }
    const vtkIdType ids[2] = { points->InsertNextPoint(a), points->InsertNextPoint(b) };
    lines->InsertNextCell(2, ids);
  }
  vtkNew<vtkPolyData> strokes;
  strokes->SetPoints(points);
  strokes->SetLines(lines);
  return strokes;
}
} // namespace

namespace
{
// A texture of squares x squares dark and light squares over the unit square, 16 texels each.
vtkSmartPointer<vtkTexture> checkerboardTexture(int squares)
{
  const int side = 16 * squares;
  vtkNew<vtkImageData> image;
  image->SetDimensions(side, side, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < side; ++y)
  {
    for (int x = 0; x < side; ++x)
    {
      const bool dark = ((x / 16) + (y / 16)) % 2 == 0;
      unsigned char* texel = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
      texel[0] = dark ? 40 : 235;
      texel[1] = dark ? 60 : 225;
      texel[2] = dark ? 110 : 200;
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOff();
  return texture;
}

// A renderer showing the surface as the options say, or nullptr and `error`.
vtkSmartPointer<vtkRenderer> makeRenderer(vtkPolyData* surface, const SceneOptions& options, std::string& error)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkRenderer> renderer;
  renderer->GradientBackgroundOn();
  renderer->SetBackground(0.93, 0.93, 0.95);
  renderer->SetBackground2(0.72, 0.75, 0.82);

  if (!options.colorArray.empty())
  {
    vtkDataArray* array = surface->GetPointData()->GetArray(options.colorArray.c_str());
    bool onCells = false;
    if (!array)
    {
      array = surface->GetCellData()->GetArray(options.colorArray.c_str());
      onCells = array != nullptr;
    }
    if (!array || array->GetNumberOfComponents() != 1)
    {
      error = "no one-component point or cell array named '" + options.colorArray + "'";
      return nullptr;
    }
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(array->GetNumberOfTuples()));
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
    {
      const double value = array->GetComponent(i, 0);
      if (std::isfinite(value))
      {
        values.push_back(value);
      }
    }
    vtkSmartPointer<vtkScalarsToColors> colors;
    if (options.colorMap == SceneOptions::ColorMap::Categorical && onCells && options.outlineSegments)
    {
      vtkNew<vtkPolyDataMapper> boundaryMapper;
      boundaryMapper->SetInputData(segmentBoundaries(surface, array));
      boundaryMapper->SetResolveCoincidentTopologyToPolygonOffset();
      vtkNew<vtkActor> boundaryActor;
      boundaryActor->SetMapper(boundaryMapper);
      boundaryActor->GetProperty()->SetColor(0.05, 0.05, 0.05);
      boundaryActor->GetProperty()->SetLineWidth(2.0);
      boundaryActor->GetProperty()->LightingOff();
      renderer->AddActor(boundaryActor);
      mapper->SetResolveCoincidentTopologyToPolygonOffset();
    }
    if (options.colorMap == SceneOptions::ColorMap::Categorical)
    {
      vtkNew<vtkLookupTable> table;
      const double lo = values.empty() ? 0.0 : *std::min_element(values.begin(), values.end());
      const double hi = values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
      const int labels = static_cast<int>(hi - lo) + 1;
      table->SetNumberOfTableValues(std::max(labels, 1));
      for (int i = 0; i < labels; ++i)
      {
        const double* c = LabelColors[i % 12];
        table->SetTableValue(i, c[0], c[1], c[2], 1.0);
      }
      table->SetTableRange(lo - 0.5, hi + 0.5);
      table->Build();
      colors = table;
    }
    else
    {
      vtkNew<vtkDiscretizableColorTransferFunction> ctf;
      ctf->SetColorSpaceToDiverging();
      double lo, hi;
      if (options.colorMap == SceneOptions::ColorMap::Diverging)
      {
        std::vector<double> magnitudes(values);
        for (double& m : magnitudes)
        {
          m = std::abs(m);
        }
        hi = options.symmetricRange > 0.0 ? options.symmetricRange
                                          : std::max(quantile(magnitudes, options.rangeFraction), 1e-12);
        lo = -hi;
        ctf->AddRGBPoint(lo, 0.230, 0.299, 0.754);
        ctf->AddRGBPoint(0.0, 0.865, 0.865, 0.865);
        ctf->AddRGBPoint(hi, 0.706, 0.016, 0.150);
      }
      else
      {
        lo = quantile(values, 1.0 - options.rangeFraction);
        hi = std::max(quantile(values, options.rangeFraction), lo + 1e-12);
        ctf->SetColorSpaceToLab();
        ctf->AddRGBPoint(lo, 0.267, 0.005, 0.329);
        ctf->AddRGBPoint(0.5 * (lo + hi), 0.128, 0.567, 0.551);
        ctf->AddRGBPoint(hi, 0.993, 0.906, 0.144);
      }
      ctf->SetNanColor(0.8, 0.8, 0.8); // values without a number (a field solved on part of the surface)
      ctf->DiscretizeOn();
      ctf->SetNumberOfValues(256);
      ctf->Build();
      colors = ctf;
    }
    mapper->SetLookupTable(colors);
    mapper->SetScalarModeToUsePointFieldData();
    if (onCells)
    {
      mapper->SetScalarModeToUseCellFieldData();
    }
    mapper->SelectColorArray(options.colorArray.c_str());
    mapper->SetUseLookupTableScalarRange(true);
    mapper->ScalarVisibilityOn();
    mapper->SetColorModeToMapScalars();
    mapper->InterpolateScalarsBeforeMappingOn();

    if (options.colorMap != SceneOptions::ColorMap::Categorical)
    {
      vtkNew<vtkScalarBarActor> legend;
      legend->SetLookupTable(colors);
      legend->SetTitle(options.legendTitle.empty() ? options.colorArray.c_str() : options.legendTitle.c_str());
      legend->SetNumberOfLabels(5);
      legend->SetLabelFormat("%-#6.3g");
      legend->SetWidth(0.14);
      legend->SetHeight(0.6);
      legend->SetPosition(0.84, 0.18);
      legend->SetBarRatio(0.3);
      legend->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
      legend->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
      legend->GetTitleTextProperty()->ShadowOff();
      legend->GetLabelTextProperty()->ShadowOff();
      legend->GetTitleTextProperty()->ItalicOff();
      legend->GetLabelTextProperty()->ItalicOff();
      legend->UnconstrainedFontSizeOn();
      legend->GetTitleTextProperty()->SetFontSize(13);
      legend->GetLabelTextProperty()->SetFontSize(12);
      renderer->AddActor2D(legend);
    }
  }

  if (options.isolineCount > 0 && !options.colorArray.empty() &&
    surface->GetPointData()->GetArray(options.colorArray.c_str()))
  {
    double range[2];
    surface->GetPointData()->GetArray(options.colorArray.c_str())->GetRange(range);
    const double* tableRange = mapper->GetLookupTable()->GetRange();
    const double lo = std::max(range[0], tableRange[0]), hi = std::min(range[1], tableRange[1]);
    vtkNew<vtkContourFilter> contours;
    contours->SetInputData(surface);
    contours->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, options.colorArray.c_str());
    contours->GenerateValues(
      options.isolineCount, lo + (hi - lo) / (options.isolineCount + 1), hi - (hi - lo) / (options.isolineCount + 1));
    contours->ComputeScalarsOff();
    vtkNew<vtkPolyDataMapper> contourMapper;
    contourMapper->SetInputConnection(contours->GetOutputPort());
    contourMapper->ScalarVisibilityOff();
    contourMapper->SetResolveCoincidentTopologyToPolygonOffset();
    vtkNew<vtkActor> contourActor;
    contourActor->SetMapper(contourMapper);
    contourActor->GetProperty()->SetColor(0.15, 0.15, 0.15);
    contourActor->GetProperty()->SetLineWidth(1.0);
    contourActor->GetProperty()->LightingOff();
    renderer->AddActor(contourActor);
    mapper->SetResolveCoincidentTopologyToPolygonOffset();
  }

  for (const SceneOptions::Overlay& overlay : options.overlays)
  {
    vtkNew<vtkPolyDataMapper> overlayMapper;
    overlayMapper->SetInputData(overlay.data);
    overlayMapper->ScalarVisibilityOff();
    overlayMapper->SetResolveCoincidentTopologyToPolygonOffset();
    vtkNew<vtkActor> overlayActor;
    overlayActor->SetMapper(overlayMapper);
    overlayActor->GetProperty()->SetColor(overlay.color[0], overlay.color[1], overlay.color[2]);
    overlayActor->GetProperty()->SetLineWidth(static_cast<float>(overlay.width));
    overlayActor->GetProperty()->SetPointSize(static_cast<float>(overlay.width));
    overlayActor->GetProperty()->SetRenderPointsAsSpheres(true);
    overlayActor->GetProperty()->SetRenderLinesAsTubes(true);
    renderer->AddActor(overlayActor);
    mapper->SetResolveCoincidentTopologyToPolygonOffset();
  }

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.85, 0.82);
  actor->GetProperty()->SetSpecular(0.15);
  actor->GetProperty()->SetSpecularPower(20.0);
  if (options.checkerboardSquares > 0)
  {
    if (!surface->GetPointData()->GetTCoords())
    {
      error = "the surface has no texture coordinates for the checkerboard";
      return nullptr;
    }
    actor->SetTexture(checkerboardTexture(options.checkerboardSquares));
    actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  }
  renderer->AddActor(actor);

  if (!options.directionArray.empty())
  {
    vtkDataArray* directions = surface->GetPointData()->GetArray(options.directionArray.c_str());
    if (!directions || directions->GetNumberOfComponents() != 3)
    {
      error = "no three-component point array named '" + options.directionArray + "'";
      return nullptr;
    }
    vtkNew<vtkPolyDataMapper> strokeMapper;
    strokeMapper->SetInputData(directionStrokes(surface, directions, options.directionCount));
    vtkNew<vtkActor> strokes;
    strokes->SetMapper(strokeMapper);
    strokes->GetProperty()->SetColor(0.15, 0.15, 0.2);
    strokes->GetProperty()->SetLineWidth(1.2);
    strokes->GetProperty()->LightingOff();
    renderer->AddActor(strokes);
  }

  if (!options.caption.empty())
  {
    vtkNew<vtkTextActor> caption;
    caption->SetInput(options.caption.c_str());
    caption->GetTextProperty()->SetFontSize(16);
    caption->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
    caption->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    caption->GetPositionCoordinate()->SetValue(0.015, 1.0 - 30.0 / options.height);
    renderer->AddActor2D(caption);
  }

  renderer->ResetCamera();
  vtkCamera* camera = renderer->GetActiveCamera();
  if (options.frameLongestAxis)
  {
    double bounds[6];
    surface->GetBounds(bounds);
    const double extent[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] };
    const int shortest = static_cast<int>(std::min_element(extent, extent + 3) - extent);
    const int longest = static_cast<int>(std::max_element(extent, extent + 3) - extent);
    double position[3], up[3] = { 0, 0, 0 };
    const double* focal = camera->GetFocalPoint();
    const double distance = camera->GetDistance();
    for (int k = 0; k < 3; ++k)
    {
      position[k] = focal[k] + (k == shortest ? distance : 0.0);
    }
    up[longest == shortest ? (shortest + 1) % 3 : longest] = 1.0;
    camera->SetPosition(position);
    camera->SetViewUp(up);
  }
  camera->Azimuth(options.azimuth);
  camera->Elevation(options.elevation);
  camera->OrthogonalizeViewUp();
  renderer->ResetCamera();
  camera->Zoom(options.zoom);
  return renderer;
}

vtkSmartPointer<vtkRenderWindow> makeWindow(const SceneOptions& options)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  std::string noDisplay; // without one, VTK reports it when the window is first rendered
  if (void* display = ProcessDisplay(noDisplay))
  {
    window->SetDisplayId(display);
  }
  window->SetOffScreenRendering(options.offscreen ? 1 : 0);
  window->SetSize(options.width, options.height);
  window->SetMultiSamples(0);
  return window;
}
// Two views in one window, each half of the left options' size, optionally with one camera.
vtkSmartPointer<vtkRenderWindow> renderTwoViews(vtkPolyData* leftSurface, const SceneOptions& left,
  vtkPolyData* rightSurface, const SceneOptions& right, bool shareCamera, std::string& error)
{
  SceneOptions leftHalf = left, rightHalf = right;
  leftHalf.width = rightHalf.width = left.width / 2;
  leftHalf.height = rightHalf.height = left.height;
  vtkSmartPointer<vtkRenderer> a = makeRenderer(leftSurface, leftHalf, error);
  vtkSmartPointer<vtkRenderer> b = a ? makeRenderer(rightSurface, rightHalf, error) : nullptr;
  if (!a || !b)
  {
    return nullptr;
  }
  a->SetViewport(0.0, 0.0, 0.5, 1.0);
  b->SetViewport(0.5, 0.0, 1.0, 1.0);
  if (shareCamera)
  {
    b->SetActiveCamera(a->GetActiveCamera());
  }
  vtkSmartPointer<vtkRenderWindow> window = makeWindow(left);
  window->AddRenderer(a);
  window->AddRenderer(b);
  window->Render();
  return window;
}
} // namespace

vtkSmartPointer<vtkRenderWindow> RenderScene(vtkPolyData* surface, const SceneOptions& options, std::string& error)
{
  vtkSmartPointer<vtkRenderer> renderer = makeRenderer(surface, options, error);
  if (!renderer)
  {
    return nullptr;
  }
  vtkSmartPointer<vtkRenderWindow> window = makeWindow(options);
  window->AddRenderer(renderer);
  window->Render();
  return window;
}

vtkSmartPointer<vtkRenderWindow> RenderSideBySide(
  vtkPolyData* surface, const SceneOptions& left, const SceneOptions& right, std::string& error)
{
  return renderTwoViews(surface, left, surface, right, true, error);
}

vtkSmartPointer<vtkRenderWindow> RenderPair(vtkPolyData* leftSurface, const SceneOptions& left,
  vtkPolyData* rightSurface, const SceneOptions& right, std::string& error)
{
  return renderTwoViews(leftSurface, left, rightSurface, right, false, error);
}

vtkSmartPointer<vtkRenderWindow> RenderCutScene(vtkPolyData* labelledSurface, vtkPolyData* stroke,
  vtkPolyData* constraints, vtkPolyData* cut, const std::string& caption, std::string& error)
{
  SceneOptions left;
  left.colorArray = "HarmonicField";
  left.legendTitle = "Harmonic\nfield";
  left.symmetricRange = 3.0; // the constraints are I - 1 and I + 1 around the cut
  left.isolineCount = 11;
  left.width = 1200;
  left.height = 600;
  left.zoom = 1.15;
  left.azimuth = 45.0;
  left.elevation = 10.0;
  left.caption = caption;
  left.overlays = { { stroke, { { 0.1, 0.7, 0.1 } }, 7.0 }, { constraints, { { 0.95, 0.85, 0.1 } }, 7.0 } };
  SceneOptions right = left;
  right.colorArray = "Segment";
  right.colorMap = SceneOptions::ColorMap::Categorical;
  right.isolineCount = 0;
  right.caption = "segments and the cut";
  right.overlays = { { cut, { { 0.9, 0.1, 0.1 } }, 4.0 } };
  return RenderSideBySide(labelledSurface, left, right, error);
}

bool WritePNG(vtkRenderWindow* window, const std::string& fileName, std::string& error)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(fileName.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    error = "cannot write " + fileName;
    return false;
  }
  return true;
}

} // namespace kerf
