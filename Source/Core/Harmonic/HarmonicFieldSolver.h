// The harmonic-field solver: hard vertex values and soft constraints at points inside faces.
#pragma once

#include "Mesh/TriangleMesh.h"
#include "Numerics/SparseCholesky.h"

#include <memory>
#include <string>
#include <vector>

namespace kerf
{

/// A point inside triangle `face` (barycentric coordinates w.r.t. its corners 0, 1, 2) whose field
/// value should be `value` (how strictly: see SoftConstraintFormulation).
struct SoftConstraint
{
  int face = -1;
  Vector3 barycentric = Vector3::Zero();
  double value = 0.0;
};

/// How soft constraints shape the field (see HarmonicFieldSolver).
enum class SoftConstraintFormulation
{
  /// f is harmonic away from the constraint points and takes their values there: it minimises
  /// f^T L f + K w sum_i (C_i f - c_i)^2 with the stiff K = HarmonicFieldSolver::
  /// PointValueStiffness. The plain Laplacian is factored: a first cut costs about a third, a new
  /// stroke about half of LeastSquares' (Documentation/filters/HarmonicCuts.md). Its cuts follow
  /// the least-squares ones within half the stroke offset on the benchmark meshes, but bend
  /// between the points on coarse, stretched triangles.
  PointValues,
  /// SeamCut's least squares, ||L_F f||^2 + w^2 sum_i (C_i f - c_i)^2; the squared Laplacian is
  /// factored. Smoother fields and straighter cuts on coarse meshes, at a higher cost.
  LeastSquares
};

/// The mean edge length, as a fraction of the bounding-box diagonal, up to which
/// automaticFormulation picks point values: there the default stroke offset (0.005 of the
/// diagonal) spans 0.9 mean edges or more.
constexpr double PointValueEdgeFraction = 0.005 / 0.9;

/// The formulation for `mesh` when the user names none: point values on meshes whose mean edge is
/// at most PointValueEdgeFraction of the diagonal, least squares (the closer cut on coarse meshes)
/// on the others. Where the default offset spans 0.9 mean edges or more the two agree: psb-dev's
/// models subdivided once, every human as the input, mean fidelity 0.0043 (least squares) and
/// 0.0049 (point values; median ratio 1.02) on the 23 such models, against 0.0064 and 0.0122 on
/// those below 0.7 edges (and psb-dev itself, all below 0.7: 0.0021 and 0.0083); on the benchmark's
/// cube dumbbells of 100k and 1M triangles (0.97 and 3.1 edges per offset) the cuts lie 0.05 and
/// 0.07 stroke offsets apart on average. Least squares costs three times as much on a fresh mesh.
/// Documentation/filters/HarmonicCuts.md, "Formulation".
SoftConstraintFormulation automaticFormulation(const TriangleMesh& mesh);

/// The formulation named "least-squares" or "point-values"; throws kerf::Error for another name.
SoftConstraintFormulation parseSoftConstraintFormulation(const std::string& name);

/// The constraints of one field: any combination of hard Dirichlet values on vertices and soft
/// constraints inside faces with weight w.
struct FieldConstraints
{
  std::vector<int> dirichletVertices;
  std::vector<double> dirichletValues;
  std::vector<SoftConstraint> soft;
  double softWeight = 1.0;
  /// The triangles the soft constraints' faces index, when they are not the solver mesh's own:
  /// the intrinsic Delaunay Laplacian is solved on the intrinsic triangles over the same points,
  /// while constraints stay inside the input's triangles, where the field is read. Null: the
  /// solver mesh's triangles.
  const std::vector<Triangle>* softTriangles = nullptr;
  SoftConstraintFormulation formulation = SoftConstraintFormulation::LeastSquares;
};

/// A solved field and how it was obtained.
struct HarmonicFieldSolution
{
  std::vector<double> field;     ///< per vertex; 0 on points used by no triangle
  double relativeResidual = 0.0; ///< ||M x - b|| / ||b|| of the system solved
  /// What the solve cost: a new factorization, a low-rank correction of the cached one (new soft
  /// constraint locations), or only a back-substitution (new values).
  enum class Work
  {
    Factorization,
    Update,
    BackSubstitution
  };
  Work work = Work::Factorization;
};

/// The field for display: each value clamped to the range of the constraint values (hard and
/// soft). A least-squares field overshoots its constraints far from them (-12..26 for +-1 on the
/// bundled camel, -4,413..29,910 with concavity-aware weights), so a colour map over its whole
/// range shows one colour; clamped, it shows the two sides and the transition where cuts lie.
/// Without constraints the field is returned as it is.
std::vector<double> clampToConstraintRange(const std::vector<double>& field, const FieldConstraints& constraints);

/// Solves for the field f, reusing its factorization while the mesh, the weights, the hard
/// vertices and the formulation stay the same, and its low-rank term while the constraint
/// locations do.
///
/// With hard constraints only, f is harmonic: L_FF f_F = -L_FD f_D (ROI Scissor, Eq. 1),
/// free boundaries getting the natural (zero-flux) condition. With soft constraints C_i (each
/// interpolates f at the constraint's point with its barycentric weights):
/// - PointValues: (L_FF + K w C_F^T C_F) f_F = -L_FD f_D + K w C_F^T (c - C_D f_D);
/// - LeastSquares (SeamCut, Eq. 1): f minimises ||L_F f||^2 + w^2 sum_i (C_i f - c_i)^2 over the
///   free values, L_F the Laplacian rows of the free vertices: (L_F^T L_F + w^2 C_F^T C_F) f_F =
///   -L_F^T L_FD f_D + w^2 C_F^T (c - C_D f_D).
/// The first term is factored once per surface, weighting and hard set (AMD ordering, or
/// geometricNestedDissection from geometricOrderingRows() free vertices); the
/// constraint term is the low-rank correction U U^T, applied through the Woodbury identity
/// (SparseCholesky::prepare/apply), so new strokes cost a sparse forward solve over the strokes'
/// elimination-tree reach and a k x k solve, and new values only the k x k solve and one
/// back-substitution. In a component without hard values the Laplacian term annihilates constants: one vertex of it is
/// fixed at 0 in the factored term and the component's constant offset becomes a separate unknown fitted to the
/// constraints, so the solution is that of the system itself, without regularization.
///
/// Throws kerf::Error for: no constraint, a component without any constraint (its field would
/// be undefined), indices out of range, NaN values or weights, a vertex given two different
/// hard values, and a failed factorization.
class HarmonicFieldSolver
{
public:
  HarmonicFieldSolver();
  ~HarmonicFieldSolver();

  HarmonicFieldSolution solve(
    const TriangleMesh& mesh, const std::vector<double>& edgeWeights, const FieldConstraints& constraints);

  /// Forgets the cached factorization.
  void reset();

  /// From this many free vertices the factored term is ordered by geometricNestedDissection
  /// instead of AMD: `laplacianRows` for the Laplacian (hard values, point values; default
  /// GeometricOrderingRows), `squaredRows` for least squares' squared Laplacian (default
  /// GeometricOrderingRowsSquared). Applies from the next factorization.
  void setGeometricOrderingRows(int laplacianRows, int squaredRows)
  {
    this->GeometricRows = laplacianRows;
    this->GeometricSquaredRows = squaredRows;
  }
  /// Both thresholds at once.
  void setGeometricOrderingRows(int rows) { this->setGeometricOrderingRows(rows, rows); }
  int geometricOrderingRows() const { return this->GeometricRows; }
  int geometricOrderingRowsSquared() const { return this->GeometricSquaredRows; }

  /// The fill-reducing permutation of the cached factorization (empty before the first, or
  /// without CHOLMOD), row k being the free vertex's column eliminated k-th.
  std::vector<int> factorPermutation() const;

  /// Past this many soft constraints (or more than half the unknowns), the constraint term is
  /// factored together with the Laplacian term instead of through the Woodbury identity, whose
  /// dense k x k capacitance matrix grows as k^3.
  static constexpr int DirectConstraintCount = 1024;

  /// PointValues: the constraint term is PointValueStiffness w sum_i (C_i f - c_i)^2. Stiff enough
  /// that the field meets the values within 0.5% on the benchmark meshes; finite, so that
  /// coincident points with different values average instead of making the system singular.
  static constexpr double PointValueStiffness = 1e3;

private:
  int GeometricRows;
  int GeometricSquaredRows;
  struct Problem;
  struct Cache;
  // The steps of solve(), in order.
  static Problem checkProblem(
    const TriangleMesh& mesh, const std::vector<double>& edgeWeights, const FieldConstraints& constraints);
  /// Factors the Laplacian term when the operator, the hard vertices or the mode changed; true
  /// if it did.
  bool factorIfChanged(const TriangleMesh& mesh, const std::vector<double>& edgeWeights, const Problem& problem);
  /// The hard values' right-hand side; solves for it when the values changed.
  Eigen::VectorXd solveHardValues(const Problem& problem);
  /// Prepares the constraint term for new constraint locations; true if it did.
  bool prepareSoftConstraints(const TriangleMesh& mesh, const FieldConstraints& constraints, bool direct);
  /// The many-constraint form: the constraint term and the offsets factored with the Laplacian.
  void factorWithConstraints(
    const TriangleMesh& mesh, const FieldConstraints& constraints, const Eigen::SparseMatrix<double>& u);
  /// Adds the soft constraints' correction to the free values x and fills the offsets.
  void solveSoftConstraints(const TriangleMesh& mesh, const FieldConstraints& constraints, const Problem& problem,
    const Eigen::VectorXd& hardRhs, Eigen::VectorXd& x, std::vector<double>& offset) const;
  double relativeResidual(const TriangleMesh& mesh, const FieldConstraints& constraints, const Problem& problem,
    const Eigen::VectorXd& hardRhs, const Eigen::VectorXd& x, const std::vector<double>& offset) const;
  std::vector<double> assembleField(const TriangleMesh& mesh, const Problem& problem, const Eigen::VectorXd& x,
    const std::vector<double>& offset) const;

  std::unique_ptr<Cache> State;
};

} // namespace kerf
