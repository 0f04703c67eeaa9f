// One surface's harmonic cuts: constraints placed on it, fields solved with a kept factorization, cuts chosen.
#pragma once

#include "Harmonic/HarmonicFieldSolver.h"
#include "Harmonic/Isolines.h"
#include "Harmonic/StrokeConstraints.h"
#include "Numerics/LaplacianWeights.h"
#include "Surface/Surface.h"

#include <memory>
#include <optional>
#include <vector>

namespace kerf
{

/// How constraint points are put on the surface.
struct ConstraintPlacement
{
  /// Hard values at the vertices the points snap to (snapToVertex), instead of soft constraints
  /// at the points themselves.
  bool hard = false;
  /// Points farther than this from the surface are refused (length units; 0: no limit).
  double maximumDistance = 0.0;
};

/// The field's parameters.
struct HarmonicFieldOptions
{
  LaplacianWeightOptions weights;
  /// Weight w of the soft constraints, relative to the Laplacian's mean diagonal entry.
  double softWeight = 1.0;
  /// How the soft constraints shape the field.
  SoftConstraintFormulation formulation = SoftConstraintFormulation::LeastSquares;
};

/// How the cut is chosen among the field's isolines.
enum class CutMode
{
  /// The isoline f = isoValue (sliding the value slides the cut: SeamCut, section 3).
  Value,
  /// The best-scored of candidateCount sampled values (ROI Scissor, section 4.2).
  BestScore,
  /// The component of f = isoValue nearest to the stroke (SeamCut, section 2.1.3).
  NearStroke
};

struct CutOptions
{
  CutMode mode = CutMode::Value;
  double isoValue = 0.0;
  int candidateCount = 50;
  std::vector<Vector3> stroke; ///< NearStroke: the stroke's points
};

/// A chosen cut.
struct CutResult
{
  double value = 0.0;                    ///< the iso-value of the cut
  std::vector<Isoline> isolines;         ///< the chosen components
  std::vector<double> scores;            ///< each chosen component's score
  std::vector<IsovalueScore> candidates; ///< BestScore: every candidate, in order of value
  std::vector<int> labels;               ///< per face: the segments the cut bounds
};

/// The reusable state of harmonic cuts on one surface: the surface (with its locator, normals and
/// Laplacian weights cached by Surface) and the solver with its factorization. A filter, the
/// benchmark runner and the command line all drive cuts through a session, so the decisions live
/// here once. Not thread-safe.
class HarmonicCutSession
{
public:
  explicit HarmonicCutSession(std::shared_ptr<const Surface> surface);

  const Surface& surface() const { return *this->SurfacePointer; }
  const TriangleMesh& mesh() const { return this->SurfacePointer->mesh(); }
  /// kerf::automaticFormulation of the surface, computed on first use.
  SoftConstraintFormulation automaticFormulation() const;

  /// Adds hard values for vertices; NaN values and vertices used by no triangle are skipped.
  void addHardValues(
    const std::vector<int>& vertices, const std::vector<double>& values, FieldConstraints& constraints) const;

  /// Gives each connected component without any constraint a hard `value` at its first vertex,
  /// so that its field is that constant instead of undefined: a stroke then cuts the components
  /// it touches and leaves the others whole (with `value` off the cut's iso-value, no isoline
  /// crosses them). Returns how many components it held.
  int holdUnconstrainedComponents(FieldConstraints& constraints, double value) const;

  /// Places value constraints at points: each point is projected onto the surface and becomes a
  /// soft constraint there, or a hard value at the vertex it snaps to. Throws kerf::Error naming
  /// the point for NaN or infinite coordinates or values and for points farther than allowed.
  void projectConstraints(const std::vector<Vector3>& points, const std::vector<double>& values,
    const ConstraintPlacement& placement, FieldConstraints& constraints) const;

  /// SeamCut's strokes to paired constraints (strokeConstraints with the surface's locator and
  /// normals).
  StrokeConstraintSet strokeConstraints(
    const std::vector<std::vector<Vector3>>& strokes, const StrokeOptions& options) const;

  /// Solves the field; the factorization is kept while the weights, the hard vertices and the
  /// kind of constraints stay the same (see HarmonicFieldSolver). The intrinsic Delaunay
  /// weighting is solved on the intrinsic triangulation's edges (intrinsicDelaunayLaplacian,
  /// cached on the surface), on the same vertices; soft constraints stay in the mesh's triangles.
  HarmonicFieldSolution solve(FieldConstraints constraints, const HarmonicFieldOptions& options);

  /// Chooses the cut on a field (one value per mesh vertex). Throws kerf::Error for NaN field
  /// values on the surface, a range beyond double precision, a non-finite iso-value, a missing or
  /// non-finite stroke in NearStroke mode and a constant field in BestScore mode.
  CutResult chooseCut(const std::vector<double>& field, const CutOptions& options) const;

  /// A stroke's whole cut on its own field: constraints at isoValue +- 1, the field, and the
  /// component of f = isoValue nearest to the stroke (none if the field has no isoline there).
  struct StrokeCut
  {
    std::vector<double> field;
    std::vector<Isoline> isolines; ///< every component of f = isoValue
    int chosen = -1;               ///< the one nearest to the stroke, or -1
    std::vector<int> sideFaces;    ///< the faces holding the stroke's constraint points
  };
  StrokeCut cutFromStroke(const std::vector<std::vector<Vector3>>& strokes, const StrokeOptions& strokeOptions,
    const HarmonicFieldOptions& fieldOptions);

private:
  std::shared_ptr<const Surface> SurfacePointer;
  HarmonicFieldSolver Solver;
  mutable std::optional<SoftConstraintFormulation> Automatic;
};

} // namespace kerf
