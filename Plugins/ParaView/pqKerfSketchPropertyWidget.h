// The panel of Kerf's sketch widget in ParaView: how to draw, undo and clear, labels, the selection as input, and the
// cut that follows at once.
#ifndef pqKerfSketchPropertyWidget_h
#define pqKerfSketchPropertyWidget_h

#include "pqInteractivePropertyWidget.h"

#include <QElapsedTimer>
#include <QList>
#include <QPointer>
#include <QVariant>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class vtkKerfSketchRepresentation;
class vtkKerfSketchWidget;
class vtkObject;

/**
 * A property-group widget for the filters that take input drawn on the surface. The group's
 * functions name the filter's properties the widget sets:
 * - strokes (panel_widget="KerfStrokes"): StrokePoints, StrokeSizes and, for labelled strokes,
 *   StrokeLabels;
 * - discs (panel_widget="KerfDiscs"): Discs;
 * - points (panel_widget="KerfPoints"): Points.
 * The group's hints may name the typed input the drawn input replaces, shown paler in the view
 * (`<KerfTyped stroke="..." foreground="..." background="..." center="..." radius="..."
 * points="..."/>`), and `<KerfSketch maximum_points="1" overrides="1" follow="..."/>`: one point
 * only, an override label, the text of the toggle that re-executes the filter when a gesture ends.
 */
class pqKerfSketchPropertyWidget : public pqInteractivePropertyWidget
{
  Q_OBJECT
  Q_PROPERTY(QList<QVariant> strokePoints READ strokePoints WRITE setStrokePoints NOTIFY drawnChanged)
  Q_PROPERTY(QList<QVariant> strokeSizes READ strokeSizes WRITE setStrokeSizes NOTIFY drawnChanged)
  Q_PROPERTY(QList<QVariant> strokeLabels READ strokeLabels WRITE setStrokeLabels NOTIFY drawnChanged)
  Q_PROPERTY(QList<QVariant> discs READ discs WRITE setDiscs NOTIFY drawnChanged)
  Q_PROPERTY(QList<QVariant> clickedPoints READ clickedPoints WRITE setClickedPoints NOTIFY drawnChanged)
  typedef pqInteractivePropertyWidget Superclass;

public:
  /// `mode` is a vtkKerfSketchRepresentation::Modes value.
  pqKerfSketchPropertyWidget(int mode, vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr);
  ~pqKerfSketchPropertyWidget() override;

  QList<QVariant> strokePoints() const;
  QList<QVariant> strokeSizes() const;
  QList<QVariant> strokeLabels() const;
  QList<QVariant> discs() const;
  QList<QVariant> clickedPoints() const;
  void setStrokePoints(const QList<QVariant>& values);
  void setStrokeSizes(const QList<QVariant>& values);
  void setStrokeLabels(const QList<QVariant>& values);
  void setDiscs(const QList<QVariant>& values);
  void setClickedPoints(const QList<QVariant>& values);

  bool eventFilter(QObject* watched, QEvent* event) override;

protected:
  void showEvent(QShowEvent* event) override;

Q_SIGNALS:
  /// The notify signal of the drawn-input properties, which only ever come from the server
  /// manager (the widget sets the filter's properties; Apply commits what these hold): never
  /// emitted.
  void drawnChanged();

protected Q_SLOTS:
  void placeWidget() override;

private Q_SLOTS:
  void gestureEnded();
  void undo();
  void clear();
  void useSelection();
  void chooseLabel(int index);
  void updateTyped();
  void rendering();
  void rendered();
  void applyNow();

private:
  vtkKerfSketchWidget* sketchWidget() const;
  vtkKerfSketchRepresentation* representation() const;
  void showLabel();
  void showMessage(vtkObject* caller, unsigned long event, void* data);
  void setStatus(const QString& text, bool problem);
  bool overView(QObject* watched) const;
  void fitToPanel();

  int Mode;
  bool Labelled = false;
  QList<QVariant> StrokePointValues, StrokeSizeValues, StrokeLabelValues, DiscValues, PointValues;
  QPointer<QLabel> Help;
  QPointer<QLabel> Status;
  QPointer<QComboBox> Label;
  QPointer<QCheckBox> Follow;
  QPointer<QPushButton> UndoButton;
  QPointer<QWidget> PanelViewport;
  QElapsedTimer Since;
  bool Timing = false;
  qint64 RenderingAt = -1; // when the view began to render after the gesture
  unsigned long MessageObserver = 0;
  unsigned long LabelObserver = 0;
};

#endif
