// Drawn strokes, discs and points of a filter's panel: their lists, setters, and the strokes they give.
#include "KerfDrawnInput.h"

#include "Error.h"
#include "Geodesic/SurfaceLocation.h"
#include "KerfFilterBorder.h"
#include "KerfInputArrays.h"
#include "KerfParameterChecks.h"
#include "vtkDiscClickAlgorithm.h"

#include <vtkAlgorithm.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>

#include <cmath>
#include <set>

namespace kerf
{

namespace
{
void checkCount(long long count, const char* what)
{
  if (count > StrokePointList::MaximumCount)
  {
    throw Error(std::string("a panel holds at most ") + std::to_string(StrokePointList::MaximumCount) + " " + what +
      ", not " + std::to_string(count));
  }
}

// Resizes `list` to `count` entries of `fill` (a negative count leaves it); true when it changed.
template <typename List, typename Value>
bool resize(List& list, int count, const Value& fill, const char* what)
{
  checkCount(count, what);
  if (count < 0 || static_cast<std::size_t>(count) == list.size())
  {
    return false;
  }
  list.resize(static_cast<std::size_t>(count), fill);
  return true;
}

// Sets entry `index` of `list`, growing it with `fill` (a negative index is ignored); true when it
// changed.
template <typename List, typename Value>
bool assign(List& list, int index, const Value& value, const Value& fill, const char* what)
{
  if (index < 0)
  {
    return false;
  }
  checkCount(static_cast<long long>(index) + 1, what);
  if (static_cast<std::size_t>(index) >= list.size())
  {
    list.resize(static_cast<std::size_t>(index) + 1, fill);
  }
  if (list[static_cast<std::size_t>(index)] == value)
  {
    return false;
  }
  list[static_cast<std::size_t>(index)] = value;
  return true;
}

// Runs a setter inside the setter's border and marks the algorithm modified when it changed.
template <typename Change>
void setAndMark(vtkAlgorithm* algorithm, const std::string& what, const Change& change)
{
  GuardSetter(algorithm, what.c_str(), [&]() {
    if (change())
    {
      algorithm->Modified();
    }
  });
}
} // namespace

bool PanelIntegerList::SetCount(int count)
{
  return resize(this->List, count, 0, "numbers");
}

bool PanelIntegerList::Set(int index, int value)
{
  return assign(this->List, index, value, 0, "numbers");
}

void SetPanelIntegerCount(vtkAlgorithm* algorithm, PanelIntegerList& list, int count, const std::string& noun)
{
  setAndMark(algorithm, "Cannot set the number of " + noun, [&]() { return list.SetCount(count); });
}

void SetPanelInteger(vtkAlgorithm* algorithm, PanelIntegerList& list, int index, int value, const std::string& noun)
{
  setAndMark(algorithm, "Cannot set a " + noun, [&]() { return list.Set(index, value); });
}

std::vector<DrawnStroke> DrawnStrokeList::Strokes() const
{
  return splitDrawnStrokes(this->Points.Points(), this->Sizes.Values(), this->Labels.Values());
}

bool DrawnStrokeList::Add(const std::vector<Vector3>& points, int label)
{
  if (points.empty())
  {
    return false;
  }
  // Sizes and labels for every earlier stroke first, so that the new one is a stroke of its own;
  // everything is checked before anything changes.
  const std::vector<DrawnStroke> before = this->Strokes();
  checkCount(static_cast<long long>(this->Points.Count()) + static_cast<long long>(points.size()), "points");
  this->Sizes.SetCount(static_cast<int>(before.size()));
  this->Labels.SetCount(static_cast<int>(before.size()));
  for (std::size_t s = 0; s < before.size(); ++s)
  {
    this->Sizes.Set(static_cast<int>(s), static_cast<int>(before[s].points.size()));
    this->Labels.Set(static_cast<int>(s), before[s].label);
  }
  int next = this->Points.Count();
  for (const Vector3& p : points)
  {
    this->Points.Set(next++, p);
  }
  this->Sizes.Set(this->Sizes.Count(), static_cast<int>(points.size()));
  this->Labels.Set(this->Labels.Count(), label);
  return true;
}

bool DrawnStrokeList::Clear()
{
  const bool changed = this->Points.Count() > 0 || this->Sizes.Count() > 0 || this->Labels.Count() > 0;
  this->Points.SetCount(0);
  this->Sizes.SetCount(0);
  this->Labels.SetCount(0);
  return changed;
}

bool DrawnDiscList::SetCount(int count)
{
  return resize(this->List, count, std::array<double, 5>{}, "discs");
}

bool DrawnDiscList::Set(int index, const std::array<double, 5>& disc)
{
  return assign(this->List, index, disc, std::array<double, 5>{}, "discs");
}

std::vector<DrawnDisc> DrawnDiscList::Discs() const
{
  std::vector<DrawnDisc> discs;
  for (std::size_t i = 0; i < this->List.size(); ++i)
  {
    const std::array<double, 5>& d = this->List[i];
    DrawnDisc disc;
    disc.centre = Vector3(d[0], d[1], d[2]);
    if (!disc.centre.allFinite() || disc.centre.cwiseAbs().maxCoeff() > CoordinateLimit)
    {
      throw Error("drawn disc " + std::to_string(i) + " has a centre with NaN, infinite or huge coordinates");
    }
    if (!(std::isfinite(d[3]) && d[3] > 0.0))
    {
      throw Error("drawn disc " + std::to_string(i) + " has the radius " + std::to_string(d[3]) +
        "; drag outward from the click to give it a positive radius");
    }
    disc.radius = d[3];
    disc.subtract = d[4] != 0.0;
    discs.push_back(disc);
  }
  return discs;
}

void SetPanelDiscCount(vtkAlgorithm* algorithm, DrawnDiscList& list, int count)
{
  setAndMark(algorithm, "Cannot set the number of drawn discs", [&]() { return list.SetCount(count); });
}

void SetPanelDisc(vtkAlgorithm* algorithm, DrawnDiscList& list, int index, const std::array<double, 5>& disc)
{
  setAndMark(algorithm, "Cannot set a drawn disc", [&]() { return list.Set(index, disc); });
}

std::vector<Vector3> DrawnStrokeOnSurface(const Surface& surface, const DrawnStroke& stroke, std::size_t index)
{
  std::vector<Vector3> placed;
  for (std::size_t i = 0; i < stroke.points.size(); ++i)
  {
    placed.push_back(surfacePosition(surface.mesh(),
      PanelPointOnSurface(
        surface, stroke.points[i], "drawn stroke " + std::to_string(index) + " point " + std::to_string(i))));
  }
  return placed;
}

std::vector<std::vector<Vector3>> PanelOverrideStrokes(const DrawnStrokeList& drawn, const Surface& surface, bool every)
{
  std::vector<std::vector<Vector3>> overrides;
  const std::vector<DrawnStroke> list = drawn.Empty() ? std::vector<DrawnStroke>() : drawn.Strokes();
  for (std::size_t s = 0; s < list.size(); ++s)
  {
    if (every || list[s].label == OverrideStrokeLabel)
    {
      overrides.push_back(DrawnStrokeOnSurface(surface, list[s], s));
    }
  }
  return overrides;
}

std::vector<std::vector<Vector3>> PanelStrokes(
  const DrawnStrokeList& drawn, const StrokePointList& typed, const Surface& surface)
{
  std::vector<std::vector<Vector3>> strokes;
  if (!drawn.Empty())
  {
    const std::vector<DrawnStroke> list = drawn.Strokes();
    for (std::size_t s = 0; s < list.size(); ++s)
    {
      strokes.push_back(DrawnStrokeOnSurface(surface, list[s], s));
    }
  }
  else if (typed.Count() > 0)
  {
    strokes.push_back(PanelPointsOnSurface(typed, surface, "stroke"));
  }
  return strokes;
}

std::vector<std::vector<Vector3>> ReadStrokes(
  vtkPolyData* strokeInput, const DrawnStrokeList& drawn, const StrokePointList& typed, const Surface& surface)
{
  if (strokeInput)
  {
    std::vector<std::vector<Vector3>> strokes = ReadPolylines(strokeInput, "the stroke input");
    if (strokes.empty())
    {
      throw Error("the stroke input holds no lines");
    }
    return strokes;
  }
  std::vector<std::vector<Vector3>> strokes = PanelStrokes(drawn, typed, surface);
  if (strokes.empty())
  {
    throw Error("there is no stroke: draw one (in ParaView: hold Ctrl and drag across the surface), type its points "
                "(StrokePoints) or connect polylines to the Strokes input");
  }
  return strokes;
}

PanelLabelledStrokes PanelLabelled(const DrawnStrokeList& drawn,
  const std::vector<std::pair<int, const StrokePointList*>>& typed, const Surface& surface)
{
  PanelLabelledStrokes out;
  std::set<int> drawnLabels;
  const std::vector<DrawnStroke> list = drawn.Empty() ? std::vector<DrawnStroke>() : drawn.Strokes();
  for (std::size_t s = 0; s < list.size(); ++s)
  {
    const int label = list[s].label;
    if (label < OverrideStrokeLabel)
    {
      throw Error("drawn stroke " + std::to_string(s) + " has the label " + std::to_string(label) +
        "; labels are 0 and up (background 0, foreground 1), or -1 for an override stroke");
    }
    if (label == OverrideStrokeLabel)
    {
      continue; // PanelOverrideStrokes' below
    }
    drawnLabels.insert(label);
    out.strokes.push_back({ label, DrawnStrokeOnSurface(surface, list[s], s) });
  }
  out.overrides = PanelOverrideStrokes(drawn, surface, false);
  for (const auto& [label, points] : typed)
  {
    if (points && points->Count() > 0 && drawnLabels.count(label) == 0)
    {
      out.strokes.push_back({ label,
        PanelPointsOnSurface(*points, surface,
          label == 1     ? "foreground"
            : label == 0 ? "background"
                         : "typed stroke") });
    }
  }
  return out;
}

DiscClicks ReadDiscClicks(
  const Surface& surface, vtkDiscClickAlgorithm* algorithm, const DrawnDiscList& drawn, vtkPointSet* input)
{
  const double diagonal = surface.mesh().boundingBoxDiagonal();
  const double absoluteRadius = algorithm->GetAbsoluteRadius();
  const double radius = Finite(absoluteRadius, "AbsoluteRadius") > 0.0
    ? absoluteRadius
    : RelativeDistance(algorithm->GetRadius(), diagonal, "Radius");
  DiscClicks clicks;
  const double maximumProjection = algorithm->GetMaximumProjectionDistance();
  clicks.tolerance = Finite(maximumProjection, "MaximumProjectionDistance") > 0.0
    ? maximumProjection
    : std::numeric_limits<double>::infinity();
  if (!input && drawn.Count() > 0)
  {
    const std::vector<DrawnDisc> discs = drawn.Discs();
    for (std::size_t i = 0; i < discs.size(); ++i)
    {
      const SurfacePoint click = PanelPointOnSurface(surface, discs[i].centre, "drawn disc " + std::to_string(i));
      (discs[i].subtract ? clicks.subtracted : clicks.added)
        .push_back({ surfacePosition(surface.mesh(), click), discs[i].radius });
    }
    if (clicks.added.empty())
    {
      throw Error(
        "every drawn disc subtracts: draw one that adds (hold Ctrl without Shift and drag outward from a click)");
    }
    return clicks;
  }
  if (!input)
  {
    const double* p = algorithm->GetClickPoint();
    const SurfacePoint click = PanelPointOnSurface(surface, Vector3(p[0], p[1], p[2]), "the click point");
    clicks.added.push_back({ surfacePosition(surface.mesh(), click), radius });
    return clicks;
  }
  const std::vector<Vector3> points = ReadPoints(input);
  // Optional per-click arrays: read when the input has them.
  const auto optional = [&](const char* name) {
    return name && *name && input->GetPointData()->GetAbstractArray(name)
      ? ReadNamedPointArray(input, name, "the clicks")
      : std::vector<double>();
  };
  const std::vector<double> radii = optional(algorithm->GetClickRadiusArrayName());
  const std::vector<double> subtract = optional(algorithm->GetClickSubtractArrayName());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (!radii.empty() && !(std::isfinite(radii[i]) && radii[i] > 0.0))
    {
      throw Error("click " + std::to_string(i) + " has the radius " + std::to_string(radii[i]) +
        "; radii are positive fractions of the diagonal");
    }
    const double r = radii.empty() ? radius : radii[i] * diagonal;
    (!subtract.empty() && subtract[i] != 0.0 ? clicks.subtracted : clicks.added).push_back({ points[i], r });
  }
  if (clicks.added.empty() && !clicks.subtracted.empty())
  {
    throw Error("every click subtracts its disc: at least one click must add one");
  }
  if (clicks.added.empty())
  {
    throw Error("the click input holds no point");
  }
  return clicks;
}

} // namespace kerf
