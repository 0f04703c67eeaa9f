// A benchmark method's parameters: "name=value;name=value" parsed, and each value read by its rule.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace kerf
{

/// A method's parameters, "name=value;name=value", parsed and checked against the names it knows.
class MethodParameters
{
public:
  MethodParameters(const std::string& text, const std::vector<std::string>& known);
  /// The value of a positive number parameter, or `fallback`; throws for anything else.
  double positive(const std::string& name, double fallback) const;
  /// The value of a number parameter (any finite number, the whole text), or `fallback`; throws for
  /// anything else ("0.5,x=1" is not 0.5).
  double number(const std::string& name, double fallback) const;
  /// The value of a parameter that counts something (a whole number below 1000), or `fallback`;
  /// throws for anything else.
  int wholeNumber(const std::string& name, int fallback) const;
  /// The value of a parameter in [0, 1) (the whole text a number), or `fallback`; throws for
  /// anything else.
  double fraction(const std::string& name, double fallback) const;
  /// The text of a parameter, or `fallback`.
  std::string text(const std::string& name, const std::string& fallback) const;

private:
  std::map<std::string, std::string> Values;
};

} // namespace kerf
