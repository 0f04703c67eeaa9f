// What Easy Mesh Cutting's filters share: labelled strokes read from polylines, boundaries written as polylines.
#include "KerfEasyMeshCutting.h"

#include "Error.h"
#include "KerfFilterUtilities.h"

#include <vtkCellData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <string>

namespace kerf
{

std::vector<LabelledStroke> ReadLabelledStrokes(vtkPolyData* input, const char* labelArray)
{
  const std::vector<std::vector<Vector3>> lines = ReadPolylines(input, "the strokes");
  if (lines.empty())
  {
    throw Error("the strokes hold no line");
  }
  const std::vector<double> labels = ReadNamedCellArray(input, labelArray, "the strokes");
  const vtkIdType first = input->GetNumberOfVerts(); // a line's cell id follows the verts
  std::vector<LabelledStroke> strokes;
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    const double label = labels[static_cast<std::size_t>(first) + i];
    if (!(label >= 0.0 && label <= 1e9 && label == std::floor(label)))
    {
      throw Error("stroke " + std::to_string(i) + " has the label " + std::to_string(label) +
        "; labels are non-negative integers (background 0, foreground 1)");
    }
    strokes.push_back({ static_cast<int>(label), lines[i] });
  }
  return strokes;
}

IsophoticMetricOptions MetricOptions(double normalWeight, double curvatureWeight, int augmentation, bool perEdge)
{
  IsophoticMetricOptions metric;
  metric.normalWeight = Finite(normalWeight, "NormalWeight");
  metric.curvatureWeight = Finite(curvatureWeight, "CurvatureWeight");
  metric.augmentation = static_cast<CurvatureAugmentation>(augmentation);
  metric.curvaturePerEdge = perEdge;
  return metric;
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
