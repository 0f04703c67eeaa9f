// The panel widget "KerfDiscs": Kerf's sketch widget drawing discs (see pqKerfSketchPropertyWidget).
#ifndef pqKerfDiscsPropertyWidget_h
#define pqKerfDiscsPropertyWidget_h

#include "pqKerfSketchPropertyWidget.h"
#include "vtkKerfSketchRepresentation.h"

class pqKerfDiscsPropertyWidget : public pqKerfSketchPropertyWidget
{
public:
  pqKerfDiscsPropertyWidget(vtkSMProxy* proxy, vtkSMPropertyGroup* group, QWidget* parent = nullptr)
    : pqKerfSketchPropertyWidget(vtkKerfSketchRepresentation::DISCS, proxy, group, parent)
  {
  }
};

#endif
