// The exception every Core function throws when its input cannot be processed.
#pragma once

#include <stdexcept>
#include <string>

namespace kerf
{

/// Thrown by Core functions for input they refuse (with a sentence naming the problem) and for
/// numerical failures. Filters catch it and report the message with vtkErrorMacro.
class Error : public std::runtime_error
{
public:
  explicit Error(const std::string& message)
    : std::runtime_error(message)
  {
  }
};

} // namespace kerf
