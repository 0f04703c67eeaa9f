// What Easy Mesh Cutting's filters (vtkEasyMeshCut, vtkRegionGrowing, vtkSnakeRefinement) share:
// labelled strokes read from polylines, the growing options, boundaries written as polylines.
#pragma once

#include "KerfDrawnInput.h"
#include "Segmentation/EasyMeshCut.h"

#include <utility>
#include <vector>

class vtkPolyData;
class vtkStrokeGrowingAlgorithm;

namespace kerf
{

/// The strokes of `input` with their labels, the cell array `labelArray` (non-negative
/// integers): each point of a vertex cell a stroke of one point, each line a stroke along it.
/// Throws kerf::Error for no line and no vertex, a missing or malformed array, or a label that is
/// negative or not an integer.
std::vector<LabelledStroke> ReadLabelledStrokes(vtkPolyData* input, const char* labelArray);

/// The labelled strokes of a filter that grows parts: those of `strokeInput` (ReadLabelledStrokes)
/// when it is connected, else those of its panel (PanelLabelled, the typed strokes `typed` where
/// no stroke of their label is drawn); the override strokes drawn in the panel either way.
/// Throws kerf::Error when there is no stroke.
PanelLabelledStrokes ReadGrowingStrokes(vtkPolyData* strokeInput, const char* labelArray, const DrawnStrokeList& drawn,
  const std::vector<std::pair<int, const StrokePointList*>>& typed, const Surface& surface);

/// The growing options from a filter's properties: the metric (w, w*, augmentation 0-2, per edge)
/// and the stroke points' farthest projection (MaximumProjectionDistance times `diagonal`), NaN
/// refused.
RegionGrowingOptions ReadGrowingOptions(vtkStrokeGrowingAlgorithm* algorithm, double diagonal);

/// The snake options from a filter's properties, NaN refused.
SnakeOptions SnakeOptionsFrom(int iterations, double convergence, double curvatureOffset, int slideSamples);

/// Writes boundaries as polylines (kerf::WritePolylines: Length, Closed) with the cell arrays
/// LeftLabel and RightLabel.
void WriteLabelBoundaries(const std::vector<EasyMeshCutBoundary>& boundaries, vtkPolyData* lines);

} // namespace kerf
