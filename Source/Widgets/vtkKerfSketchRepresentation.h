/**
 * @class vtkKerfSketchRepresentation
 * @brief What Kerf's sketch widget draws and holds: strokes drawn on the visible surface (with
 * labels), discs clicked and dragged out on it, or points clicked on it, and the typed input they
 * replace, shown in grey.
 *
 * The representation keeps the drawn input as the flat lists a filter takes (see
 * vtkDrawnStrokeAlgorithm, vtkDiscClickAlgorithm): stroke points one stroke after another with each
 * stroke's size and label; discs as (x, y, z, radius, subtract); points in order. The gestures of
 * vtkKerfSketchWidget go through StartGesture / ContinueGesture / EndGesture: at the start the
 * view's depth buffer is read once (the camera does not move while drawing), and every mouse
 * position is taken back to the surface point it shows (kerf::DepthImage), so drawing costs the
 * same on any mesh and needs no copy of it. Strokes that leave the surface or cross an occluding
 * contour are split; each piece is simplified to within half a pixel (and SimplifyTolerance of
 * the placed bounds' diagonal). A disc's radius is the length of the way over the visible surface
 * from the click to the mouse, and its rim is drawn where that length is reached in every
 * direction. Every change is undoable (Undo) until MaximumUndo changes back.
 *
 * The display: drawn strokes as thick lines in their label's colour (LabelColor), one-point
 * strokes as dots, discs as their rims (adding ones orange, subtracting ones blue), points as dots
 * joined in order; the typed input (TypedStrokePoints, TypedForegroundPoints,
 * TypedBackgroundPoints, TypedDisc, TypedPoints) thinner and paler, and only where the drawn input
 * does not replace it.
 */
#ifndef vtkKerfSketchRepresentation_h
#define vtkKerfSketchRepresentation_h

#include "KerfWidgetsModule.h"
#include "vtkWidgetRepresentation.h"

#include <memory>
#include <string>

class vtkDoubleArray;
class vtkIntArray;
class vtkPoints;

class KERFWIDGETS_EXPORT vtkKerfSketchRepresentation : public vtkWidgetRepresentation
{
public:
  static vtkKerfSketchRepresentation* New();
  vtkTypeMacro(vtkKerfSketchRepresentation, vtkWidgetRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What a gesture makes.
  enum Modes
  {
    /// A drag draws strokes (several per gesture where it leaves the surface); a click on a
    /// stroke erases it; a click elsewhere adds a one-point stroke when Labelled.
    STROKES = 0,
    /// A press on the surface and a drag outward make a disc; Shift at the press makes it
    /// subtract; a click on a disc's centre erases it.
    DISCS = 1,
    /// A click adds a point (replaces the last one when MaximumPoints is 1); a click on a point
    /// erases it.
    POINTS = 2
  };

  ///@{
  /// The mode. Default STROKES.
  vtkSetClampMacro(Mode, int, STROKES, POINTS);
  vtkGetMacro(Mode, int);
  ///@}

  ///@{
  /// Whether strokes carry labels (Easy Mesh Cut, Region Growing): each gets CurrentLabel and its
  /// colour, and a click adds a one-point stroke. Default off.
  vtkSetMacro(Labelled, bool);
  vtkGetMacro(Labelled, bool);
  vtkBooleanMacro(Labelled, bool);
  ///@}

  ///@{
  /// Whether a stroke may be an override stroke (label -1: Easy Mesh Cut's boundary editing).
  /// Default off.
  vtkSetMacro(AllowOverride, bool);
  vtkGetMacro(AllowOverride, bool);
  vtkBooleanMacro(AllowOverride, bool);
  ///@}

  ///@{
  /// The label the next stroke gets: 0 and up, or -1 for an override stroke (where
  /// AllowOverride). Default 1.
  void SetCurrentLabel(int label);
  vtkGetMacro(CurrentLabel, int);
  ///@}

  ///@{
  /// POINTS: how many points there may be (0: any number; 1: a click moves the point). Default 0.
  vtkSetClampMacro(MaximumPoints, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumPoints, int);
  ///@}

  ///@{
  /// Strokes are simplified to within this fraction of the placed bounds' diagonal (and half a
  /// pixel). Default 0.001.
  vtkSetClampMacro(SimplifyTolerance, double, 0.0, 0.1);
  vtkGetMacro(SimplifyTolerance, double);
  ///@}

  ///@{
  /// A gesture that moves the mouse less than this many pixels is a click. Default 4.
  vtkSetClampMacro(ClickTolerance, double, 0.0, 100.0);
  vtkGetMacro(ClickTolerance, double);
  ///@}

  ///@{
  /// A click erases the stroke, disc centre or point within this many pixels of it. Default 8.
  vtkSetClampMacro(PickTolerance, double, 0.0, 100.0);
  vtkGetMacro(PickTolerance, double);
  ///@}

  ///@{
  /// Changes that Undo can take back. Default 100.
  vtkSetClampMacro(MaximumUndo, int, 0, 100000);
  vtkGetMacro(MaximumUndo, int);
  ///@}

  ///@{
  /// The drawn strokes: their points one after another (x, y, z each), the number of points of
  /// each and each one's label (setters as vtkDrawnStrokeAlgorithm's; the getters return the
  /// lists, owned by the representation).
  void SetNumberOfStrokePoints(int count);
  void SetStrokePoint(int index, double x, double y, double z);
  vtkDoubleArray* GetStrokePoints();
  void SetNumberOfStrokeSizes(int count);
  void SetStrokeSize(int index, int size);
  vtkIntArray* GetStrokeSizes();
  void SetNumberOfStrokeLabels(int count);
  void SetStrokeLabel(int index, int label);
  vtkIntArray* GetStrokeLabels();
  int GetNumberOfStrokes();
  /// The number of different labels of 0 and up among the drawn strokes.
  int GetNumberOfLabels();
  ///@}

  ///@{
  /// The drawn discs: (x, y, z, radius, subtract) each.
  void SetNumberOfDiscs(int count);
  void SetDisc(int index, double x, double y, double z, double radius, double subtract);
  vtkDoubleArray* GetDiscs();
  int GetNumberOfDiscs();
  ///@}

  ///@{
  /// The clicked points, in order.
  void SetNumberOfClickedPoints(int count);
  void SetClickedPoint(int index, double x, double y, double z);
  vtkDoubleArray* GetClickedPoints();
  int GetNumberOfClickedPoints();
  ///@}

  ///@{
  /// The typed input the drawn input replaces, shown paler while nothing replaces it: a stroke
  /// without label, Easy Mesh Cut's foreground (label 1) and background (label 0) points, a disc
  /// (its click and radius: TypedDiscRadius 0 shows the click alone) and points.
  void SetNumberOfTypedStrokePoints(int count);
  void SetTypedStrokePoint(int index, double x, double y, double z);
  void SetNumberOfTypedForegroundPoints(int count);
  void SetTypedForegroundPoint(int index, double x, double y, double z);
  void SetNumberOfTypedBackgroundPoints(int count);
  void SetTypedBackgroundPoint(int index, double x, double y, double z);
  void SetTypedDiscCenter(double x, double y, double z);
  void SetTypedDiscRadius(double radius);
  void SetNumberOfTypedPoints(int count);
  void SetTypedPoint(int index, double x, double y, double z);
  ///@}

  /// The colour of a label's strokes (label -1: override strokes), and of unlabelled strokes.
  static void LabelColor(int label, bool labelled, double rgb[3]);

  /// What a gesture did.
  enum GestureOutcomes
  {
    /// Nothing changed (see GetMessage for why, if anything is to be said).
    GESTURE_NOTHING = 0,
    /// The drawn input changed.
    GESTURE_CHANGED = 1
  };

  ///@{
  /// A gesture at display position (x, y) (pixels, as the interactor's event positions): the
  /// start reads the depth buffer of the renderer's window; `subtract` makes a disc subtract.
  /// EndGesture returns a GestureOutcomes value; GetMessage then says what went wrong, if
  /// anything, as a sentence for the user (empty when all is well).
  void StartGesture(double x, double y, bool subtract);
  void ContinueGesture(double x, double y);
  int EndGesture(double x, double y);
  /// Ends the gesture in progress without changing the drawn input.
  void CancelGesture();
  bool IsGestureActive() const;
  const char* GetMessage() const { return this->Message.c_str(); }
  ///@}

  ///@{
  /// Input from elsewhere (a selection of cells, their centres): each point a one-point stroke of
  /// CurrentLabel; or one disc (adding), centred on the point nearest to the points' centroid, its
  /// radius the farthest point's distance from there. Undoable; true when something changed.
  bool AddClickStrokes(vtkPoints* points);
  bool AddDiscAround(vtkPoints* points);
  ///@}

  ///@{
  /// Undo the last change; forget every drawn stroke, disc and point (undoable). True when
  /// something changed.
  bool Undo();
  bool Clear();
  bool CanUndo() const;
  ///@}

  ///@{
  /// vtkWidgetRepresentation's interface.
  void PlaceWidget(double bounds[6]) override;
  void BuildRepresentation() override;
  void GetActors(vtkPropCollection* props) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  int RenderOpaqueGeometry(vtkViewport* viewport) override;
  int RenderTranslucentPolygonalGeometry(vtkViewport* viewport) override;
  vtkTypeBool HasTranslucentPolygonalGeometry() override;
  ///@}

protected:
  vtkKerfSketchRepresentation();
  ~vtkKerfSketchRepresentation() override;

  int Mode = STROKES;
  bool Labelled = false;
  bool AllowOverride = false;
  int CurrentLabel = 1;
  int MaximumPoints = 0;
  double SimplifyTolerance = 0.001;
  double ClickTolerance = 4.0;
  double PickTolerance = 8.0;
  int MaximumUndo = 100;
  std::string Message;

private:
  vtkKerfSketchRepresentation(const vtkKerfSketchRepresentation&) = delete;
  void operator=(const vtkKerfSketchRepresentation&) = delete;

  // After a setter: reports a refused size or index, marks the representation modified when a
  // list changed and, for the drawn lists, forgets the undo states (the drawn input was set from
  // outside).
  void ListChanged(int change, bool drawn);

  struct Internals;
  std::unique_ptr<Internals> State;
};

#endif
