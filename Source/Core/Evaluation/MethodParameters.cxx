// Parsing a benchmark method's parameters and reading their values.
#include "Evaluation/MethodParameters.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <exception>

namespace kerf
{

MethodParameters::MethodParameters(const std::string& text, const std::vector<std::string>& known)
{
  std::size_t start = 0;
  while (start < text.size())
  {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string pair = text.substr(start, end - start);
    start = end + 1;
    if (pair.empty())
    {
      continue;
    }
    const std::size_t equals = pair.find('=');
    const std::string name = pair.substr(0, equals);
    if (equals == std::string::npos || std::find(known.begin(), known.end(), name) == known.end())
    {
      throw Error("unknown or malformed method parameter '" + pair + "'");
    }
    this->Values[name] = pair.substr(equals + 1);
  }
}

double MethodParameters::number(const std::string& name, double fallback) const
{
  const auto found = this->Values.find(name);
  if (found == this->Values.end())
  {
    return fallback;
  }
  try
  {
    std::size_t used = 0;
    const double value = std::stod(found->second, &used);
    if (used == found->second.size() && std::isfinite(value))
    {
      return value;
    }
  }
  catch (const std::exception&)
  {
  }
  throw Error("method parameter " + name + " must be a number, got '" + found->second + "'");
}

double MethodParameters::positive(const std::string& name, double fallback) const
{
  const double value = this->number(name, fallback);
  if (this->Values.count(name) && !(value > 0.0))
  {
    throw Error("method parameter " + name + " must be a positive number, got '" + this->text(name, "") + "'");
  }
  return value;
}

int MethodParameters::wholeNumber(const std::string& name, int fallback) const
{
  const std::string given = this->text(name, std::to_string(fallback));
  return given.find_first_not_of("0123456789") == std::string::npos && !given.empty() && given.size() < 4
    ? std::stoi(given)
    : throw Error("the method parameter '" + name + "' must be a whole number below 1000, not '" + given + "'");
}

double MethodParameters::fraction(const std::string& name, double fallback) const
{
  const std::string given = this->text(name, "");
  if (given.empty())
  {
    return fallback;
  }
  std::size_t used = 0;
  double value = -1.0;
  try
  {
    value = std::stod(given, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used != given.size() || !(value >= 0.0 && value < 1.0))
  {
    throw Error("the method parameter '" + name + "' must be a number in [0, 1), not '" + given + "'");
  }
  return value;
}

std::string MethodParameters::text(const std::string& name, const std::string& fallback) const
{
  const auto found = this->Values.find(name);
  return found == this->Values.end() ? fallback : found->second;
}

} // namespace kerf
