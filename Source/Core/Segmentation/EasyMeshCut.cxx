// Easy Mesh Cutting in one call: region growing, optional snake refinement, boundaries as polylines.
#include "Segmentation/EasyMeshCut.h"

#include "Surface/Surface.h"

namespace kerf
{

namespace
{
void measure(EasyMeshCutBoundary& boundary)
{
  const std::vector<Vector3>& p = boundary.points;
  for (std::size_t i = 1; i < p.size(); ++i)
  {
    boundary.length += (p[i] - p[i - 1]).norm();
  }
  if (boundary.closed && p.size() > 1)
  {
    boundary.length += (p.front() - p.back()).norm();
  }
}
} // namespace

EasyMeshCutResult refineBoundaries(
  const std::shared_ptr<const Surface>& surface, const std::vector<int>& faceLabels, const EasyMeshCutOptions& options)
{
  EasyMeshCutResult result;
  BoundarySnake snake(surface, faceLabels);
  if (options.refine)
  {
    result.snake = snake.refine(options.snake);
  }
  for (const std::vector<Vector3>& stroke : options.overrides)
  {
    snake.overrideWithStroke(stroke, options.overrideRadius, options.growing.maximumDistance);
  }
  result.faceLabels = snake.faceLabels();
  for (const SnakeCurve& curve : snake.curves())
  {
    EasyMeshCutBoundary boundary{ curve.leftLabel, curve.rightLabel, curve.closed, {}, 0.0 };
    for (const SnakePoint& point : curve.points)
    {
      boundary.points.push_back(point.position);
    }
    measure(boundary);
    result.boundaries.push_back(std::move(boundary));
  }
  return result;
}

EasyMeshCutResult easyMeshCut(const std::shared_ptr<const Surface>& surface, const std::vector<LabelledStroke>& strokes,
  const EasyMeshCutOptions& options)
{
  const TriangleMesh& mesh = surface->mesh();
  EasyMeshCutResult result;
  result.growing = growRegions(*surface, strokes, options.growing);
  result.distances = result.growing.distances;
  if (!options.refine && options.overrides.empty())
  {
    result.faceLabels = result.growing.faceLabels;
    for (const LabelBoundary& chain : labelBoundaries(mesh, result.faceLabels))
    {
      EasyMeshCutBoundary boundary{ chain.leftLabel, chain.rightLabel, chain.closed, {}, 0.0 };
      for (int v : chain.vertices)
      {
        boundary.points.push_back(mesh.point(v));
      }
      measure(boundary);
      result.boundaries.push_back(std::move(boundary));
    }
    return result;
  }
  EasyMeshCutResult refined = refineBoundaries(surface, result.growing.faceLabels, options);
  result.faceLabels = std::move(refined.faceLabels);
  result.boundaries = std::move(refined.boundaries);
  result.snake = refined.snake;
  return result;
}

} // namespace kerf
