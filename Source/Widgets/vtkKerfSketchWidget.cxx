// vtkKerfSketchWidget: the mouse and keys of Kerf's sketch widget, passed to its representation's gestures.
#include "vtkKerfSketchWidget.h"

#include "vtkKerfSketchRepresentation.h"

#include <vtkCallbackCommand.h>
#include <vtkEvent.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkWidgetCallbackMapper.h>
#include <vtkWidgetEvent.h>

#include <cctype>
#include <cstring>

vtkStandardNewMacro(vtkKerfSketchWidget);

vtkKerfSketchWidget::vtkKerfSketchWidget()
{
  // Before the camera's interactor style, which takes the left button otherwise.
  this->Priority = 0.9;
  this->ManagesCursor = 0;
  this->CallbackMapper->SetCallbackMethod(vtkCommand::LeftButtonPressEvent, vtkEvent::AnyModifier, 0, 0, nullptr,
    vtkWidgetEvent::Select, this, vtkKerfSketchWidget::StartAction);
  this->CallbackMapper->SetCallbackMethod(
    vtkCommand::MouseMoveEvent, vtkWidgetEvent::Move, this, vtkKerfSketchWidget::MoveAction);
  this->CallbackMapper->SetCallbackMethod(vtkCommand::LeftButtonReleaseEvent, vtkEvent::AnyModifier, 0, 0, nullptr,
    vtkWidgetEvent::EndSelect, this, vtkKerfSketchWidget::EndAction);
  this->CallbackMapper->SetCallbackMethod(vtkCommand::KeyPressEvent, vtkEvent::AnyModifier, 0, 0, nullptr,
    vtkWidgetEvent::ModifyEvent, this, vtkKerfSketchWidget::KeyAction);
}

vtkKerfSketchWidget::~vtkKerfSketchWidget() = default;

void vtkKerfSketchWidget::SetRepresentation(vtkKerfSketchRepresentation* representation)
{
  this->Superclass::SetWidgetRepresentation(representation);
}

vtkKerfSketchRepresentation* vtkKerfSketchWidget::GetSketchRepresentation()
{
  return vtkKerfSketchRepresentation::SafeDownCast(this->WidgetRep);
}

void vtkKerfSketchWidget::CreateDefaultRepresentation()
{
  if (!this->WidgetRep)
  {
    this->WidgetRep = vtkKerfSketchRepresentation::New();
  }
}

void vtkKerfSketchWidget::SetEnabled(int enabling)
{
  if (!enabling && this->Drawing)
  {
    // Disabled while drawing (the panel hidden, the view changed): the gesture ends, unfinished.
    this->Drawing = false;
    this->ReleaseFocus();
    this->EndInteraction();
    if (vtkKerfSketchRepresentation* representation = this->GetSketchRepresentation())
    {
      representation->CancelGesture();
    }
  }
  this->Superclass::SetEnabled(enabling);
}

void vtkKerfSketchWidget::StartAction(vtkAbstractWidget* widget)
{
  vtkKerfSketchWidget* self = static_cast<vtkKerfSketchWidget*>(widget);
  vtkRenderWindowInteractor* interactor = self->Interactor;
  vtkKerfSketchRepresentation* representation = self->GetSketchRepresentation();
  if (!interactor || !representation || !self->CurrentRenderer)
  {
    return;
  }
  if (!interactor->GetControlKey() && !self->DrawWithoutModifier)
  {
    return; // the camera's
  }
  const int x = interactor->GetEventPosition()[0];
  const int y = interactor->GetEventPosition()[1];
  if (!self->CurrentRenderer->IsInViewport(x, y))
  {
    return;
  }
  self->Drawing = true;
  self->GrabFocus(self->EventCallbackCommand);
  representation->StartGesture(x, y, interactor->GetShiftKey() != 0);
  self->EventCallbackCommand->SetAbortFlag(1);
  self->StartInteraction();
  self->InvokeEvent(vtkCommand::StartInteractionEvent, nullptr);
  self->Render();
}

void vtkKerfSketchWidget::MoveAction(vtkAbstractWidget* widget)
{
  vtkKerfSketchWidget* self = static_cast<vtkKerfSketchWidget*>(widget);
  if (!self->Drawing || !self->GetSketchRepresentation())
  {
    return;
  }
  self->GetSketchRepresentation()->ContinueGesture(
    self->Interactor->GetEventPosition()[0], self->Interactor->GetEventPosition()[1]);
  self->EventCallbackCommand->SetAbortFlag(1);
  self->Render();
}

void vtkKerfSketchWidget::EndAction(vtkAbstractWidget* widget)
{
  vtkKerfSketchWidget* self = static_cast<vtkKerfSketchWidget*>(widget);
  if (!self->Drawing || !self->GetSketchRepresentation())
  {
    return;
  }
  self->Drawing = false;
  self->ReleaseFocus();
  vtkKerfSketchRepresentation* representation = self->GetSketchRepresentation();
  const int outcome =
    representation->EndGesture(self->Interactor->GetEventPosition()[0], self->Interactor->GetEventPosition()[1]);
  self->EventCallbackCommand->SetAbortFlag(1);
  self->EndInteraction();
  self->LastChanged = outcome == vtkKerfSketchRepresentation::GESTURE_CHANGED;
  self->InvokeEvent(vtkCommand::EndInteractionEvent, nullptr);
  self->Say(representation->GetMessage());
  if (!self->LastChanged || self->RenderAfterChange)
  {
    self->Render();
  }
}

void vtkKerfSketchWidget::KeyAction(vtkAbstractWidget* widget)
{
  vtkKerfSketchWidget* self = static_cast<vtkKerfSketchWidget*>(widget);
  vtkRenderWindowInteractor* interactor = self->Interactor;
  vtkKerfSketchRepresentation* representation = self->GetSketchRepresentation();
  if (!interactor || !representation || self->Drawing)
  {
    return;
  }
  const char* key = interactor->GetKeySym();
  if (!key)
  {
    return;
  }
  // Ctrl+Z alone: Ctrl+Shift+Z is redo elsewhere.
  if (interactor->GetControlKey() && !interactor->GetShiftKey() &&
    (std::strcmp(key, "z") == 0 || std::strcmp(key, "Z") == 0))
  {
    self->Undo();
    self->EventCallbackCommand->SetAbortFlag(1);
  }
  else if (representation->GetLabelled() && std::strlen(key) == 1 && std::isdigit(static_cast<unsigned char>(key[0])))
  {
    self->SetCurrentLabel(key[0] - '0');
    self->EventCallbackCommand->SetAbortFlag(1);
  }
  else if (representation->GetLabelled() && representation->GetAllowOverride() &&
    (std::strcmp(key, "o") == 0 || std::strcmp(key, "O") == 0))
  {
    self->SetCurrentLabel(-1);
    self->EventCallbackCommand->SetAbortFlag(1);
  }
}

void vtkKerfSketchWidget::Changed(bool changed)
{
  this->LastChanged = changed;
  if (changed)
  {
    this->InvokeEvent(vtkCommand::StartInteractionEvent, nullptr);
    this->InvokeEvent(vtkCommand::EndInteractionEvent, nullptr);
    if (this->RenderAfterChange)
    {
      this->Render();
    }
  }
}

void vtkKerfSketchWidget::Undo()
{
  vtkKerfSketchRepresentation* representation = this->GetSketchRepresentation();
  this->Changed(representation && representation->Undo());
}

void vtkKerfSketchWidget::Clear()
{
  vtkKerfSketchRepresentation* representation = this->GetSketchRepresentation();
  this->Changed(representation && representation->Clear());
}

void vtkKerfSketchWidget::AddClicks(vtkPoints* points)
{
  vtkKerfSketchRepresentation* representation = this->GetSketchRepresentation();
  this->Changed(representation && representation->AddClickStrokes(points));
}

void vtkKerfSketchWidget::AddDiscAround(vtkPoints* points)
{
  vtkKerfSketchRepresentation* representation = this->GetSketchRepresentation();
  this->Changed(representation && representation->AddDiscAround(points));
  if (representation && !this->LastChanged)
  {
    this->Say(representation->GetMessage());
  }
}

void vtkKerfSketchWidget::SetCurrentLabel(int label)
{
  if (vtkKerfSketchRepresentation* representation = this->GetSketchRepresentation())
  {
    representation->SetCurrentLabel(label);
    this->InvokeEvent(vtkCommand::ModifiedEvent, nullptr);
  }
}

void vtkKerfSketchWidget::Say(const std::string& message)
{
  this->Message = message;
  if (message.empty())
  {
    return;
  }
  if (this->HasObserver(MessageEvent))
  {
    this->InvokeEvent(MessageEvent, const_cast<char*>(this->Message.c_str()));
  }
  else
  {
    vtkWarningMacro(<< message);
  }
}

void vtkKerfSketchWidget::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DrawWithoutModifier: " << this->DrawWithoutModifier << "\n";
  os << indent << "RenderAfterChange: " << this->RenderAfterChange << "\n";
  os << indent << "LastChanged: " << this->LastChanged << "\n";
  os << indent << "Message: " << this->Message << "\n";
}
