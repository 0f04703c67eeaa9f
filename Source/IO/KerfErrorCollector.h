// Captures the first error an inner VTK algorithm reports, so the outer one can report it once.
#pragma once

#include <vtkCommand.h>

#include <string>

namespace kerf
{

/// An observer for ErrorEvent (and WarningEvent) that keeps the first message, stripped of
/// VTK's "ERROR: In file, line n / class (address):" preamble, instead of printing it.
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    if (!this->Message.empty() || !callData)
    {
      return;
    }
    std::string text = static_cast<const char*>(callData);
    const std::size_t address = text.find("): ");
    if (text.compare(0, 6, "ERROR:") == 0 && address != std::string::npos)
    {
      text = text.substr(address + 3);
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    {
      text.pop_back();
    }
    this->Message = text;
  }
  std::string Message;
};

} // namespace kerf
