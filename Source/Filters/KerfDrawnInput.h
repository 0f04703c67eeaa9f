// What a filter's panel draws on the surface (strokes, discs, points) and the rule that drawn input replaces typed
// input.
#pragma once

#include "Geodesic/ROIScissor.h"
#include "KerfPanelPoints.h"
#include "Segmentation/RegionGrowing.h"
#include "Sketch/SurfaceSketch.h"

#include <array>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDiscClickAlgorithm;
class vtkPointSet;
class vtkPolyData;

namespace kerf
{

/// Whole numbers set one by one in a filter's panel (a stroke's size, its label). A count or an
/// index beyond StrokePointList::MaximumCount is refused before anything is allocated.
class PanelIntegerList
{
public:
  /// These set the list; true when it changed. Throw kerf::Error for an absurd count or index.
  bool SetCount(int count);
  bool Set(int index, int value);
  int Count() const { return static_cast<int>(this->List.size()); }
  const std::vector<int>& Values() const { return this->List; }

private:
  std::vector<int> List;
};

/// The setters of a panel's whole numbers, as SetPanelPointCount and SetPanelPoint.
void SetPanelIntegerCount(vtkAlgorithm* algorithm, PanelIntegerList& list, int count, const std::string& noun);
void SetPanelInteger(vtkAlgorithm* algorithm, PanelIntegerList& list, int index, int value, const std::string& noun);

/// The label of a drawn override stroke (Easy Mesh Cut's boundary editing): not a part's label.
constexpr int OverrideStrokeLabel = -1;

/// The strokes drawn in a filter's panel (Kerf's sketch widget in ParaView): the points of every
/// stroke one after another, the number of points of each (all the points one stroke when there
/// are no sizes) and each stroke's label (0 for all when there are no labels).
class DrawnStrokeList
{
public:
  StrokePointList Points;
  PanelIntegerList Sizes;
  PanelIntegerList Labels;

  bool Empty() const { return this->Points.Count() == 0; }
  /// The strokes in order (kerf::splitDrawnStrokes). Throws kerf::Error when the sizes do not add
  /// up to the number of points or one is below 1, or when there are labels but not one per stroke.
  std::vector<DrawnStroke> Strokes() const;
  /// Appends a stroke of `points` with `label`; true when it changed the list (no points: false).
  /// Throws kerf::Error, changing nothing, when the list would hold more than
  /// StrokePointList::MaximumCount points or its lists do not agree.
  bool Add(const std::vector<Vector3>& points, int label);
  /// Forgets every stroke; true when there was one.
  bool Clear();
};

/// A disc drawn in a panel: a click and a geodesic radius in the input's units; a subtracting disc
/// is cut out of the union of the others.
struct DrawnDisc
{
  Vector3 centre = Vector3::Zero();
  double radius = 0.0;
  bool subtract = false;
};

/// The discs drawn in a filter's panel, five numbers each (x, y, z, radius, subtract: non-zero
/// subtracts). A count or an index beyond StrokePointList::MaximumCount is refused.
class DrawnDiscList
{
public:
  bool SetCount(int count);
  bool Set(int index, const std::array<double, 5>& disc);
  int Count() const { return static_cast<int>(this->List.size()); }
  /// The discs; throws kerf::Error naming the disc for NaN, infinite or huge coordinates and a
  /// radius that is not positive.
  std::vector<DrawnDisc> Discs() const;

private:
  std::vector<std::array<double, 5>> List;
};

/// The setters of a panel's discs, as SetPanelPointCount and SetPanelPoint.
void SetPanelDiscCount(vtkAlgorithm* algorithm, DrawnDiscList& list, int count);
void SetPanelDisc(vtkAlgorithm* algorithm, DrawnDiscList& list, int index, const std::array<double, 5>& disc);

/// A filter's strokes from its panel: the drawn strokes (each point moved to the nearest point of
/// the surface) where any are drawn, else the typed points as one stroke, else none.
std::vector<std::vector<Vector3>> PanelStrokes(
  const DrawnStrokeList& drawn, const StrokePointList& typed, const Surface& surface);

/// The strokes of a filter with strokes as polylines on input 1 or, without it, in its panel: the
/// polylines, else PanelStrokes; throws kerf::Error when there is no stroke.
std::vector<std::vector<Vector3>> ReadStrokes(
  vtkPolyData* strokeInput, const DrawnStrokeList& drawn, const StrokePointList& typed, const Surface& surface);

/// The points of a panel's drawn strokes moved to the nearest points of the surface (named "drawn
/// stroke <s> point <i>" in errors).
std::vector<Vector3> DrawnStrokeOnSurface(const Surface& surface, const DrawnStroke& stroke, std::size_t index);

/// A panel's drawn strokes labelled OverrideStrokeLabel (all of them with `every`), on the surface:
/// override strokes for the filters that edit boundaries.
std::vector<std::vector<Vector3>> PanelOverrideStrokes(
  const DrawnStrokeList& drawn, const Surface& surface, bool every);

/// Labelled strokes from a panel and the override strokes among them.
struct PanelLabelledStrokes
{
  std::vector<LabelledStroke> strokes;
  std::vector<std::vector<Vector3>> overrides;
};

/// A filter's labelled strokes from its panel: the drawn strokes of labels 0 and up (each point
/// moved to the nearest surface point), then each typed stroke whose label has no drawn stroke
/// (`typed`: label and points; empty lists are skipped); drawn strokes labelled
/// OverrideStrokeLabel are override strokes. Throws kerf::Error for a label below
/// OverrideStrokeLabel.
PanelLabelledStrokes PanelLabelled(const DrawnStrokeList& drawn,
  const std::vector<std::pair<int, const StrokePointList*>>& typed, const Surface& surface);

/// The clicks of a filter with geodesic discs (vtkGeodesicDisc, vtkROIScissor) and how far from
/// the surface they may be.
struct DiscClicks
{
  std::vector<ROIClick> added;
  std::vector<ROIClick> subtracted;
  /// The farthest a click of the click input may be from the surface, as a fraction of the
  /// bounding-box diagonal (infinity: no limit).
  double tolerance = 0.0;
};

/// The clicks of a filter with geodesic discs (its properties, see vtkDiscClickAlgorithm): each
/// point of `clickInput` (input 1), with its own radius (the point array ClickRadiusArrayName, a
/// fraction of the diagonal) when the input has that array, and subtracting its disc where the
/// point array ClickSubtractArrayName is non-zero; without a click input, the `drawn` discs where
/// there are any, else ClickPoint; both moved to the nearest surface point. Throws naming the
/// parameter or the click for NaN parameters, a radius that is not positive, no click and only
/// subtracting clicks.
DiscClicks ReadDiscClicks(
  const Surface& surface, vtkDiscClickAlgorithm* algorithm, const DrawnDiscList& drawn, vtkPointSet* clickInput);

} // namespace kerf
