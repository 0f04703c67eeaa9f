// The panel widget "KerfPoints": Kerf's sketch widget drawing points (see pqKerfSketchPropertyWidget).
#ifndef pqKerfPointsPropertyWidget_h
#define pqKerfPointsPropertyWidget_h

#include "pqKerfSketchPropertyWidget.h"
#include "vtkKerfSketchRepresentation.h"

class pqKerfPointsPropertyWidget : public pqKerfSketchPropertyWidget
{
public:
  pqKerfPointsPropertyWidget(vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr)
    : pqKerfSketchPropertyWidget(vtkKerfSketchRepresentation::POINTS, proxy, group, parent)
  {
  }
};

#endif
