/**
 * @class vtkKerfSketchWidget
 * @brief Kerf's sketch widget: strokes drawn, discs dragged out and points clicked on the visible
 * surface of a view, for the filters that take them (Stroke Cut, Easy Mesh Cut, Region Growing,
 * ROI Scissor, Geodesic Disc, Geodesic Polyline, Geodesic Seam).
 *
 * Hold Ctrl and press the left button on the surface (or just press it, with
 * DrawWithoutModifier): a drag draws a stroke (vtkKerfSketchRepresentation::STROKES), drags out a
 * disc from the press (DISCS; with Shift as well the disc subtracts) or, released where pressed,
 * clicks (a click on a stroke, a disc's centre or a point erases it; POINTS adds a point). Without
 * Ctrl the left button turns the camera as before. Ctrl+Z takes the last change back; the number
 * keys choose the label of the next stroke and O an override stroke (labelled strokes only).
 *
 * Events: StartInteractionEvent when a gesture starts, EndInteractionEvent when it ends and after
 * Undo and Clear (GetLastChanged says whether the drawn input changed), and MessageEvent with a
 * sentence for the user when a gesture gives nothing (GetMessage; without an observer of
 * MessageEvent the sentence is a warning).
 */
#ifndef vtkKerfSketchWidget_h
#define vtkKerfSketchWidget_h

#include "KerfWidgetsModule.h"
#include "vtkAbstractWidget.h"
#include "vtkCommand.h"

#include <string>

class vtkKerfSketchRepresentation;
class vtkPoints;

class KERFWIDGETS_EXPORT vtkKerfSketchWidget : public vtkAbstractWidget
{
public:
  static vtkKerfSketchWidget* New();
  vtkTypeMacro(vtkKerfSketchWidget, vtkAbstractWidget);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Invoked with the message (a const char*) when a gesture gives nothing and says why.
  enum
  {
    MessageEvent = vtkCommand::UserEvent + 4511
  };

  void SetRepresentation(vtkKerfSketchRepresentation* representation);
  vtkKerfSketchRepresentation* GetSketchRepresentation();
  void CreateDefaultRepresentation() override;
  /// Disabling the widget while drawing ends the gesture without changing the drawn input.
  void SetEnabled(int enabling) override;

  ///@{
  /// Draw with the left button alone, without Ctrl (the camera then turns with Ctrl or another
  /// button). Default off.
  vtkSetMacro(DrawWithoutModifier, bool);
  vtkGetMacro(DrawWithoutModifier, bool);
  vtkBooleanMacro(DrawWithoutModifier, bool);
  ///@}

  ///@{
  /// Render the view when a gesture, Undo or Clear changes the drawn input. Default on; off where
  /// something else renders right after anyway (ParaView's panel applies the filter, which
  /// renders), so that the view is not drawn twice.
  vtkSetMacro(RenderAfterChange, bool);
  vtkGetMacro(RenderAfterChange, bool);
  vtkBooleanMacro(RenderAfterChange, bool);
  ///@}

  ///@{
  /// Take back the last change; forget every drawn stroke, disc and point. Each invokes
  /// StartInteractionEvent and EndInteractionEvent when it changes something.
  void Undo();
  void Clear();
  ///@}

  ///@{
  /// Input from elsewhere (ParaView's selection): each point a one-point stroke of the current
  /// label; or one disc, centred on the point nearest to their centroid and reaching the farthest
  /// of them. Undoable; each invokes StartInteractionEvent and EndInteractionEvent.
  void AddClicks(vtkPoints* points);
  void AddDiscAround(vtkPoints* points);
  ///@}

  /// The label of the next stroke (see vtkKerfSketchRepresentation::SetCurrentLabel).
  void SetCurrentLabel(int label);

  /// Whether the last gesture, Undo or Clear changed the drawn input.
  vtkGetMacro(LastChanged, bool);
  /// What the last gesture had to say (empty when all went well).
  const char* GetMessage() const { return this->Message.c_str(); }

protected:
  vtkKerfSketchWidget();
  ~vtkKerfSketchWidget() override;

  static void StartAction(vtkAbstractWidget* widget);
  static void MoveAction(vtkAbstractWidget* widget);
  static void EndAction(vtkAbstractWidget* widget);
  static void KeyAction(vtkAbstractWidget* widget);

  void Changed(bool changed);
  void Say(const std::string& message);

  bool DrawWithoutModifier = false;
  bool RenderAfterChange = true;
  bool Drawing = false;
  bool LastChanged = false;
  std::string Message;

private:
  vtkKerfSketchWidget(const vtkKerfSketchWidget&) = delete;
  void operator=(const vtkKerfSketchWidget&) = delete;
};

#endif
