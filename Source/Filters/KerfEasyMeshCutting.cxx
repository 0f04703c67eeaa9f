// What Easy Mesh Cutting's filters share: labelled strokes read from polylines and vertices, the growing options,
// boundaries written as polylines.
#include "KerfEasyMeshCutting.h"

#include "Error.h"
#include "KerfDrawnInput.h"
#include "KerfInputArrays.h"
#include "KerfOutputArrays.h"
#include "KerfPanelPoints.h"
#include "KerfParameterChecks.h"
#include "vtkStrokeGrowingAlgorithm.h"

#include <vtkCellData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <string>

namespace kerf
{

std::vector<LabelledStroke> ReadLabelledStrokes(vtkPolyData* input, const char* labelArray)
{
  // Vertex cells come first in the cell data, lines next; each point of a vertex cell is a stroke
  // of one point, each line a stroke along it.
  const std::vector<std::vector<Vector3>> vertices = ReadVertexCells(input, "the strokes");
  const std::vector<std::vector<Vector3>> lines = ReadPolylines(input, "the strokes");
  if (vertices.empty() && lines.empty())
  {
    throw Error("the strokes hold no line and no vertex");
  }
  const std::vector<double> labels = ReadNamedCellArray(input, labelArray, "the strokes");
  const auto labelOf = [&labels](std::size_t cell, const std::string& stroke) {
    const double label = labels[cell];
    if (!(label >= 0.0 && label <= 1e9 && label == std::floor(label)))
    {
      throw Error(stroke + " has the label " + std::to_string(label) +
        "; labels are non-negative integers (background 0, foreground 1)");
    }
    return static_cast<int>(label);
  };
  std::vector<LabelledStroke> strokes;
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const int label = labelOf(i, "vertex cell " + std::to_string(i) + " of the strokes");
    for (const Vector3& point : vertices[i])
    {
      strokes.push_back({ label, { point } });
    }
  }
  const std::size_t first = static_cast<std::size_t>(input->GetNumberOfVerts()); // a line's cell id follows the verts
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    strokes.push_back({ labelOf(first + i, "stroke " + std::to_string(i)), lines[i] });
  }
  return strokes;
}

PanelLabelledStrokes ReadGrowingStrokes(vtkPolyData* strokeInput, const char* labelArray, const DrawnStrokeList& drawn,
  const std::vector<std::pair<int, const StrokePointList*>>& typed, const Surface& surface)
{
  PanelLabelledStrokes read;
  if (strokeInput)
  {
    // Strokes from the input; override strokes drawn in the panel still edit the boundaries.
    read.strokes = ReadLabelledStrokes(strokeInput, labelArray);
    read.overrides = PanelOverrideStrokes(drawn, surface, false);
    return read;
  }
  read = PanelLabelled(drawn, typed, surface);
  if (read.strokes.empty())
  {
    throw Error("there are no strokes: draw a stroke for each part (in ParaView: hold Ctrl and drag over the part, "
                "its label chosen in the panel or with the number keys over the view) or connect labelled polylines "
                "to the Strokes input");
  }
  return read;
}

RegionGrowingOptions ReadGrowingOptions(vtkStrokeGrowingAlgorithm* algorithm, double diagonal)
{
  RegionGrowingOptions growing;
  growing.metric.normalWeight = Finite(algorithm->GetNormalWeight(), "NormalWeight");
  growing.metric.curvatureWeight = Finite(algorithm->GetCurvatureWeight(), "CurvatureWeight");
  growing.metric.augmentation = static_cast<CurvatureAugmentation>(algorithm->GetCurvatureAugmentation());
  growing.metric.curvaturePerEdge = algorithm->GetCurvaturePerEdge();
  growing.maximumDistance =
    RelativeDistance(algorithm->GetMaximumProjectionDistance(), diagonal, "MaximumProjectionDistance");
  switch (algorithm->GetBoundaryPlacement())
  {
    case vtkStrokeGrowingAlgorithm::BOUNDARY_FRONTS:
      growing.placement = BoundaryPlacement::Fronts;
      break;
    case vtkStrokeGrowingAlgorithm::BOUNDARY_MINIMUM_CUT:
      growing.placement = BoundaryPlacement::MinimumCut;
      break;
    default:
      growing.placement = BoundaryPlacement::RandomWalks;
  }
  growing.cutPlacement.band = Finite(algorithm->GetCutBand(), "CutBand");
  return growing;
}

SnakeOptions SnakeOptionsFrom(int iterations, double convergence, double curvatureOffset, int slideSamples)
{
  SnakeOptions snake;
  snake.iterations = iterations;
  snake.convergence = Finite(convergence, "SnakeConvergence");
  snake.curvatureOffset = Finite(curvatureOffset, "SnakeCurvatureOffset");
  snake.slideSamples = slideSamples;
  return snake;
}

void WriteLabelBoundaries(const std::vector<EasyMeshCutBoundary>& boundaries, vtkPolyData* lines)
{
  std::vector<PolylineToWrite> polylines;
  std::vector<int> leftLabels, rightLabels;
  for (const EasyMeshCutBoundary& boundary : boundaries)
  {
    polylines.push_back({ &boundary.points, boundary.closed, boundary.length });
    leftLabels.push_back(boundary.leftLabel);
    rightLabels.push_back(boundary.rightLabel);
  }
  WritePolylines(polylines, lines);
  lines->GetCellData()->AddArray(MakeIntArray("LeftLabel", leftLabels));
  lines->GetCellData()->AddArray(MakeIntArray("RightLabel", rightLabels));
}

} // namespace kerf
