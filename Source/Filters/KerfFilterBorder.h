// The border every Kerf filter's RequestData and setters run inside: exceptions become one vtkErrorMacro and a 0
// return; the surface loaded; the ports of a surface with optional points.
#pragma once

#include "KerfSurfaceInput.h"

#include <functional>

class vtkAlgorithm;
class vtkInformation;
class vtkPointSet;
class vtkPolyData;

namespace kerf
{

/// The border every RequestData runs inside: `body` does the work and throws kerf::Error (or
/// anything else) on failure. Every exception stops here: it is reported with vtkErrorMacro as
/// "<what>: <message>." and RunGuarded returns 0 (VTK's failure); otherwise the progress is set
/// to 1 and it returns 1.
int RunGuarded(vtkAlgorithm* algorithm, const char* what, const std::function<void()>& body);

/// Calls `setter` and stops every exception at the border of a filter's setter (an impossible
/// size, an allocation failure): reported with vtkErrorMacro, nothing changes.
void GuardSetter(vtkAlgorithm* algorithm, const char* what, const std::function<void()>& setter);

/// Loads `input` into `surface` (converting and validating it, or reusing the conversion of the
/// same geometry); throws kerf::Error with the reason it is refused.
void LoadSurface(SurfaceInput& surface, vtkPolyData* input, const MeshRequirements& requirements);

/// Input port information of a filter with a surface on port 0 and optional points (any
/// vtkPointSet) on port 1.
int FillSurfaceAndOptionalPointsPorts(int port, vtkInformation* info);

} // namespace kerf
