// Kerf's sketch widget driven by mouse events in a VTK render window: strokes on a sphere stay on it and split off it,
// clicks erase, undo restores, discs measure the surface, points; a drawn stroke cuts the sphere in two; the picture.
#include "KerfTestUtilities.h"
#include "vtkKerfSketchRepresentation.h"
#include "vtkKerfSketchWidget.h"
#include "vtkStrokeCut.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRegressionTestImage.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <cmath>
#include <iostream>
#include <string>

namespace
{
constexpr double Radius = 0.5;

struct Mouse
{
  vtkRenderWindowInteractor* interactor;

  void event(unsigned long id, int x, int y, bool control, bool shift)
  {
    this->interactor->SetEventInformation(x, y, control ? 1 : 0, shift ? 1 : 0);
    this->interactor->InvokeEvent(id);
  }
  // A drag from (x0, y0) to (x1, y1) in `steps` moves, holding Ctrl unless told otherwise.
  void drag(int x0, int y0, int x1, int y1, int steps = 10, bool control = true, bool shift = false)
  {
    this->event(vtkCommand::LeftButtonPressEvent, x0, y0, control, shift);
    for (int i = 1; i <= steps; ++i)
    {
      this->event(vtkCommand::MouseMoveEvent, x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps, control, shift);
    }
    this->event(vtkCommand::LeftButtonReleaseEvent, x1, y1, control, shift);
  }
  void click(int x, int y) { this->drag(x, y, x, y, 0); }
};

// The largest distance of the representation's stroke points from the sphere.
double farthestFromSphere(vtkDoubleArray* points)
{
  double farthest = 0.0;
  for (vtkIdType i = 0; i < points->GetNumberOfTuples(); ++i)
  {
    const double* p = points->GetTuple3(i);
    farthest = std::max(farthest, std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - Radius));
  }
  return farthest;
}
} // namespace

int TestSketchWidgetImage(int argc, char* argv[])
{
  bool ok = true;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(Radius);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(96);
  sphere->Update();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.32, 0.34, 0.43);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  renderer->ResetCamera();
  window->Render();

  vtkNew<vtkKerfSketchWidget> widget;
  widget->SetInteractor(interactor);
  widget->CreateDefaultRepresentation();
  vtkKerfSketchRepresentation* sketch = widget->GetSketchRepresentation();
  double bounds[6];
  sphere->GetOutput()->GetBounds(bounds);
  sketch->PlaceWidget(bounds);
  widget->SetEnabled(1);
  window->Render();
  std::string said;
  vtkNew<vtkCallbackCommand> listen;
  listen->SetClientData(&said);
  listen->SetCallback([](vtkObject*, unsigned long, void* client, void* message) {
    *static_cast<std::string*>(client) = static_cast<const char*>(message);
  });
  widget->AddObserver(vtkKerfSketchWidget::MessageEvent, listen);
  Mouse mouse{ interactor };

  // A drag across the sphere from the background on the left to the background on the right:
  // one stroke, on the sphere, simplified (a great half-circle needs a few tens of points).
  mouse.drag(20, 150, 280, 150, 4);
  ok &= KERF_CHECK(widget->GetLastChanged());
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 1);
  vtkDoubleArray* points = sketch->GetStrokePoints();
  std::cout << "stroke: " << points->GetNumberOfTuples() << " points, farthest " << farthestFromSphere(points)
            << " from the sphere" << std::endl;
  ok &= KERF_CHECK(points->GetNumberOfTuples() >= 5 && points->GetNumberOfTuples() <= 80);
  ok &= KERF_CHECK(farthestFromSphere(points) < 0.01 * Radius);
  ok &= KERF_CHECK(points->GetTuple3(0)[0] < -0.45 && points->GetTuple3(points->GetNumberOfTuples() - 1)[0] > 0.45);
  ok &= KERF_CHECK(sketch->GetStrokeSizes()->GetValue(0) == points->GetNumberOfTuples());

  // Without Ctrl the left button is the camera's: no stroke, the camera turned (and put back).
  vtkNew<vtkCamera> kept;
  kept->DeepCopy(renderer->GetActiveCamera());
  mouse.drag(150, 60, 150, 240, 4, false);
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 1);
  double up[3];
  renderer->GetActiveCamera()->GetViewUp(up);
  ok &= KERF_CHECK(std::abs(up[1] - kept->GetViewUp()[1]) > 1e-3 ||
    std::abs(renderer->GetActiveCamera()->GetPosition()[2] - kept->GetPosition()[2]) > 1e-3);
  renderer->GetActiveCamera()->DeepCopy(kept);
  renderer->ResetCameraClippingRange();
  window->Render();

  // Off the surface: nothing, and the widget says why.
  mouse.drag(5, 5, 60, 20);
  ok &= KERF_CHECK(!widget->GetLastChanged() && sketch->GetNumberOfStrokes() == 1);
  ok &= KERF_CHECK(said.find("never touched the surface") != std::string::npos);

  // A vertical stroke from above the sphere to below it, then a click on the first stroke erases
  // it, Undo brings it back, Clear forgets both and Undo restores them.
  said.clear();
  mouse.drag(150, 290, 150, 10, 2);
  std::cout << "vertical: " << sketch->GetNumberOfStrokes() << " strokes, said '" << said << "'" << std::endl;
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 2);
  mouse.click(80, 150);
  ok &= KERF_CHECK(widget->GetLastChanged() && sketch->GetNumberOfStrokes() == 1);
  widget->Undo();
  ok &= KERF_CHECK(widget->GetLastChanged() && sketch->GetNumberOfStrokes() == 2);
  widget->Clear();
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 0);
  widget->Undo();
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 2);
  widget->Undo(); // the vertical stroke
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 1);

  // A stroke on the far side of the sphere does not show: a click over it erases nothing (the
  // front one is out of reach), and adds nothing either, unlabelled.
  sketch->SetNumberOfStrokePoints(3);
  sketch->SetStrokePoint(0, -0.2, 0.3, -0.4);
  sketch->SetStrokePoint(1, 0.0, 0.3, -0.4);
  sketch->SetStrokePoint(2, 0.2, 0.3, -0.4);
  sketch->SetNumberOfStrokeSizes(1);
  sketch->SetStrokeSize(0, 3);
  sketch->SetNumberOfStrokeLabels(0);
  window->Render();
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 1);
  int farX = 0, farY = 0;
  {
    renderer->SetWorldPoint(0.0, 0.3, -0.4, 1.0);
    renderer->WorldToDisplay();
    farX = static_cast<int>(std::lround(renderer->GetDisplayPoint()[0]));
    farY = static_cast<int>(std::lround(renderer->GetDisplayPoint()[1]));
  }
  mouse.click(farX, farY);
  ok &= KERF_CHECK(!widget->GetLastChanged() && sketch->GetNumberOfStrokes() == 1);
  // Set from outside, the strokes leave nothing to undo.
  ok &= KERF_CHECK(!sketch->CanUndo());
  // Put the first stroke back for what follows.
  mouse.drag(20, 150, 280, 150, 4);
  widget->Undo();
  sketch->SetNumberOfStrokePoints(0);
  sketch->SetNumberOfStrokeSizes(0);
  mouse.drag(20, 150, 280, 150, 4);
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 1);

  // The drawn stroke cuts the sphere: the harmonic cut along it halves the sphere (the stroke
  // runs along its equator y = 0 as seen from +z).
  vtkNew<vtkStrokeCut> cut;
  cut->SetInputConnection(sphere->GetOutputPort());
  points = sketch->GetStrokePoints();
  cut->SetNumberOfDrawnStrokePoints(static_cast<int>(points->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < points->GetNumberOfTuples(); ++i)
  {
    const double* p = points->GetTuple3(i);
    cut->SetDrawnStrokePoint(static_cast<int>(i), p[0], p[1], p[2]);
  }
  ok &= KERF_CHECK(kerf::test::UpdateAndCaptureError(cut).empty());
  vtkIntArray* sizes = vtkIntArray::SafeDownCast(cut->GetOutput()->GetFieldData()->GetArray("SegmentSizes"));
  ok &= KERF_CHECK(sizes && sizes->GetNumberOfTuples() == 2);
  if (sizes && sizes->GetNumberOfTuples() == 2)
  {
    const double half = 0.5 * cut->GetOutput()->GetNumberOfCells();
    std::cout << "cut: " << sizes->GetValue(0) << " and " << sizes->GetValue(1) << " faces" << std::endl;
    ok &= KERF_CHECK(std::abs(sizes->GetValue(0) - half) < 0.05 * half);
  }

  // Labels: the next stroke gets the current label.
  sketch->SetLabelled(true);
  widget->SetCurrentLabel(0);
  mouse.drag(100, 200, 200, 200, 3);
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 2 && sketch->GetStrokeLabels()->GetValue(1) == 0);
  // Labelled, a click on the surface away from the strokes is a one-point stroke (a seed).
  mouse.click(150, 110);
  ok &= KERF_CHECK(sketch->GetNumberOfStrokes() == 3 && sketch->GetStrokeSizes()->GetValue(2) == 1);

  // Discs: pressed at the sphere's centre pixel (its pole (0, 0, 0.5)) and dragged 60 pixels out;
  // the radius is the length over the surface, the arc 0.5 acos(z / 0.5) to the point under the
  // release.
  // (A filter's widget has one mode; the strokes are put aside first, or the walk would climb
  // their tubes.)
  widget->Clear();
  sketch->SetMode(vtkKerfSketchRepresentation::DISCS);
  window->Render();
  mouse.drag(150, 150, 150, 210, 6);
  ok &= KERF_CHECK(sketch->GetNumberOfDiscs() == 1);
  renderer->SetDisplayPoint(150, 210, 0.0);
  double released[3] = { 0.0, 0.0, 0.0 };
  {
    // The sphere's point under the release: the ray from the eye through the pixel.
    double near[4], far[4];
    renderer->SetDisplayPoint(150, 210, 0.0);
    renderer->DisplayToWorld();
    renderer->GetWorldPoint(near);
    renderer->SetDisplayPoint(150, 210, 1.0);
    renderer->DisplayToWorld();
    renderer->GetWorldPoint(far);
    double o[3], d[3];
    for (int k = 0; k < 3; ++k)
    {
      o[k] = near[k] / near[3];
      d[k] = far[k] / far[3] - o[k];
    }
    const double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const double b = 2.0 * (o[0] * d[0] + o[1] * d[1] + o[2] * d[2]);
    const double c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - Radius * Radius;
    const double t = (-b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
    for (int k = 0; k < 3; ++k)
    {
      released[k] = o[k] + t * d[k];
    }
  }
  const double arc = Radius * std::acos(std::min(1.0, released[2] / Radius));
  const double* disc = sketch->GetDiscs()->GetTuple(0);
  std::cout << "disc: radius " << disc[3] << ", the arc to the release " << arc << std::endl;
  ok &= KERF_CHECK(std::abs(disc[3] - arc) < 0.03 * arc);
  ok &= KERF_CHECK(std::abs(disc[2] - Radius) < 0.01 && disc[4] == 0.0);
  // With Shift as well, the disc subtracts; pressed and released at one place, there is none.
  mouse.drag(150, 150, 190, 150, 4, true, true);
  ok &= KERF_CHECK(sketch->GetNumberOfDiscs() == 2 && sketch->GetDiscs()->GetTuple(1)[4] == 1.0);
  mouse.click(200, 100);
  ok &= KERF_CHECK(!widget->GetLastChanged() && said.find("no radius") != std::string::npos);

  // Points: one at most moves with each click.
  sketch->SetMode(vtkKerfSketchRepresentation::POINTS);
  sketch->SetMaximumPoints(1);
  mouse.click(120, 150);
  mouse.click(180, 150);
  ok &= KERF_CHECK(sketch->GetNumberOfClickedPoints() == 1 && sketch->GetClickedPoints()->GetTuple3(0)[0] > 0.0);
  mouse.click(5, 5);
  ok &= KERF_CHECK(said.find("missed the surface") != std::string::npos);

  // Nothing shown in the view (the surface hidden, or its source not yet applied): the widget
  // says so.
  actor->VisibilityOff();
  sketch->SetMode(vtkKerfSketchRepresentation::STROKES); // (whose strokes were cleared above)
  window->Render();
  mouse.drag(100, 150, 200, 150);
  ok &= KERF_CHECK(!widget->GetLastChanged() && said.find("Nothing is shown to draw on") != std::string::npos);
  actor->VisibilityOn();

  // The picture: the discs' rims on the sphere (orange adding, blue subtracting), the point.
  sketch->SetMode(vtkKerfSketchRepresentation::DISCS);
  window->Render();
  const int result = vtkRegressionTestImage(window);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return ok && result != vtkRegressionTester::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
