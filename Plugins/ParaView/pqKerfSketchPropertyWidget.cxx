// pqKerfSketchPropertyWidget: the sketch widget's panel, its shortcuts over the view, the selection taken as strokes or
// a disc, and the apply that follows a gesture.
#include "pqKerfSketchPropertyWidget.h"

#include "vtkKerfSketchRepresentation.h"
#include "vtkKerfSketchWidget.h"

#include "pqActiveObjects.h"
#include "pqApplicationCore.h"
#include "pqCoreUtilities.h"
#include "pqOutputPort.h"
#include "pqPipelineSource.h"
#include "pqPropertiesPanel.h"
#include "pqSMAdaptor.h"
#include "pqSelectionManager.h"
#include "pqServer.h"
#include "pqSettings.h"
#include "pqView.h"
#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkOutputWindow.h"
#include "vtkPVDataInformation.h"
#include "vtkPVLogger.h"
#include "vtkPVXMLElement.h"
#include "vtkPointSet.h"
#include "vtkSMNewWidgetRepresentationProxy.h"
#include "vtkSMPropertyGroup.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSmartPointer.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QCursor>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPixmap>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QTextEdit>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
// The typed input the drawn input replaces: (the KerfTyped hint's attribute, the widget's
// property showing it).
const char* const TypedInputs[][2] = {
  { "stroke", "TypedStrokePoints" },
  { "foreground", "TypedForegroundPoints" },
  { "background", "TypedBackgroundPoints" },
  { "center", "TypedDiscCenter" },
  { "radius", "TypedDiscRadius" },
  { "points", "TypedPoints" },
};

vtkPVXMLElement* hint(vtkSMPropertyGroup* group, const char* name)
{
  vtkPVXMLElement* hints = group->GetHints();
  return hints ? hints->FindNestedElementByName(name) : nullptr;
}

QString helpText(int mode, bool labelled)
{
  switch (mode)
  {
    case vtkKerfSketchRepresentation::DISCS:
      return QObject::tr("<b>Ctrl+drag</b> outward from a click to make a disc, <b>Ctrl+Shift+drag</b> to "
                         "cut one out; Ctrl+click a centre to erase, Ctrl+Z undoes.");
    case vtkKerfSketchRepresentation::POINTS:
      return QObject::tr("<b>Ctrl+click</b> on the surface to add a point, on a point to erase it; "
                         "Ctrl+Z undoes.");
    default:
      return labelled ? QObject::tr("<b>Ctrl+drag</b> over each part in its label's colour (keys 0-9 over the "
                                    "view choose it); Ctrl+click a stroke to erase, Ctrl+Z undoes.")
                      : QObject::tr("<b>Ctrl+drag</b> across the surface where the cut should go; Ctrl+click "
                                    "a stroke to erase it, Ctrl+Z undoes.");
  }
}

QIcon swatch(int label)
{
  double rgb[3];
  vtkKerfSketchRepresentation::LabelColor(label, true, rgb);
  QPixmap pixmap(12, 12);
  pixmap.fill(QColor::fromRgbF(rgb[0], rgb[1], rgb[2]));
  return QIcon(pixmap);
}
} // namespace

pqKerfSketchPropertyWidget::pqKerfSketchPropertyWidget(
  int mode, vtkSMProxy* smproxy, vtkSMPropertyGroup* smgroup, QWidget* parentObject)
  : Superclass("representations", "KerfSketchWidgetRepresentation", smproxy, smgroup, parentObject)
  , Mode(mode)
{
  this->setShowLabel(false);
  this->Labelled = smgroup->GetProperty("StrokeLabels") != nullptr;
  vtkSMNewWidgetRepresentationProxy* widget = this->widgetProxy();
  vtkSMPropertyHelper(widget, "Mode").Set(mode);
  vtkSMPropertyHelper(widget, "Labelled").Set(this->Labelled ? 1 : 0);
  vtkPVXMLElement* sketch = hint(smgroup, "KerfSketch");
  int maximumPoints = 0;
  if (sketch && sketch->GetScalarAttribute("maximum_points", &maximumPoints))
  {
    vtkSMPropertyHelper(widget, "MaximumPoints").Set(maximumPoints);
  }
  int overrides = 0;
  if (sketch)
  {
    sketch->GetScalarAttribute("overrides", &overrides);
  }
  widget->UpdateVTKObjects();
  if (vtkKerfSketchRepresentation* representation = this->representation())
  {
    representation->SetAllowOverride(overrides != 0);
  }

  // The panel: two lines of help, the label, the buttons, the toggle, what happened last.
  QVBoxLayout* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  this->Help = new QLabel(sketch && sketch->GetAttribute("help") ? QString::fromUtf8(sketch->GetAttribute("help"))
                                                                 : helpText(mode, this->Labelled),
    this);
  this->Help->setObjectName("Help");
  this->Help->setWordWrap(true);
  layout->addWidget(this->Help);
  if (this->Labelled)
  {
    QHBoxLayout* row = new QHBoxLayout();
    row->addWidget(new QLabel(tr("Next label"), this));
    this->Label = new QComboBox(this);
    this->Label->setObjectName("Label");
    this->Label->addItem(swatch(1), tr("1: foreground (the part to cut out)"), 1);
    this->Label->addItem(swatch(0), tr("0: background (the rest)"), 0);
    for (int label = 2; label <= 9; ++label)
    {
      this->Label->addItem(swatch(label), tr("%1: another part").arg(label), label);
    }
    if (overrides)
    {
      this->Label->addItem(swatch(-1), tr("O: override (the boundary runs here)"), -1);
    }
    this->Label->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    this->Label->setMinimumContentsLength(10);
    row->addWidget(this->Label, 1);
    layout->addLayout(row);
    this->connect(this->Label, SIGNAL(currentIndexChanged(int)), SLOT(chooseLabel(int)));
  }
  QHBoxLayout* buttons = new QHBoxLayout();
  this->UndoButton = new QPushButton(tr("Undo"), this);
  this->UndoButton->setObjectName("Undo");
  this->UndoButton->setToolTip(tr("Take back the last stroke, disc, point or erasure (Ctrl+Z over the view)"));
  QPushButton* clear = new QPushButton(tr("Clear"), this);
  clear->setObjectName("Clear");
  clear->setToolTip(tr("Forget everything drawn (Undo brings it back); the typed input, shown paler, is used again"));
  buttons->addWidget(this->UndoButton);
  buttons->addWidget(clear);
  this->connect(this->UndoButton, SIGNAL(clicked()), SLOT(undo()));
  this->connect(clear, SIGNAL(clicked()), SLOT(clear()));
  if (this->Labelled || mode == vtkKerfSketchRepresentation::DISCS)
  {
    QPushButton* selection = new QPushButton(this->Labelled ? tr("Use Selection") : tr("Use Selection as Disc"), this);
    selection->setObjectName("UseSelection");
    selection->setToolTip(this->Labelled
        ? tr("The cells selected in the view (Select Cells On, polygon selection, Grow Selection) become clicks of the "
             "label chosen above")
        : tr("The cells selected in the view become a disc: its centre the selected cell nearest to their middle, "
             "its radius reaching the farthest of them"));
    this->connect(selection, SIGNAL(clicked()), SLOT(useSelection()));
    layout->addLayout(buttons);
    layout->addWidget(selection); // a row of its own: the panel is narrow
  }
  else
  {
    layout->addLayout(buttons);
  }
  const char* followText =
    sketch && sketch->GetAttribute("follow") ? sketch->GetAttribute("follow") : "The result follows each gesture";
  this->Follow = new QCheckBox(tr(followText), this);
  this->Follow->setObjectName("Follow");
  this->Follow->setToolTip(tr("Apply when a stroke, disc or click ends, without pressing Apply"));
  pqSettings* settings = pqApplicationCore::instance()->settings();
  const QString key = QString("Kerf/Follow/%1").arg(smproxy->GetXMLName());
  this->Follow->setChecked(settings->value(key, true).toBool());
  QObject::connect(this->Follow, &QCheckBox::toggled, [this, key](bool on) {
    pqApplicationCore::instance()->settings()->setValue(key, on);
    if (vtkKerfSketchWidget* widget = this->sketchWidget())
    {
      widget->SetRenderAfterChange(!on); // the apply renders
    }
  });
  layout->addWidget(this->Follow);
  this->Status = new QLabel(this);
  this->Status->setObjectName("Status");
  this->Status->setWordWrap(true);
  layout->addWidget(this->Status);

  // The drawn input, held here so that Apply commits what the widget set.
  const std::pair<const char*, const char*> links[] = { { "StrokePoints", "strokePoints" },
    { "StrokeSizes", "strokeSizes" }, { "StrokeLabels", "strokeLabels" }, { "Discs", "discs" },
    { "Points", "clickedPoints" } };
  for (const auto& [function, qtProperty] : links)
  {
    if (vtkSMProperty* property = smgroup->GetProperty(function))
    {
      this->addPropertyLink(this, qtProperty, SIGNAL(drawnChanged()), property);
    }
  }

  // The typed input the drawn input replaces, shown paler.
  if (vtkPVXMLElement* typed = hint(smgroup, "KerfTyped"))
  {
    for (const auto& pair : TypedInputs)
    {
      if (const char* name = typed->GetAttribute(pair[0]))
      {
        if (vtkSMProperty* property = smproxy->GetProperty(name))
        {
          pqCoreUtilities::connect(property, vtkCommand::UncheckedPropertyModifiedEvent, this, SLOT(updateTyped()));
          pqCoreUtilities::connect(property, vtkCommand::ModifiedEvent, this, SLOT(updateTyped()));
        }
      }
    }
  }
  this->updateTyped();

  this->connect(this, SIGNAL(endInteraction()), SLOT(gestureEnded()));
  if (vtkKerfSketchWidget* sketchWidget = this->sketchWidget())
  {
    this->MessageObserver =
      sketchWidget->AddObserver(vtkKerfSketchWidget::MessageEvent, this, &pqKerfSketchPropertyWidget::showMessage);
    sketchWidget->SetRenderAfterChange(!this->Follow->isChecked());
    // A label chosen in the view (a key the panel did not see): the panel shows it too.
    this->LabelObserver =
      sketchWidget->AddObserver(vtkCommand::ModifiedEvent, this, &pqKerfSketchPropertyWidget::showLabel);
  }
  qApp->installEventFilter(this);
  this->setWidgetVisible(true);
}

pqKerfSketchPropertyWidget::~pqKerfSketchPropertyWidget()
{
  qApp->removeEventFilter(this);
  if (vtkKerfSketchWidget* widget = this->sketchWidget())
  {
    widget->RemoveObserver(this->MessageObserver);
    widget->RemoveObserver(this->LabelObserver);
  }
}

vtkKerfSketchWidget* pqKerfSketchPropertyWidget::sketchWidget() const
{
  return vtkKerfSketchWidget::SafeDownCast(this->widgetProxy()->GetWidget());
}

vtkKerfSketchRepresentation* pqKerfSketchPropertyWidget::representation() const
{
  vtkSMProxy* proxy = this->widgetProxy()->GetRepresentationProxy();
  return proxy ? vtkKerfSketchRepresentation::SafeDownCast(proxy->GetClientSideObject()) : nullptr;
}

void pqKerfSketchPropertyWidget::showLabel()
{
  vtkKerfSketchRepresentation* representation = this->representation();
  if (this->Label && representation)
  {
    const int index = this->Label->findData(representation->GetCurrentLabel());
    if (index >= 0 && index != this->Label->currentIndex())
    {
      this->Label->setCurrentIndex(index);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The values Apply commits.

QList<QVariant> pqKerfSketchPropertyWidget::strokePoints() const
{
  return this->StrokePointValues;
}
QList<QVariant> pqKerfSketchPropertyWidget::strokeSizes() const
{
  return this->StrokeSizeValues;
}
QList<QVariant> pqKerfSketchPropertyWidget::strokeLabels() const
{
  return this->StrokeLabelValues;
}
QList<QVariant> pqKerfSketchPropertyWidget::discs() const
{
  return this->DiscValues;
}
QList<QVariant> pqKerfSketchPropertyWidget::clickedPoints() const
{
  return this->PointValues;
}
void pqKerfSketchPropertyWidget::setStrokePoints(const QList<QVariant>& values)
{
  this->StrokePointValues = values;
}
void pqKerfSketchPropertyWidget::setStrokeSizes(const QList<QVariant>& values)
{
  this->StrokeSizeValues = values;
}
void pqKerfSketchPropertyWidget::setStrokeLabels(const QList<QVariant>& values)
{
  this->StrokeLabelValues = values;
}
void pqKerfSketchPropertyWidget::setDiscs(const QList<QVariant>& values)
{
  this->DiscValues = values;
}
void pqKerfSketchPropertyWidget::setClickedPoints(const QList<QVariant>& values)
{
  this->PointValues = values;
}

// ---------------------------------------------------------------------------------------------

void pqKerfSketchPropertyWidget::placeWidget()
{
  vtkBoundingBox bounds = this->dataBounds();
  if (!bounds.IsValid())
  {
    return;
  }
  double box[6];
  bounds.GetBounds(box);
  vtkSMNewWidgetRepresentationProxy* widget = this->widgetProxy();
  vtkSMPropertyHelper(widget, "PlaceWidget").Set(box, 6);
  widget->UpdateVTKObjects();
}

void pqKerfSketchPropertyWidget::updateTyped()
{
  vtkPVXMLElement* typed = hint(this->propertyGroup(), "KerfTyped");
  if (!typed)
  {
    return;
  }
  vtkSMNewWidgetRepresentationProxy* widget = this->widgetProxy();
  for (const auto& pair : TypedInputs)
  {
    const char* name = typed->GetAttribute(pair[0]);
    vtkSMProperty* property = name ? this->proxy()->GetProperty(name) : nullptr;
    vtkSMProperty* shown = widget->GetProperty(pair[1]);
    if (property && shown)
    {
      pqSMAdaptor::setMultipleElementProperty(
        shown, pqSMAdaptor::getMultipleElementProperty(property, pqSMAdaptor::UNCHECKED));
    }
  }
  widget->UpdateVTKObjects();
  this->render();
}

void pqKerfSketchPropertyWidget::chooseLabel(int index)
{
  if (this->Label && index >= 0)
  {
    const int label = this->Label->itemData(index).toInt();
    if (vtkKerfSketchWidget* widget = this->sketchWidget())
    {
      widget->SetCurrentLabel(label);
    }
    vtkSMPropertyHelper(this->widgetProxy(), "CurrentLabel").Set(label);
    this->widgetProxy()->UpdateVTKObjects();
  }
}

void pqKerfSketchPropertyWidget::undo()
{
  if (vtkKerfSketchWidget* widget = this->sketchWidget())
  {
    widget->Undo();
    if (!widget->GetLastChanged())
    {
      this->setStatus(tr("Nothing to undo."), false);
    }
  }
}

void pqKerfSketchPropertyWidget::clear()
{
  if (vtkKerfSketchWidget* widget = this->sketchWidget())
  {
    widget->Clear();
  }
}

void pqKerfSketchPropertyWidget::setStatus(const QString& text, bool problem)
{
  if (this->Status)
  {
    this->Status->setText(text);
    this->Status->setStyleSheet(problem ? "color: #b03000;" : "");
    this->fitToPanel();
  }
}

void pqKerfSketchPropertyWidget::showMessage(vtkObject*, unsigned long, void* data)
{
  const char* message = static_cast<const char*>(data);
  if (message && *message)
  {
    this->setStatus(QString::fromUtf8(message), true);
    // The Output Messages window as well, where ParaView reports every problem.
    vtkOutputWindow::GetInstance()->DisplayWarningText((std::string("Kerf: ") + message + "\n").c_str());
  }
}

void pqKerfSketchPropertyWidget::gestureEnded()
{
  vtkKerfSketchWidget* widget = this->sketchWidget();
  if (!widget || !widget->GetLastChanged())
  {
    return;
  }
  if (!*widget->GetMessage())
  {
    this->setStatus(QString(), false);
  }
  // What the filter needs before it can run at all (a path two points, Region Growing two labels):
  // until then the gesture waits, rather than each one failing.
  vtkPVXMLElement* sketch = hint(this->propertyGroup(), "KerfSketch");
  vtkKerfSketchRepresentation* representation = this->representation();
  int minimumPoints = 0, minimumLabels = 0;
  if (sketch && representation)
  {
    sketch->GetScalarAttribute("minimum_points", &minimumPoints);
    sketch->GetScalarAttribute("minimum_labels", &minimumLabels);
    const int points = representation->GetNumberOfClickedPoints();
    if (points > 0 && points < minimumPoints)
    {
      this->setStatus(
        tr("Click %1 more point(s): the filter needs %2.").arg(minimumPoints - points).arg(minimumPoints), false);
      this->render(); // the widget leaves it to the apply, which waits
      return;
    }
    if (representation->GetNumberOfStrokes() > 0 && representation->GetNumberOfLabels() < minimumLabels)
    {
      this->setStatus(
        tr("Draw a stroke of another label (the keys 0-9 over the view): the parts need %1 labels.").arg(minimumLabels),
        false);
      this->render();
      return;
    }
  }
  if (this->Follow && this->Follow->isChecked())
  {
    this->Since.start();
    // After the property links have passed the widget's values on (they do so on this event).
    QTimer::singleShot(0, this, SLOT(applyNow()));
  }
}

void pqKerfSketchPropertyWidget::applyNow()
{
  pqPropertiesPanel* panel = nullptr;
  for (QWidget* parent = this->parentWidget(); parent && !panel; parent = parent->parentWidget())
  {
    panel = qobject_cast<pqPropertiesPanel*>(parent);
  }
  if (!panel)
  {
    return;
  }
  if (pqView* view = this->view())
  {
    this->connect(view, SIGNAL(beginRender()), SLOT(rendering()), Qt::UniqueConnection);
    this->connect(view, SIGNAL(endRender()), SLOT(rendered()), Qt::UniqueConnection);
  }
  this->Timing = true;
  this->RenderingAt = -1;
  const qint64 queued = this->Since.elapsed();
  panel->apply();
  // The panel's apply renders the views itself; a second render would only hold the next gesture.
  if (this->Timing)
  {
    if (pqView* view = this->view())
    {
      view->render();
    }
  }
  vtkVLogF(PARAVIEW_LOG_APPLICATION_VERBOSITY(), "Kerf sketch: apply began %lld ms after the gesture",
    static_cast<long long>(queued));
}

void pqKerfSketchPropertyWidget::rendering()
{
  if (this->Timing && this->RenderingAt < 0)
  {
    this->RenderingAt = this->Since.elapsed();
  }
}

void pqKerfSketchPropertyWidget::rendered()
{
  if (!this->Timing)
  {
    return;
  }
  this->Timing = false;
  const qint64 ms = this->Since.elapsed();
  const qint64 start = this->RenderingAt < 0 ? ms : this->RenderingAt;
  vtkVLogF(PARAVIEW_LOG_APPLICATION_VERBOSITY(),
    "Kerf sketch: shown %lld ms after the gesture (update %lld ms, render %lld ms)", static_cast<long long>(ms),
    static_cast<long long>(start), static_cast<long long>(ms - start));
  vtkSMSourceProxy* source = vtkSMSourceProxy::SafeDownCast(this->proxy());
  vtkPVDataInformation* information = source ? source->GetDataInformation(0) : nullptr;
  if (information && information->GetNumberOfCells() == 0)
  {
    this->setStatus(tr("The filter gave nothing: its message is in the Output Messages window; Ctrl+Z takes the "
                       "last gesture back."),
      true);
    return;
  }
  this->setStatus(tr("Applied and shown %1 ms after the gesture.").arg(ms), false);
}

// ---------------------------------------------------------------------------------------------
// The selection as input.

void pqKerfSketchPropertyWidget::useSelection()
{
  pqSelectionManager* selections =
    qobject_cast<pqSelectionManager*>(pqApplicationCore::instance()->manager("SELECTION_MANAGER"));
  pqOutputPort* port = selections ? selections->getSelectedPort() : nullptr;
  vtkSMSourceProxy* selection = port ? port->getSelectionInput() : nullptr;
  if (!port || !selection)
  {
    this->setStatus(tr("Nothing is selected: select cells in the view first (Select Cells On, or polygon "
                       "selection)."),
      true);
    return;
  }
  // The selected cells' centres, brought to this process as ParaView's Python Fetch does.
  vtkSMSessionProxyManager* proxies = port->getServer()->proxyManager();
  vtkSmartPointer<vtkSMSourceProxy> extract;
  extract.TakeReference(vtkSMSourceProxy::SafeDownCast(proxies->NewProxy("filters", "ExtractSelection")));
  vtkSmartPointer<vtkSMSourceProxy> centers;
  centers.TakeReference(vtkSMSourceProxy::SafeDownCast(proxies->NewProxy("filters", "CellCenters")));
  vtkSmartPointer<vtkSMSourceProxy> reduce;
  reduce.TakeReference(vtkSMSourceProxy::SafeDownCast(proxies->NewProxy("filters", "ReductionFilter")));
  vtkSmartPointer<vtkSMSourceProxy> move;
  move.TakeReference(vtkSMSourceProxy::SafeDownCast(proxies->NewProxy("filters", "ClientServerMoveData")));
  if (!extract || !centers || !reduce || !move)
  {
    this->setStatus(tr("ParaView's selection filters are missing."), true);
    return;
  }
  vtkSMPropertyHelper(extract, "Input").Set(port->getSource()->getProxy(), port->getPortNumber());
  vtkSMPropertyHelper(extract, "Selection").Set(selection, port->getSelectionInputPort());
  extract->UpdateVTKObjects();
  vtkSMPropertyHelper(centers, "Input").Set(extract);
  centers->UpdateVTKObjects();
  vtkSMPropertyHelper(reduce, "Input").Set(centers);
  vtkSMPropertyHelper(reduce, "PostGatherHelperName").Set("vtkAppendPolyData");
  reduce->UpdateVTKObjects();
  reduce->UpdatePipeline();
  vtkSMPropertyHelper(move, "Input").Set(reduce);
  vtkSMPropertyHelper(move, "OutputDataType").Set(VTK_POLY_DATA);
  move->UpdateVTKObjects();
  move->UpdatePipeline();
  vtkAlgorithm* mover = vtkAlgorithm::SafeDownCast(move->GetClientSideObject());
  vtkPointSet* moved = mover ? vtkPointSet::SafeDownCast(mover->GetOutputDataObject(0)) : nullptr;
  if (!moved || moved->GetNumberOfPoints() == 0)
  {
    this->setStatus(tr("The selection holds no cell of %1.").arg(port->getSource()->getSMName()), true);
    return;
  }
  vtkPointSet* cells = vtkPointSet::SafeDownCast(moved);
  vtkKerfSketchWidget* widget = this->sketchWidget();
  if (!cells || !widget)
  {
    return;
  }
  if (this->Labelled)
  {
    widget->AddClicks(cells->GetPoints());
  }
  else
  {
    widget->AddDiscAround(cells->GetPoints());
  }
  if (widget->GetLastChanged())
  {
    this->setStatus(tr("%1 selected cells taken.").arg(cells->GetNumberOfPoints()), false);
  }
}

// ---------------------------------------------------------------------------------------------
// Shortcuts over the view, whichever widget has the keyboard focus.

bool pqKerfSketchPropertyWidget::overView(QObject* watched) const
{
  pqView* view = this->view();
  QWidget* viewWidget = view ? view->widget() : nullptr;
  if (!viewWidget || !viewWidget->isVisible())
  {
    return false;
  }
  for (QObject* object = watched; object; object = object->parent())
  {
    if (object == viewWidget)
    {
      return true;
    }
  }
  return viewWidget->rect().contains(viewWidget->mapFromGlobal(QCursor::pos()));
}

void pqKerfSketchPropertyWidget::showEvent(QShowEvent* event)
{
  this->Superclass::showEvent(event);
  for (QWidget* parent = this->parentWidget(); parent && !this->PanelViewport; parent = parent->parentWidget())
  {
    if (QScrollArea* area = qobject_cast<QScrollArea*>(parent))
    {
      this->PanelViewport = area->viewport();
    }
  }
  this->fitToPanel();
}

// The panel's other rows may be wider than what shows of it: this widget keeps within what shows,
// its help and status line wrapped, so that nothing of it is cut off.
void pqKerfSketchPropertyWidget::fitToPanel()
{
  if (!this->PanelViewport)
  {
    return;
  }
  const int width =
    std::max(120, this->PanelViewport->width() - this->mapTo(this->PanelViewport, QPoint(0, 0)).x() - 8);
  this->setMaximumWidth(width);
  for (QLabel* label : { this->Help.data(), this->Status.data() })
  {
    if (label)
    {
      label->setMaximumWidth(width);
      // The panel's layout does not ask a label for its height at a new width: say it.
      label->setMinimumHeight(label->text().isEmpty() ? 0 : label->heightForWidth(width));
    }
  }
}

bool pqKerfSketchPropertyWidget::eventFilter(QObject* watched, QEvent* event)
{
  if (event->type() == QEvent::Resize && watched == this->PanelViewport)
  {
    this->fitToPanel();
  }
  if ((event->type() != QEvent::KeyPress && event->type() != QEvent::ShortcutOverride) || !this->isSelected() ||
    !this->isWidgetVisible())
  {
    return this->Superclass::eventFilter(watched, event);
  }
  QKeyEvent* key = static_cast<QKeyEvent*>(event);
  // Ctrl+Z alone (Ctrl+Shift+Z is redo), digits and O unmodified; never a key typed into a text
  // field or a spin box that has the focus.
  const Qt::KeyboardModifiers modifiers = key->modifiers() & ~Qt::KeypadModifier;
  QWidget* focus = QApplication::focusWidget();
  if (focus &&
    (qobject_cast<QLineEdit*>(focus) || qobject_cast<QAbstractSpinBox*>(focus) || qobject_cast<QTextEdit*>(focus) ||
      qobject_cast<QPlainTextEdit*>(focus)))
  {
    return this->Superclass::eventFilter(watched, event);
  }
  const bool undo = key->key() == Qt::Key_Z && modifiers == Qt::ControlModifier;
  const bool digit =
    this->Labelled && modifiers == Qt::NoModifier && key->key() >= Qt::Key_0 && key->key() <= Qt::Key_9;
  const bool override = this->Labelled && modifiers == Qt::NoModifier && key->key() == Qt::Key_O && this->Label &&
    this->Label->findData(-1) >= 0;
  if (!(undo || digit || override) || !this->overView(watched))
  {
    return this->Superclass::eventFilter(watched, event);
  }
  if (event->type() == QEvent::ShortcutOverride)
  {
    event->accept(); // ours, not Edit > Undo's
    return true;
  }
  if (undo)
  {
    this->undo();
  }
  else if (this->Label)
  {
    const int index = this->Label->findData(override ? -1 : key->key() - Qt::Key_0);
    if (index >= 0)
    {
      this->Label->setCurrentIndex(index);
    }
  }
  return true;
}
