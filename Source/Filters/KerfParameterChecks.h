// Checks of a filter's parameters before Core sees them: names, NaN, distances as fractions of the diagonal, the stroke
// sampling and the formulation.
#pragma once

#include "Harmonic/HarmonicCutSession.h"
#include "Harmonic/StrokeConstraints.h"
#include "KerfSurfaceInput.h"

#include <initializer_list>
#include <string>
#include <vector>

class vtkStrokeConstraintAlgorithm;

namespace kerf
{

/// Throws unless every output array name is non-empty.
void CheckOutputNames(std::initializer_list<const char*> names);
/// Throws if two output arrays of the same kind would get the same name.
void CheckDifferentNames(const char* a, const char* b, const std::string& what);

/// `value` if it is a number; throws naming the parameter for NaN.
double Finite(double value, const char* parameter);
/// A stroke's iso-value I: finite, and small enough that I + 1 and I - 1 differ from it (the
/// values of its two sides); throws otherwise.
double StrokeIsoValue(double value);
/// The soft-constraint formulation a Formulation property names: 0 point values, 1 least
/// squares, 2 automatic (the session's kerf::automaticFormulation: least squares on coarse
/// meshes, point values where the mean edge is at most 1/180 of the diagonal).
SoftConstraintFormulation FilterFormulation(int property, const HarmonicCutSession& session);
/// A distance given as a fraction of the bounding-box diagonal, in length units; 0 stays 0 (no
/// limit). Throws for NaN.
double RelativeDistance(double fraction, double diagonal, const char* parameter);

/// MaximumProjectionDistance as a length: `fraction` of the surface's bounding-box diagonal, or
/// infinity for 0 (no limit). Throws naming `parameter` for NaN.
double ProjectionLimit(double fraction, const Surface& surface, const char* parameter);

/// The sampling of a vtkStrokeConstraintAlgorithm's strokes into constraints: samples per segment,
/// offset (Offset times `diagonal`), its cap, the iso-value and the projection limit
/// (MaximumProjectionDistance times `diagonal`); throws naming the parameter for NaN.
StrokeOptions ReadStrokeOptions(vtkStrokeConstraintAlgorithm* algorithm, double diagonal);

/// Throws `message` unless every value of the vectors and `scalar` is finite.
void CheckFinite(std::initializer_list<const std::vector<double>*> vectors, double scalar, const std::string& message);

} // namespace kerf
