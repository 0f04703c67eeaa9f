// Harmonic cuts on one surface: constraint placement, the field, and the choice of the cut.
#include "Harmonic/HarmonicCutSession.h"

#include "Error.h"
#include "Geometry/ClosestPoint.h"
#include "Mesh/MeshValidation.h"
#include "Numerics/FieldGradient.h"
#include "Numerics/IntrinsicTriangulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace kerf
{

HarmonicCutSession::HarmonicCutSession(std::shared_ptr<const Surface> surface)
  : SurfacePointer(std::move(surface))
{
  if (!this->SurfacePointer)
  {
    throw Error("a harmonic-cut session needs a surface");
  }
}

SoftConstraintFormulation HarmonicCutSession::automaticFormulation() const
{
  if (!this->Automatic)
  {
    this->Automatic = kerf::automaticFormulation(this->mesh());
  }
  return *this->Automatic;
}

void HarmonicCutSession::addHardValues(
  const std::vector<int>& vertices, const std::vector<double>& values, FieldConstraints& constraints) const
{
  if (vertices.size() != values.size())
  {
    throw Error("there are " + std::to_string(vertices.size()) + " hard vertices but " + std::to_string(values.size()) +
      " values");
  }
  const TriangleMesh& mesh = this->mesh();
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const int vertex = vertices[i];
    if (vertex < 0 || vertex >= mesh.vertexCount())
    {
      throw Error("hard value for vertex " + std::to_string(vertex) + ", which is not a vertex of the mesh");
    }
    if (!std::isnan(values[i]) && !mesh.vertexFaces(vertex).empty())
    {
      constraints.dirichletVertices.push_back(vertex);
      constraints.dirichletValues.push_back(values[i]);
    }
  }
}

int HarmonicCutSession::holdUnconstrainedComponents(FieldConstraints& constraints, double value) const
{
  const TriangleMesh& mesh = this->mesh();
  std::vector<char> constrained(static_cast<std::size_t>(mesh.componentCount()), 0);
  for (const int v : constraints.dirichletVertices)
  {
    if (v >= 0 && v < mesh.vertexCount() && mesh.vertexComponent(v) >= 0)
    {
      constrained[static_cast<std::size_t>(mesh.vertexComponent(v))] = 1;
    }
  }
  for (const SoftConstraint& s : constraints.soft)
  {
    if (s.face >= 0 && s.face < mesh.faceCount())
    {
      constrained[static_cast<std::size_t>(mesh.faceComponent(s.face))] = 1;
    }
  }
  int held = 0;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const int c = mesh.vertexComponent(v);
    if (c >= 0 && !constrained[static_cast<std::size_t>(c)])
    {
      constrained[static_cast<std::size_t>(c)] = 1;
      constraints.dirichletVertices.push_back(v);
      constraints.dirichletValues.push_back(value);
      ++held;
    }
  }
  return held;
}

void HarmonicCutSession::projectConstraints(const std::vector<Vector3>& points, const std::vector<double>& values,
  const ConstraintPlacement& placement, FieldConstraints& constraints) const
{
  if (points.size() != values.size())
  {
    throw Error("there are " + std::to_string(points.size()) + " constraint points but " +
      std::to_string(values.size()) + " values");
  }
  if (!std::isfinite(placement.maximumDistance))
  {
    throw Error("the largest distance from a constraint point to the surface must be a number (0 for no limit)");
  }
  const double limit =
    placement.maximumDistance > 0.0 ? placement.maximumDistance : std::numeric_limits<double>::infinity();
  const TriangleMesh& mesh = this->mesh();
  const ClosestPointLocator& locator = this->surface().locator();
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (!points[i].allFinite() || points[i].cwiseAbs().maxCoeff() > CoordinateLimit || !std::isfinite(values[i]))
    {
      throw Error("constraint point " + std::to_string(i) + " has a NaN, infinite or huge coordinate or value");
    }
    const ClosestPointLocator::Hit hit = locator.closest(points[i]);
    if (hit.distance > limit)
    {
      throw Error("constraint point " + std::to_string(i) + " is " + std::to_string(hit.distance) +
        " away from the surface, farther than the allowed " + std::to_string(limit));
    }
    if (placement.hard)
    {
      constraints.dirichletVertices.push_back(snapToVertex(mesh, hit));
      constraints.dirichletValues.push_back(values[i]);
    }
    else
    {
      constraints.soft.push_back({ hit.face, hit.barycentric, values[i] });
    }
  }
}

StrokeConstraintSet HarmonicCutSession::strokeConstraints(
  const std::vector<std::vector<Vector3>>& strokes, const StrokeOptions& options) const
{
  return kerf::strokeConstraints(
    this->mesh(), this->surface().locator(), this->surface().vertexNormals(), strokes, options);
}

namespace
{
// The intrinsic Delaunay Laplacian of a surface and the scale of its soft constraints.
struct IntrinsicLaplacianSet
{
  IntrinsicDelaunayLaplacian laplacian;
  double meanDiagonal = 1.0;
};
} // namespace

HarmonicFieldSolution HarmonicCutSession::solve(FieldConstraints constraints, const HarmonicFieldOptions& options)
{
  constraints.formulation = options.formulation;
  if (options.weights.weighting == LaplacianWeighting::IntrinsicDelaunay)
  {
    // Its edges join vertex pairs the mesh may not join: the field is solved on the intrinsic
    // triangles (the same points), while soft constraints stay inside the mesh's own triangles,
    // where the field is read and its isolines extracted.
    const IntrinsicLaplacianSet& intrinsic =
      this->surface().derived<IntrinsicLaplacianSet>("intrinsic-delaunay-laplacian", [this] {
        IntrinsicLaplacianSet set;
        set.laplacian = intrinsicDelaunayLaplacian(this->mesh());
        set.meanDiagonal = laplacianMeanDiagonal(set.laplacian.mesh, set.laplacian.weights);
        return set;
      });
    constraints.softWeight = options.softWeight * intrinsic.meanDiagonal;
    constraints.softTriangles = &this->mesh().triangles();
    return this->Solver.solve(intrinsic.laplacian.mesh, intrinsic.laplacian.weights, constraints);
  }
  const LaplacianWeightSet& weights = this->surface().laplacianWeights(options.weights);
  constraints.softWeight = options.softWeight * weights.meanDiagonal;
  return this->Solver.solve(this->mesh(), weights.weights, constraints);
}

namespace
{
// Checks the field on the vertices used by triangles.
void checkField(const TriangleMesh& mesh, const std::vector<double>& field)
{
  if (static_cast<int>(field.size()) != mesh.vertexCount())
  {
    throw Error("the field has " + std::to_string(field.size()) + " values for " + std::to_string(mesh.vertexCount()) +
      " points");
  }
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -lowest;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (mesh.vertexFaces(v).empty())
    {
      continue;
    }
    if (!std::isfinite(field[v]))
    {
      throw Error("the field has a NaN or infinite value at point " + std::to_string(v));
    }
    lowest = std::min(lowest, field[v]);
    highest = std::max(highest, field[v]);
  }
  if (!std::isfinite(highest - lowest))
  {
    throw Error("the field's range [" + std::to_string(lowest) + ", " + std::to_string(highest) +
      "] overflows double precision; rescale the field");
  }
}
} // namespace

CutResult HarmonicCutSession::chooseCut(const std::vector<double>& field, const CutOptions& options) const
{
  const TriangleMesh& mesh = this->mesh();
  checkField(mesh, field);
  if (options.mode != CutMode::BestScore && !std::isfinite(options.isoValue))
  {
    throw Error("the iso-value must be finite");
  }
  if (options.mode == CutMode::NearStroke)
  {
    if (options.stroke.empty())
    {
      throw Error("the cut nearest to a stroke needs a stroke");
    }
    for (std::size_t i = 0; i < options.stroke.size(); ++i)
    {
      if (!options.stroke[i].allFinite() || options.stroke[i].cwiseAbs().maxCoeff() > CoordinateLimit)
      {
        throw Error("stroke point " + std::to_string(i) + " has a NaN, infinite or huge coordinate");
      }
    }
  }

  CutResult result;
  result.value = options.isoValue;
  // Gradient magnitudes: every face's to score candidates, else only those the cut crosses.
  std::vector<double> magnitudes;
  if (options.mode == CutMode::BestScore)
  {
    magnitudes = faceGradientMagnitudes(mesh, field);
    result.candidates = scoreIsovalues(mesh, field, magnitudes, options.candidateCount);
    if (result.candidates.empty())
    {
      throw Error("the field is constant: there is no isoline to score");
    }
    std::size_t best = 0;
    for (std::size_t i = 0; i < result.candidates.size(); ++i)
    {
      best = result.candidates[i].score > result.candidates[best].score ? i : best;
    }
    result.value = result.candidates[best].value;
  }

  result.isolines = extractIsolines(mesh, field, result.value);
  if (options.mode == CutMode::NearStroke && !result.isolines.empty())
  {
    const int nearest = nearestIsoline(result.isolines, options.stroke);
    result.isolines = { result.isolines[static_cast<std::size_t>(nearest)] };
  }
  if (options.mode != CutMode::BestScore)
  {
    std::vector<int> crossed;
    for (const Isoline& line : result.isolines)
    {
      crossed.insert(crossed.end(), line.faces.begin(), line.faces.end());
    }
    magnitudes = faceGradientMagnitudes(mesh, field, &crossed);
  }
  std::vector<const Isoline*> cut;
  for (const Isoline& line : result.isolines)
  {
    cut.push_back(&line);
    result.scores.push_back(isolineScore({ line }, magnitudes));
  }
  result.labels = labelCutSides(mesh, field, result.value, cut);
  return result;
}

HarmonicCutSession::StrokeCut HarmonicCutSession::cutFromStroke(const std::vector<std::vector<Vector3>>& strokes,
  const StrokeOptions& strokeOptions, const HarmonicFieldOptions& fieldOptions)
{
  const StrokeConstraintSet set = this->strokeConstraints(strokes, strokeOptions);
  FieldConstraints constraints;
  constraints.soft = set.constraints;
  StrokeCut cut;
  cut.field = this->solve(constraints, fieldOptions).field;
  cut.isolines = extractIsolines(this->mesh(), cut.field, strokeOptions.isoValue);
  cut.chosen = nearestIsoline(cut.isolines, set.strokeSamples);
  for (const SoftConstraint& constraint : set.constraints)
  {
    cut.sideFaces.push_back(constraint.face);
  }
  return cut;
}

} // namespace kerf
