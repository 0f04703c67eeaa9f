// The points typed in a filter's panel (ParaView's handle and polyline widgets): their lists, setters and their place
// on the surface.
#pragma once

#include "Geodesic/SurfacePoint.h"
#include "KerfSurfaceInput.h"
#include "Mesh/TriangleMesh.h"

#include <string>
#include <vector>

class vtkAlgorithm;

namespace kerf
{

/// A point set in a filter's panel (ParaView's handle and polyline widgets) on the surface: the
/// nearest surface point, whatever its distance, because the widgets' points start at the input's
/// bounds, not on the surface (pressing P puts them there). Throws naming `what` for NaN,
/// infinite or huge coordinates.
SurfacePoint PanelPointOnSurface(const Surface& surface, const Vector3& point, const std::string& what);

/// The points a filter's panel sets (ParaView's interactive polyline): a stroke, a path. A count
/// or an index beyond MaximumCount is refused before anything is allocated.
class StrokePointList
{
public:
  static constexpr int MaximumCount = 10000000;
  /// These set the list; true when it changed. Throw kerf::Error for an absurd count or index.
  bool SetCount(int count);
  bool Set(int index, const Vector3& point);
  int Count() const { return static_cast<int>(this->List.size()); }
  const std::vector<Vector3>& Points() const { return this->List; }

private:
  std::vector<Vector3> List;
};

/// The setters of a filter's panel points (SetNumberOf<Noun>Points, Set<Noun>Point): `list` is
/// changed inside GuardSetter (an absurd count or index is reported and nothing changes) and
/// `algorithm` marked modified when it changed. `noun` names the points in errors ("stroke").
void SetPanelPointCount(vtkAlgorithm* algorithm, StrokePointList& list, int count, const std::string& noun);
void SetPanelPoint(
  vtkAlgorithm* algorithm, StrokePointList& list, int index, const Vector3& point, const std::string& noun);

/// The panel's points moved to the nearest points of the surface, whatever their distance (the
/// panel's first points come from the input's bounds); throws naming "<noun> point <i>" for NaN,
/// infinite or huge coordinates.
std::vector<Vector3> PanelPointsOnSurface(
  const StrokePointList& panel, const Surface& surface, const std::string& noun);

} // namespace kerf
