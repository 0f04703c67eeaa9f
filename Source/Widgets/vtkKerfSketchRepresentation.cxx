// vtkKerfSketchRepresentation: the drawn strokes, discs and points, the gestures that make them on the view's depth
// buffer, and their display.
#include "vtkKerfSketchRepresentation.h"

#include "Error.h"
#include "Sketch/SurfaceSketch.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

vtkStandardNewMacro(vtkKerfSketchRepresentation);

namespace
{
using kerf::Vector3;
constexpr double Pi = 3.14159265358979323846;

// The drawn input: what Undo restores.
struct Drawn
{
  std::vector<Vector3> strokePoints;
  std::vector<int> strokeSizes;
  std::vector<int> strokeLabels;
  std::vector<std::array<double, 5>> discs;
  std::vector<std::vector<Vector3>> rims; // per disc, where it was dragged out (else empty)
  std::vector<Vector3> points;
};

using Stroke = kerf::DrawnStroke;

// The most entries a list takes, as a filter's panel lists (kerf::StrokePointList).
constexpr int MaximumEntries = 10000000;

// The strokes of flat lists (kerf::splitDrawnStrokes); lists that do not agree (while ParaView
// sets them one after another, or from a script) show all the points as one stroke: the filter
// says what is wrong, the display shows what there is.
std::vector<Stroke> strokesOf(const Drawn& drawn)
{
  try
  {
    return kerf::splitDrawnStrokes(drawn.strokePoints, drawn.strokeSizes,
      drawn.strokeLabels.size() == drawn.strokeSizes.size() ? drawn.strokeLabels : std::vector<int>());
  }
  catch (const kerf::Error&)
  {
    if (drawn.strokePoints.empty())
    {
      return {};
    }
    return { Stroke{ drawn.strokePoints, drawn.strokeLabels.empty() ? 0 : drawn.strokeLabels[0] } };
  }
}

void setStrokes(Drawn& drawn, const std::vector<Stroke>& strokes)
{
  drawn.strokePoints.clear();
  drawn.strokeSizes.clear();
  drawn.strokeLabels.clear();
  for (const Stroke& stroke : strokes)
  {
    drawn.strokePoints.insert(drawn.strokePoints.end(), stroke.points.begin(), stroke.points.end());
    drawn.strokeSizes.push_back(static_cast<int>(stroke.points.size()));
    drawn.strokeLabels.push_back(stroke.label);
  }
}

// What a setter did to a list.
enum class ListChange
{
  Refused,
  Same,
  Changed
};

template <typename T>
ListChange resizeList(std::vector<T>& list, int count, const T& fill)
{
  if (count < 0 || count > MaximumEntries)
  {
    return ListChange::Refused;
  }
  if (static_cast<std::size_t>(count) == list.size())
  {
    return ListChange::Same;
  }
  list.resize(static_cast<std::size_t>(count), fill);
  return ListChange::Changed;
}

template <typename T>
ListChange setEntry(std::vector<T>& list, int index, const T& value, const T& fill)
{
  if (index < 0 || index >= MaximumEntries)
  {
    return ListChange::Refused;
  }
  if (static_cast<std::size_t>(index) >= list.size())
  {
    list.resize(static_cast<std::size_t>(index) + 1, fill);
  }
  else if (list[static_cast<std::size_t>(index)] == value)
  {
    return ListChange::Same;
  }
  list[static_cast<std::size_t>(index)] = value;
  return ListChange::Changed;
}

// Three circles of `radius` about `centre` in the axis planes: a disc known only by its click and
// radius (typed, or set from a script), drawn without a view of the surface.
std::vector<std::vector<Vector3>> wireSphere(const Vector3& centre, double radius)
{
  std::vector<std::vector<Vector3>> circles(3);
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int i = 0; i < 48; ++i)
    {
      const double a = 2.0 * Pi * i / 48.0;
      Vector3 p = centre;
      p[(axis + 1) % 3] += radius * std::cos(a);
      p[(axis + 2) % 3] += radius * std::sin(a);
      circles[static_cast<std::size_t>(axis)].push_back(p);
    }
  }
  return circles;
}

// Geometry for one actor: points, lines and vertices with a colour per cell.
struct Sketch
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkUnsignedCharArray> lineColors;
  vtkNew<vtkUnsignedCharArray> vertexColors;

  Sketch()
  {
    this->lineColors->SetNumberOfComponents(3);
    this->vertexColors->SetNumberOfComponents(3);
  }
  static void push(vtkUnsignedCharArray* colors, const double rgb[3])
  {
    const unsigned char c[3] = { static_cast<unsigned char>(255.0 * rgb[0]), static_cast<unsigned char>(255.0 * rgb[1]),
      static_cast<unsigned char>(255.0 * rgb[2]) };
    colors->InsertNextTypedTuple(c);
  }
  void line(const std::vector<Vector3>& polyline, bool closed, const double rgb[3])
  {
    if (polyline.size() < 2)
    {
      if (polyline.size() == 1)
      {
        this->dot(polyline[0], rgb);
      }
      return;
    }
    const vtkIdType first = this->points->GetNumberOfPoints();
    for (const Vector3& p : polyline)
    {
      this->points->InsertNextPoint(p.data());
    }
    this->lines->InsertNextCell(static_cast<vtkIdType>(polyline.size() + (closed ? 1 : 0)));
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(polyline.size()); ++i)
    {
      this->lines->InsertCellPoint(first + i);
    }
    if (closed)
    {
      this->lines->InsertCellPoint(first);
    }
    push(this->lineColors, rgb);
  }
  void dot(const Vector3& p, const double rgb[3])
  {
    const vtkIdType id = this->points->InsertNextPoint(p.data());
    this->vertices->InsertNextCell(1, &id);
    push(this->vertexColors, rgb);
  }
  // Vertices come before lines in a vtkPolyData's cell order, and so do their colours.
  void fill(vtkPolyData* data)
  {
    data->Initialize();
    data->SetPoints(this->points);
    data->SetVerts(this->vertices);
    data->SetLines(this->lines);
    vtkNew<vtkUnsignedCharArray> colors;
    colors->SetName("Colors");
    colors->SetNumberOfComponents(3);
    colors->DeepCopy(this->vertexColors);
    for (vtkIdType i = 0; i < this->lineColors->GetNumberOfTuples(); ++i)
    {
      colors->InsertNextTuple(this->lineColors->GetTuple(i));
    }
    data->GetCellData()->SetScalars(colors);
  }
};

void pale(const double rgb[3], double out[3])
{
  for (int i = 0; i < 3; ++i)
  {
    out[i] = 0.45 * rgb[i] + 0.55;
  }
}

void setUpActor(vtkActor* actor, vtkPolyDataMapper* mapper, vtkPolyData* data, double lineWidth, double pointSize)
{
  mapper->SetInputData(data);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  // Lines drawn as tubes and points as spheres stand half their width off the surface, so the
  // surface does not hide them, without a depth offset: the next gesture reads the depth buffer
  // with them in it, and a stroke crossing an earlier one must not see a jump there.
  actor->SetMapper(mapper);
  actor->PickableOff();
  actor->GetProperty()->SetLineWidth(static_cast<float>(lineWidth));
  actor->GetProperty()->SetPointSize(static_cast<float>(pointSize));
  actor->GetProperty()->SetRenderLinesAsTubes(true);
  actor->GetProperty()->SetRenderPointsAsSpheres(true);
  actor->GetProperty()->SetAmbient(0.6);
  actor->GetProperty()->SetDiffuse(0.4);
}
} // namespace

struct vtkKerfSketchRepresentation::Internals
{
  Drawn drawn;
  std::vector<Drawn> undo;

  std::vector<Vector3> typedStroke, typedForeground, typedBackground, typedPoints;
  Vector3 typedDiscCenter = Vector3::Zero();
  double typedDiscRadius = 0.0;
  bool typedDisc = false;

  double diagonal = 0.0;

  // The gesture in progress.
  bool active = false;
  std::unique_ptr<kerf::DepthImage> image;
  std::unique_ptr<kerf::SurfaceStrokeTracer> tracer;
  double pressX = 0.0, pressY = 0.0;
  bool subtract = false;
  bool nothingShown = false;
  std::optional<Vector3> pressPoint;
  double discRadius = 0.0;
  std::vector<Vector3> discRim;

  // The lists the getters return.
  vtkNew<vtkDoubleArray> strokePointsOut, discsOut, pointsOut;
  vtkNew<vtkIntArray> strokeSizesOut, strokeLabelsOut;

  vtkNew<vtkPolyData> drawnData, typedData;
  vtkNew<vtkPolyDataMapper> drawnMapper, typedMapper;
  vtkNew<vtkActor> drawnActor, typedActor;
  vtkTimeStamp buildTime;

  void remember(int maximum)
  {
    this->undo.push_back(this->drawn);
    while (!this->undo.empty() && static_cast<int>(this->undo.size()) > maximum)
    {
      this->undo.erase(this->undo.begin());
    }
  }
};

vtkKerfSketchRepresentation::vtkKerfSketchRepresentation()
  : State(new Internals)
{
  setUpActor(this->State->drawnActor, this->State->drawnMapper, this->State->drawnData, 5.0, 12.0);
  setUpActor(this->State->typedActor, this->State->typedMapper, this->State->typedData, 3.0, 9.0);
  this->State->discsOut->SetNumberOfComponents(5);
  this->State->strokePointsOut->SetNumberOfComponents(3);
  this->State->pointsOut->SetNumberOfComponents(3);
}

vtkKerfSketchRepresentation::~vtkKerfSketchRepresentation() = default;

void vtkKerfSketchRepresentation::SetCurrentLabel(int label)
{
  const int allowed = std::clamp(label, this->AllowOverride ? -1 : 0, 99);
  if (allowed != this->CurrentLabel)
  {
    this->CurrentLabel = allowed;
    this->Modified();
  }
}

void vtkKerfSketchRepresentation::LabelColor(int label, bool labelled, double rgb[3])
{
  static const double palette[][3] = {
    { 0.15, 0.45, 1.0 }, // 0: background, blue
    { 1.0, 0.3, 0.1 },   // 1: foreground, red-orange
    { 0.2, 0.8, 0.25 },  // 2: green
    { 0.95, 0.8, 0.1 },  // 3: yellow
    { 0.7, 0.3, 0.9 },   // 4: purple
    { 0.1, 0.85, 0.85 }, // 5: cyan
    { 1.0, 0.5, 0.75 },  // 6: pink
    { 0.6, 0.4, 0.2 },   // 7: brown
    { 0.55, 0.75, 0.2 }, // 8: olive
    { 0.3, 0.3, 0.75 },  // 9: indigo
  };
  const double* c = !labelled ? palette[3] : label < 0 ? nullptr : palette[label % 10];
  const double white[3] = { 1.0, 1.0, 1.0 };
  if (!c)
  {
    c = white;
  }
  std::copy(c, c + 3, rgb);
}

// ---------------------------------------------------------------------------------------------
// The lists.

void vtkKerfSketchRepresentation::SetNumberOfStrokePoints(int count)
{
  this->ListChanged(
    static_cast<int>(resizeList(this->State->drawn.strokePoints, count, Vector3(Vector3::Zero()))), true);
}

void vtkKerfSketchRepresentation::SetStrokePoint(int index, double x, double y, double z)
{
  this->ListChanged(
    static_cast<int>(setEntry(this->State->drawn.strokePoints, index, Vector3(x, y, z), Vector3(Vector3::Zero()))),
    true);
}

vtkDoubleArray* vtkKerfSketchRepresentation::GetStrokePoints()
{
  vtkDoubleArray* out = this->State->strokePointsOut;
  out->SetNumberOfTuples(static_cast<vtkIdType>(this->State->drawn.strokePoints.size()));
  for (std::size_t i = 0; i < this->State->drawn.strokePoints.size(); ++i)
  {
    out->SetTypedTuple(static_cast<vtkIdType>(i), this->State->drawn.strokePoints[i].data());
  }
  return out;
}

void vtkKerfSketchRepresentation::SetNumberOfStrokeSizes(int count)
{
  this->ListChanged(static_cast<int>(resizeList(this->State->drawn.strokeSizes, count, 0)), true);
}

void vtkKerfSketchRepresentation::SetStrokeSize(int index, int size)
{
  this->ListChanged(static_cast<int>(setEntry(this->State->drawn.strokeSizes, index, size, 0)), true);
}

namespace
{
vtkIntArray* fillIntegers(vtkIntArray* out, const std::vector<int>& values)
{
  out->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    out->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  return out;
}
} // namespace

vtkIntArray* vtkKerfSketchRepresentation::GetStrokeSizes()
{
  return fillIntegers(this->State->strokeSizesOut, this->State->drawn.strokeSizes);
}

void vtkKerfSketchRepresentation::SetNumberOfStrokeLabels(int count)
{
  this->ListChanged(static_cast<int>(resizeList(this->State->drawn.strokeLabels, count, 0)), true);
}

void vtkKerfSketchRepresentation::SetStrokeLabel(int index, int label)
{
  this->ListChanged(static_cast<int>(setEntry(this->State->drawn.strokeLabels, index, label, 0)), true);
}

vtkIntArray* vtkKerfSketchRepresentation::GetStrokeLabels()
{
  return fillIntegers(this->State->strokeLabelsOut, this->State->drawn.strokeLabels);
}

int vtkKerfSketchRepresentation::GetNumberOfStrokes()
{
  return static_cast<int>(strokesOf(this->State->drawn).size());
}

void vtkKerfSketchRepresentation::ListChanged(int change, bool drawn)
{
  if (change == static_cast<int>(ListChange::Refused))
  {
    vtkErrorMacro(<< "a sketch list holds 0 to " << MaximumEntries << " entries: the value is refused");
    return;
  }
  if (change == static_cast<int>(ListChange::Changed))
  {
    this->Modified();
    // Set from outside (ParaView's Reset or Undo, a state file, a script): the earlier states
    // Undo would restore are no longer what the user drew.
    if (drawn && !this->State->active)
    {
      this->State->undo.clear();
    }
  }
}

int vtkKerfSketchRepresentation::GetNumberOfLabels()
{
  std::vector<int> labels;
  for (const Stroke& stroke : strokesOf(this->State->drawn))
  {
    if (stroke.label >= 0 && std::find(labels.begin(), labels.end(), stroke.label) == labels.end())
    {
      labels.push_back(stroke.label);
    }
  }
  return static_cast<int>(labels.size());
}

void vtkKerfSketchRepresentation::SetNumberOfDiscs(int count)
{
  this->ListChanged(static_cast<int>(resizeList(this->State->drawn.discs, count, std::array<double, 5>{})), true);
  resizeList(this->State->drawn.rims, count, std::vector<Vector3>());
}

void vtkKerfSketchRepresentation::SetDisc(int index, double x, double y, double z, double radius, double subtract)
{
  const std::array<double, 5> disc{ x, y, z, radius, subtract };
  if (index >= 0 && static_cast<std::size_t>(index) < this->State->drawn.discs.size() &&
    this->State->drawn.discs[static_cast<std::size_t>(index)] == disc)
  {
    return; // the same disc again (its rim stays)
  }
  this->ListChanged(static_cast<int>(setEntry(this->State->drawn.discs, index, disc, std::array<double, 5>{})), true);
  setEntry(this->State->drawn.rims, index, std::vector<Vector3>(), std::vector<Vector3>());
}

vtkDoubleArray* vtkKerfSketchRepresentation::GetDiscs()
{
  vtkDoubleArray* out = this->State->discsOut;
  out->SetNumberOfTuples(static_cast<vtkIdType>(this->State->drawn.discs.size()));
  for (std::size_t i = 0; i < this->State->drawn.discs.size(); ++i)
  {
    out->SetTypedTuple(static_cast<vtkIdType>(i), this->State->drawn.discs[i].data());
  }
  return out;
}

int vtkKerfSketchRepresentation::GetNumberOfDiscs()
{
  return static_cast<int>(this->State->drawn.discs.size());
}

void vtkKerfSketchRepresentation::SetNumberOfClickedPoints(int count)
{
  this->ListChanged(static_cast<int>(resizeList(this->State->drawn.points, count, Vector3(Vector3::Zero()))), true);
}

void vtkKerfSketchRepresentation::SetClickedPoint(int index, double x, double y, double z)
{
  this->ListChanged(
    static_cast<int>(setEntry(this->State->drawn.points, index, Vector3(x, y, z), Vector3(Vector3::Zero()))), true);
}

vtkDoubleArray* vtkKerfSketchRepresentation::GetClickedPoints()
{
  vtkDoubleArray* out = this->State->pointsOut;
  out->SetNumberOfTuples(static_cast<vtkIdType>(this->State->drawn.points.size()));
  for (std::size_t i = 0; i < this->State->drawn.points.size(); ++i)
  {
    out->SetTypedTuple(static_cast<vtkIdType>(i), this->State->drawn.points[i].data());
  }
  return out;
}

int vtkKerfSketchRepresentation::GetNumberOfClickedPoints()
{
  return static_cast<int>(this->State->drawn.points.size());
}

void vtkKerfSketchRepresentation::SetNumberOfTypedStrokePoints(int count)
{
  this->ListChanged(static_cast<int>(resizeList(this->State->typedStroke, count, Vector3(Vector3::Zero()))), false);
}

void vtkKerfSketchRepresentation::SetTypedStrokePoint(int index, double x, double y, double z)
{
  this->ListChanged(
    static_cast<int>(setEntry(this->State->typedStroke, index, Vector3(x, y, z), Vector3(Vector3::Zero()))), false);
}

void vtkKerfSketchRepresentation::SetNumberOfTypedForegroundPoints(int count)
{
  this->ListChanged(static_cast<int>(resizeList(this->State->typedForeground, count, Vector3(Vector3::Zero()))), false);
}

void vtkKerfSketchRepresentation::SetTypedForegroundPoint(int index, double x, double y, double z)
{
  this->ListChanged(
    static_cast<int>(setEntry(this->State->typedForeground, index, Vector3(x, y, z), Vector3(Vector3::Zero()))), false);
}

void vtkKerfSketchRepresentation::SetNumberOfTypedBackgroundPoints(int count)
{
  this->ListChanged(static_cast<int>(resizeList(this->State->typedBackground, count, Vector3(Vector3::Zero()))), false);
}

void vtkKerfSketchRepresentation::SetTypedBackgroundPoint(int index, double x, double y, double z)
{
  this->ListChanged(
    static_cast<int>(setEntry(this->State->typedBackground, index, Vector3(x, y, z), Vector3(Vector3::Zero()))), false);
}

void vtkKerfSketchRepresentation::SetTypedDiscCenter(double x, double y, double z)
{
  this->State->typedDiscCenter = Vector3(x, y, z);
  this->State->typedDisc = true;
  this->Modified();
}

void vtkKerfSketchRepresentation::SetTypedDiscRadius(double radius)
{
  this->State->typedDiscRadius = radius;
  this->Modified();
}

void vtkKerfSketchRepresentation::SetNumberOfTypedPoints(int count)
{
  this->ListChanged(static_cast<int>(resizeList(this->State->typedPoints, count, Vector3(Vector3::Zero()))), false);
}

void vtkKerfSketchRepresentation::SetTypedPoint(int index, double x, double y, double z)
{
  this->ListChanged(
    static_cast<int>(setEntry(this->State->typedPoints, index, Vector3(x, y, z), Vector3(Vector3::Zero()))), false);
}

// ---------------------------------------------------------------------------------------------
// Gestures.

namespace
{
// The map from display coordinates and depth to space that vtkRenderer::DisplayToWorld applies, for
// the renderer's viewport and camera now: the display's pixels to the viewport's [-1, 1] range,
// then the inverse of the camera's composite projection (depths 0 to 1). Taken once per gesture:
// the camera does not move while drawing.
Eigen::Matrix4d displayToWorld(vtkRenderer* renderer)
{
  const int* size = renderer->GetRenderWindow()->GetSize();
  const double* viewport = renderer->GetViewport();
  const double width = (viewport[2] - viewport[0]) * size[0];
  const double height = (viewport[3] - viewport[1]) * size[1];
  Eigen::Matrix4d toView = Eigen::Matrix4d::Identity();
  toView(0, 0) = 2.0 / width;
  toView(0, 3) = -2.0 * viewport[0] * size[0] / width - 1.0;
  toView(1, 1) = 2.0 / height;
  toView(1, 3) = -2.0 * viewport[1] * size[1] / height - 1.0;
  vtkMatrix4x4* projection =
    renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), 0.0, 1.0);
  Eigen::Matrix4d worldToView;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      worldToView(i, j) = projection->GetElement(i, j);
    }
  }
  return worldToView.inverse() * toView;
}

// The display position of a world point, and its depth.
Vector3 toDisplay(vtkRenderer* renderer, const Vector3& p)
{
  renderer->SetWorldPoint(p.x(), p.y(), p.z(), 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  return Vector3(d[0], d[1], d[2]);
}

double segmentDistance2D(double x, double y, const Vector3& a, const Vector3& b)
{
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double length = dx * dx + dy * dy;
  const double t = length > 0.0 ? std::clamp(((x - a.x()) * dx + (y - a.y()) * dy) / length, 0.0, 1.0) : 0.0;
  return std::hypot(x - a.x() - t * dx, y - a.y() - t * dy);
}

// Whether a point shows in the view: in front of the camera and not behind the visible surface
// (farther along the view than the surface under it by more than a few pixels, which its tube
// or dot does not reach).
bool visible(vtkRenderer* renderer, const kerf::DepthImage& image, const Vector3& p, const Vector3& display)
{
  if (!(display.z() >= 0.0 && display.z() <= 1.0))
  {
    return false;
  }
  const std::optional<double> depth = image.depth(display.x(), display.y());
  if (!depth)
  {
    return true; // the background or off the image: nothing in front of it
  }
  const Vector3 surface = *image.surfacePoint(display.x(), display.y());
  double direction[3];
  renderer->GetActiveCamera()->GetDirectionOfProjection(direction);
  const double beyond = (p - surface).dot(Vector3(direction[0], direction[1], direction[2]));
  return beyond <= 8.0 * image.pixelSize(display.x(), display.y(), *depth);
}

// The index of the visible polyline (or point) nearest to display position (x, y) within
// `tolerance` pixels, or -1.
int nearestOnScreen(vtkRenderer* renderer, const kerf::DepthImage& image,
  const std::vector<std::vector<Vector3>>& polylines, double x, double y, double tolerance)
{
  int nearest = -1;
  double best = tolerance;
  for (std::size_t i = 0; i < polylines.size(); ++i)
  {
    std::vector<Vector3> screen;
    std::vector<char> shown;
    for (const Vector3& p : polylines[i])
    {
      screen.push_back(toDisplay(renderer, p));
      shown.push_back(visible(renderer, image, p, screen.back()));
    }
    for (std::size_t k = 0; k < screen.size(); ++k)
    {
      const std::size_t next = k + 1 < screen.size() ? k + 1 : k;
      if (!shown[k] || !shown[next])
      {
        continue;
      }
      const double d = segmentDistance2D(x, y, screen[k], screen[next]);
      if (d <= best)
      {
        best = d;
        nearest = static_cast<int>(i);
      }
    }
  }
  return nearest;
}
} // namespace

bool vtkKerfSketchRepresentation::IsGestureActive() const
{
  return this->State->active;
}

void vtkKerfSketchRepresentation::StartGesture(double x, double y, bool subtract)
{
  Internals& s = *this->State;
  this->Message.clear();
  s.active = false;
  s.image.reset();
  s.tracer.reset();
  s.discRim.clear();
  s.discRadius = 0.0;
  vtkRenderer* renderer = this->Renderer;
  vtkRenderWindow* window = renderer ? renderer->GetRenderWindow() : nullptr;
  if (!window)
  {
    this->Message = "There is no view to draw in.";
    return;
  }
  const int* size = window->GetActualSize();
  if (size[0] < 1 || size[1] < 1)
  {
    this->Message = "The view has no size to draw in.";
    return;
  }
  vtkNew<vtkFloatArray> depth;
  window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth);
  std::vector<float> values(static_cast<std::size_t>(size[0]) * static_cast<std::size_t>(size[1]), 1.0f);
  if (depth->GetNumberOfTuples() == static_cast<vtkIdType>(values.size()))
  {
    std::copy(depth->GetPointer(0), depth->GetPointer(0) + values.size(), values.begin());
  }
  s.nothingShown = std::none_of(values.begin(), values.end(), [](float d) { return d < 1.0f; });
  s.image = std::make_unique<kerf::DepthImage>(
    size[0], size[1], std::move(values), kerf::DepthImage::projective(displayToWorld(renderer)));
  s.active = true;
  s.pressX = x;
  s.pressY = y;
  s.subtract = subtract;
  s.pressPoint = s.image->surfacePoint(x, y);
  s.tracer = std::make_unique<kerf::SurfaceStrokeTracer>(*s.image, x, y);
  this->Modified();
}

void vtkKerfSketchRepresentation::ContinueGesture(double x, double y)
{
  Internals& s = *this->State;
  if (!s.active)
  {
    return;
  }
  s.tracer->moveTo(x, y);
  if (this->Mode == DISCS && s.pressPoint)
  {
    s.discRadius = kerf::dragRadius(*s.image, s.pressX, s.pressY, x, y);
    s.discRim = kerf::discRim(*s.image, s.pressX, s.pressY, s.discRadius);
  }
  this->Modified();
}

int vtkKerfSketchRepresentation::EndGesture(double x, double y)
{
  Internals& s = *this->State;
  if (!s.active)
  {
    return GESTURE_NOTHING;
  }
  this->ContinueGesture(x, y);
  s.active = false;
  this->Modified();
  const bool click = s.tracer->reach() < this->ClickTolerance;
  const std::string nothing = s.nothingShown
    ? "Nothing is shown to draw on: show the surface in this view (apply its source first), then draw on it."
    : "";
  int outcome = GESTURE_NOTHING;
  if (this->Mode == STROKES)
  {
    std::vector<Stroke> strokes = strokesOf(s.drawn);
    if (click)
    {
      std::vector<std::vector<Vector3>> polylines;
      for (const Stroke& stroke : strokes)
      {
        polylines.push_back(stroke.points);
      }
      const int hit = nearestOnScreen(this->Renderer, *s.image, polylines, s.pressX, s.pressY, this->PickTolerance);
      if (hit >= 0)
      {
        s.remember(this->MaximumUndo);
        strokes.erase(strokes.begin() + hit);
        setStrokes(s.drawn, strokes);
        outcome = GESTURE_CHANGED;
      }
      else if (this->Labelled && s.pressPoint)
      {
        s.remember(this->MaximumUndo);
        strokes.push_back({ { *s.pressPoint }, this->CurrentLabel });
        setStrokes(s.drawn, strokes);
        outcome = GESTURE_CHANGED;
      }
      else
      {
        this->Message = !nothing.empty() ? nothing
          : s.pressPoint ? "To draw a stroke, hold Ctrl and drag across the surface; a click on a stroke erases it."
                         : "The click missed the surface and every stroke.";
      }
    }
    else
    {
      std::vector<Stroke> added;
      for (const std::vector<Vector3>& piece : s.tracer->pieces())
      {
        if (piece.size() < 2)
        {
          continue;
        }
        const Vector3 screen = toDisplay(this->Renderer, piece.front());
        const double pixel = s.image->pixelSize(screen.x(), screen.y(), screen.z());
        const double tolerance = std::max(0.5 * pixel, this->SimplifyTolerance * s.diagonal);
        added.push_back({ kerf::simplifyPolyline(piece, tolerance), this->Labelled ? this->CurrentLabel : 0 });
      }
      if (added.empty())
      {
        this->Message =
          !nothing.empty() ? nothing : "The stroke never touched the surface: start and draw it on the surface.";
      }
      else
      {
        s.remember(this->MaximumUndo);
        strokes.insert(strokes.end(), added.begin(), added.end());
        setStrokes(s.drawn, strokes);
        outcome = GESTURE_CHANGED;
      }
    }
  }
  else if (this->Mode == DISCS)
  {
    if (!s.pressPoint)
    {
      this->Message = !nothing.empty() ? nothing : "Start the disc on the surface: press on it and drag outward.";
    }
    else if (click || !(s.discRadius > 0.0))
    {
      std::vector<std::vector<Vector3>> centres;
      for (const std::array<double, 5>& disc : s.drawn.discs)
      {
        centres.push_back({ Vector3(disc[0], disc[1], disc[2]) });
      }
      const int hit = nearestOnScreen(this->Renderer, *s.image, centres, s.pressX, s.pressY, this->PickTolerance);
      if (hit >= 0)
      {
        s.remember(this->MaximumUndo);
        s.drawn.discs.erase(s.drawn.discs.begin() + hit);
        s.drawn.rims.erase(s.drawn.rims.begin() + hit);
        outcome = GESTURE_CHANGED;
      }
      else
      {
        this->Message = "The disc has no radius: press on the surface and drag outward to set it (a click on a "
                        "disc's centre erases it).";
      }
    }
    else
    {
      s.remember(this->MaximumUndo);
      s.drawn.discs.push_back(
        { s.pressPoint->x(), s.pressPoint->y(), s.pressPoint->z(), s.discRadius, s.subtract ? 1.0 : 0.0 });
      s.drawn.rims.push_back(s.discRim);
      outcome = GESTURE_CHANGED;
    }
  }
  else
  {
    std::vector<std::vector<Vector3>> points;
    for (const Vector3& p : s.drawn.points)
    {
      points.push_back({ p });
    }
    const int hit = nearestOnScreen(this->Renderer, *s.image, points, s.pressX, s.pressY, this->PickTolerance);
    if (!click)
    {
      this->Message = "Points are clicked: press and release Ctrl+click without dragging.";
    }
    else if (hit >= 0 && this->MaximumPoints != 1)
    {
      s.remember(this->MaximumUndo);
      s.drawn.points.erase(s.drawn.points.begin() + hit);
      outcome = GESTURE_CHANGED;
    }
    else if (!s.pressPoint)
    {
      this->Message = !nothing.empty() ? nothing : "The click missed the surface: click on it.";
    }
    else if (this->MaximumPoints > 1 && static_cast<int>(s.drawn.points.size()) >= this->MaximumPoints)
    {
      this->Message =
        "There are already " + std::to_string(this->MaximumPoints) + " points: click on one to erase it first.";
    }
    else
    {
      s.remember(this->MaximumUndo);
      if (this->MaximumPoints == 1)
      {
        s.drawn.points.clear();
      }
      s.drawn.points.push_back(*s.pressPoint);
      outcome = GESTURE_CHANGED;
    }
  }
  s.tracer.reset();
  s.image.reset(); // a view-sized buffer: kept only while drawing
  s.discRim.clear();
  s.discRadius = 0.0;
  return outcome;
}

namespace
{
std::vector<Vector3> pointsOf(vtkPoints* points)
{
  std::vector<Vector3> out(static_cast<std::size_t>(points ? points->GetNumberOfPoints() : 0));
  for (std::size_t i = 0; i < out.size(); ++i)
  {
    points->GetPoint(static_cast<vtkIdType>(i), out[i].data());
  }
  return out;
}
} // namespace

bool vtkKerfSketchRepresentation::AddClickStrokes(vtkPoints* points)
{
  const std::vector<Vector3> clicks = pointsOf(points);
  if (clicks.empty())
  {
    return false;
  }
  this->State->remember(this->MaximumUndo);
  std::vector<Stroke> strokes = strokesOf(this->State->drawn);
  for (const Vector3& p : clicks)
  {
    strokes.push_back({ { p }, this->CurrentLabel });
  }
  setStrokes(this->State->drawn, strokes);
  this->Modified();
  return true;
}

bool vtkKerfSketchRepresentation::AddDiscAround(vtkPoints* points)
{
  const std::vector<Vector3> around = pointsOf(points);
  if (around.empty())
  {
    return false;
  }
  Vector3 centroid = Vector3::Zero();
  for (const Vector3& p : around)
  {
    centroid += p / static_cast<double>(around.size());
  }
  const Vector3 centre =
    *std::min_element(around.begin(), around.end(), [&centroid](const Vector3& a, const Vector3& b) {
      return (a - centroid).squaredNorm() < (b - centroid).squaredNorm();
    });
  double radius = 0.0;
  for (const Vector3& p : around)
  {
    radius = std::max(radius, (p - centre).norm());
  }
  if (!(radius > 0.0))
  {
    this->Message = "The selection is a single cell: select more, or drag a disc out from it.";
    return false;
  }
  this->State->remember(this->MaximumUndo);
  this->State->drawn.discs.push_back({ centre.x(), centre.y(), centre.z(), radius, 0.0 });
  this->State->drawn.rims.emplace_back();
  this->Modified();
  return true;
}

void vtkKerfSketchRepresentation::CancelGesture()
{
  Internals& s = *this->State;
  s.active = false;
  s.tracer.reset();
  s.image.reset();
  s.discRim.clear();
  s.discRadius = 0.0;
  this->Modified();
}

bool vtkKerfSketchRepresentation::Undo()
{
  Internals& s = *this->State;
  if (s.undo.empty())
  {
    return false;
  }
  s.drawn = s.undo.back();
  s.undo.pop_back();
  this->Modified();
  return true;
}

bool vtkKerfSketchRepresentation::CanUndo() const
{
  return !this->State->undo.empty();
}

bool vtkKerfSketchRepresentation::Clear()
{
  Internals& s = *this->State;
  if (s.drawn.strokePoints.empty() && s.drawn.strokeSizes.empty() && s.drawn.strokeLabels.empty() &&
    s.drawn.discs.empty() && s.drawn.points.empty())
  {
    return false;
  }
  s.remember(this->MaximumUndo);
  s.drawn = Drawn();
  this->Modified();
  return true;
}

// ---------------------------------------------------------------------------------------------
// Display.

void vtkKerfSketchRepresentation::PlaceWidget(double bounds[6])
{
  if (!bounds)
  {
    return;
  }
  this->State->diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) + (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  if (!std::isfinite(this->State->diagonal))
  {
    this->State->diagonal = 0.0;
  }
  this->Modified();
}

void vtkKerfSketchRepresentation::BuildRepresentation()
{
  Internals& s = *this->State;
  if (s.buildTime >= this->GetMTime())
  {
    return;
  }
  Sketch drawn, typed;
  double rgb[3], paleRgb[3];
  const std::vector<Stroke> strokes = strokesOf(s.drawn);
  if (this->Mode == STROKES)
  {
    for (const Stroke& stroke : strokes)
    {
      LabelColor(stroke.label, this->Labelled, rgb);
      drawn.line(stroke.points, false, rgb);
    }
    if (s.active && s.tracer)
    {
      LabelColor(this->CurrentLabel, this->Labelled, rgb);
      for (const std::vector<Vector3>& piece : s.tracer->pieces())
      {
        drawn.line(piece, false, rgb);
      }
    }
    auto hasLabel = [&strokes](int label) {
      return std::any_of(
        strokes.begin(), strokes.end(), [label](const Stroke& stroke) { return stroke.label == label; });
    };
    if (!this->Labelled && strokes.empty())
    {
      LabelColor(0, false, rgb);
      pale(rgb, paleRgb);
      typed.line(s.typedStroke, false, paleRgb);
    }
    for (const auto& [label, points] : { std::make_pair(1, &s.typedForeground), std::make_pair(0, &s.typedBackground) })
    {
      if (this->Labelled && !hasLabel(label))
      {
        LabelColor(label, true, rgb);
        pale(rgb, paleRgb);
        for (const Vector3& p : *points)
        {
          typed.dot(p, paleRgb);
        }
        typed.line(*points, false, paleRgb);
      }
    }
  }
  else if (this->Mode == DISCS)
  {
    const double add[3] = { 1.0, 0.45, 0.1 };
    const double cut[3] = { 0.15, 0.45, 1.0 };
    for (std::size_t i = 0; i < s.drawn.discs.size(); ++i)
    {
      const std::array<double, 5>& disc = s.drawn.discs[i];
      const double* colour = disc[4] != 0.0 ? cut : add;
      const Vector3 centre(disc[0], disc[1], disc[2]);
      drawn.dot(centre, colour);
      if (i < s.drawn.rims.size() && !s.drawn.rims[i].empty())
      {
        drawn.line(s.drawn.rims[i], true, colour);
      }
      else
      {
        for (const std::vector<Vector3>& circle : wireSphere(centre, disc[3]))
        {
          drawn.line(circle, true, colour);
        }
      }
    }
    if (s.active && s.pressPoint)
    {
      const double* colour = s.subtract ? cut : add;
      drawn.dot(*s.pressPoint, colour);
      drawn.line(s.discRim, true, colour);
    }
    if (s.drawn.discs.empty() && s.typedDisc)
    {
      pale(add, paleRgb);
      typed.dot(s.typedDiscCenter, paleRgb);
      if (s.typedDiscRadius > 0.0)
      {
        for (const std::vector<Vector3>& circle : wireSphere(s.typedDiscCenter, s.typedDiscRadius))
        {
          typed.line(circle, true, paleRgb);
        }
      }
    }
  }
  else
  {
    const double colour[3] = { 1.0, 0.85, 0.1 };
    // Dots only: the filter's own output shows the way between them.
    for (const Vector3& p : s.drawn.points)
    {
      drawn.dot(p, colour);
    }
    if (s.drawn.points.empty())
    {
      pale(colour, paleRgb);
      for (const Vector3& p : s.typedPoints)
      {
        typed.dot(p, paleRgb);
      }
    }
  }
  drawn.fill(s.drawnData);
  typed.fill(s.typedData);
  s.buildTime.Modified();
}

void vtkKerfSketchRepresentation::GetActors(vtkPropCollection* props)
{
  props->AddItem(this->State->drawnActor);
  props->AddItem(this->State->typedActor);
}

void vtkKerfSketchRepresentation::ReleaseGraphicsResources(vtkWindow* window)
{
  this->State->drawnActor->ReleaseGraphicsResources(window);
  this->State->typedActor->ReleaseGraphicsResources(window);
}

int vtkKerfSketchRepresentation::RenderOpaqueGeometry(vtkViewport* viewport)
{
  if (!this->GetVisibility())
  {
    return 0;
  }
  this->BuildRepresentation();
  int count = 0;
  for (vtkActor* actor : { this->State->drawnActor.GetPointer(), this->State->typedActor.GetPointer() })
  {
    vtkPolyData* data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
    if (data && data->GetNumberOfPoints() > 0)
    {
      count += actor->RenderOpaqueGeometry(viewport);
    }
  }
  return count;
}

int vtkKerfSketchRepresentation::RenderTranslucentPolygonalGeometry(vtkViewport*)
{
  return 0;
}

vtkTypeBool vtkKerfSketchRepresentation::HasTranslucentPolygonalGeometry()
{
  return 0;
}

void vtkKerfSketchRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "Labelled: " << this->Labelled << "\n";
  os << indent << "AllowOverride: " << this->AllowOverride << "\n";
  os << indent << "CurrentLabel: " << this->CurrentLabel << "\n";
  os << indent << "MaximumPoints: " << this->MaximumPoints << "\n";
  os << indent << "SimplifyTolerance: " << this->SimplifyTolerance << "\n";
  os << indent << "ClickTolerance: " << this->ClickTolerance << "\n";
  os << indent << "PickTolerance: " << this->PickTolerance << "\n";
  os << indent << "MaximumUndo: " << this->MaximumUndo << "\n";
  os << indent << "Strokes: " << this->GetNumberOfStrokes() << "\n";
  os << indent << "Discs: " << this->State->drawn.discs.size() << "\n";
  os << indent << "ClickedPoints: " << this->State->drawn.points.size() << "\n";
}
