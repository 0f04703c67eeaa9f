// The points typed in a filter's panel (ParaView's handle and polyline widgets): their lists, setters and their place
// on the surface.
#include "KerfPanelPoints.h"

#include "KerfFilterBorder.h"

#include "Error.h"
#include "Geodesic/SurfaceLocation.h"

#include <vtkAlgorithm.h>

#include <limits>

namespace kerf
{

SurfacePoint PanelPointOnSurface(const Surface& surface, const Vector3& point, const std::string& what)
{
  return projectOntoSurface(surface, point, std::numeric_limits<double>::infinity(), what);
}

namespace
{
void checkStrokePointCount(long long count)
{
  if (count > StrokePointList::MaximumCount)
  {
    throw Error("a panel holds at most " + std::to_string(StrokePointList::MaximumCount) + " points, not " +
      std::to_string(count));
  }
}
} // namespace

bool StrokePointList::SetCount(int count)
{
  checkStrokePointCount(count);
  if (count < 0 || static_cast<std::size_t>(count) == this->List.size())
  {
    return false;
  }
  this->List.resize(static_cast<std::size_t>(count), Vector3::Zero());
  return true;
}

bool StrokePointList::Set(int index, const Vector3& point)
{
  if (index < 0)
  {
    return false;
  }
  checkStrokePointCount(static_cast<long long>(index) + 1);
  if (static_cast<std::size_t>(index) >= this->List.size())
  {
    this->List.resize(static_cast<std::size_t>(index) + 1, Vector3::Zero());
  }
  if (this->List[static_cast<std::size_t>(index)] == point)
  {
    return false;
  }
  this->List[static_cast<std::size_t>(index)] = point;
  return true;
}

void SetPanelPointCount(vtkAlgorithm* algorithm, StrokePointList& list, int count, const std::string& noun)
{
  GuardSetter(algorithm, ("Cannot set the number of " + noun + " points").c_str(), [&]() {
    if (list.SetCount(count))
    {
      algorithm->Modified();
    }
  });
}

void SetPanelPoint(
  vtkAlgorithm* algorithm, StrokePointList& list, int index, const Vector3& point, const std::string& noun)
{
  GuardSetter(algorithm, ("Cannot set a " + noun + " point").c_str(), [&]() {
    if (list.Set(index, point))
    {
      algorithm->Modified();
    }
  });
}

std::vector<Vector3> PanelPointsOnSurface(const StrokePointList& panel, const Surface& surface, const std::string& noun)
{
  std::vector<Vector3> positions;
  for (const Vector3& point : panel.Points())
  {
    const SurfacePoint placed =
      PanelPointOnSurface(surface, point, noun + " point " + std::to_string(positions.size()));
    positions.push_back(surfacePosition(surface.mesh(), placed));
  }
  return positions;
}

} // namespace kerf
