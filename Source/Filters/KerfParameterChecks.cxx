// Checks of a filter's parameters before Core sees them: names, NaN, distances as fractions of the diagonal, the stroke
// sampling and the formulation.
#include "KerfParameterChecks.h"

#include "Error.h"
#include "vtkStrokeConstraintAlgorithm.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace kerf
{

void CheckOutputNames(std::initializer_list<const char*> names)
{
  for (const char* name : names)
  {
    if (!name || !*name)
    {
      throw Error("every output array needs a non-empty name");
    }
  }
}

void CheckDifferentNames(const char* a, const char* b, const std::string& what)
{
  if (a && b && std::strcmp(a, b) == 0)
  {
    throw Error(what + " need different names (both are arrays of the same kind)");
  }
}

double Finite(double value, const char* parameter)
{
  if (std::isnan(value))
  {
    throw Error(std::string(parameter) + " must be a number, not NaN");
  }
  return value;
}

double StrokeIsoValue(double value)
{
  if (!std::isfinite(value) || !(value + 1.0 > value) || !(value - 1.0 < value))
  {
    throw Error(
      "IsoValue " + std::to_string(value) + " must be finite, and small enough that IsoValue +- 1 differ from it");
  }
  return value;
}

SoftConstraintFormulation FilterFormulation(int property, const HarmonicCutSession& session)
{
  switch (property)
  {
    case 0:
      return SoftConstraintFormulation::PointValues;
    case 1:
      return SoftConstraintFormulation::LeastSquares;
    default:
      return session.automaticFormulation();
  }
}

double RelativeDistance(double fraction, double diagonal, const char* parameter)
{
  if (!std::isfinite(fraction))
  {
    throw Error(std::string(parameter) + " must be a number (0 for no limit)");
  }
  return fraction > 0.0 ? fraction * diagonal : 0.0;
}

StrokeOptions ReadStrokeOptions(vtkStrokeConstraintAlgorithm* algorithm, double diagonal)
{
  StrokeOptions options;
  options.samplesPerSegment = algorithm->GetSamplesPerSegment();
  options.offset = Finite(algorithm->GetOffset(), "Offset") * diagonal;
  options.offsetLengthFraction = Finite(algorithm->GetOffsetLengthFraction(), "OffsetLengthFraction");
  options.isoValue = algorithm->GetIsoValue();
  options.maximumDistance =
    RelativeDistance(algorithm->GetMaximumProjectionDistance(), diagonal, "MaximumProjectionDistance");
  return options;
}

double ProjectionLimit(double fraction, const Surface& surface, const char* parameter)
{
  const double limit = RelativeDistance(fraction, surface.mesh().boundingBoxDiagonal(), parameter);
  return limit > 0.0 ? limit : std::numeric_limits<double>::infinity();
}

void CheckFinite(std::initializer_list<const std::vector<double>*> vectors, double scalar, const std::string& message)
{
  bool finite = std::isfinite(scalar);
  for (const std::vector<double>* values : vectors)
  {
    for (double v : *values)
    {
      finite = finite && std::isfinite(v);
    }
  }
  if (!finite)
  {
    throw Error(message);
  }
}

} // namespace kerf
