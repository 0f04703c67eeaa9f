// The panel widget "KerfStrokes": Kerf's sketch widget drawing strokes (see pqKerfSketchPropertyWidget).
#ifndef pqKerfStrokesPropertyWidget_h
#define pqKerfStrokesPropertyWidget_h

#include "pqKerfSketchPropertyWidget.h"
#include "vtkKerfSketchRepresentation.h"

class pqKerfStrokesPropertyWidget : public pqKerfSketchPropertyWidget
{
public:
  pqKerfStrokesPropertyWidget(vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr)
    : pqKerfSketchPropertyWidget(vtkKerfSketchRepresentation::STROKES, proxy, group, parent)
  {
  }
};

#endif
