// The harmonic-field solver: validation, cached factorizations, low-rank corrections for soft constraints.
#include "Harmonic/HarmonicFieldSolver.h"

#include "Error.h"
#include "Numerics/LaplacianWeights.h"
#include "Numerics/NestedDissection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace kerf
{

SoftConstraintFormulation automaticFormulation(const TriangleMesh& mesh)
{
  const double diagonal = mesh.boundingBoxDiagonal();
  const double edge = mesh.meanEdgeLength();
  return diagonal > 0.0 && edge > 0.0 && edge <= PointValueEdgeFraction * diagonal
    ? SoftConstraintFormulation::PointValues
    : SoftConstraintFormulation::LeastSquares;
}

SoftConstraintFormulation parseSoftConstraintFormulation(const std::string& name)
{
  if (name == "least-squares")
  {
    return SoftConstraintFormulation::LeastSquares;
  }
  if (name == "point-values")
  {
    return SoftConstraintFormulation::PointValues;
  }
  throw Error("formulation must be least-squares or point-values, got '" + name + "'");
}

namespace
{
bool sameSoftLocations(const std::vector<SoftConstraint>& a, const std::vector<SoftConstraint>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    if (a[i].face != b[i].face || a[i].barycentric != b[i].barycentric)
    {
      return false;
    }
  }
  return true;
}

// The corners a soft constraint interpolates between, and its connected component.
const Triangle& softCorners(const TriangleMesh& mesh, const FieldConstraints& constraints, const SoftConstraint& s)
{
  return constraints.softTriangles ? (*constraints.softTriangles)[s.face] : mesh.triangle(s.face);
}

int softComponent(const TriangleMesh& mesh, const FieldConstraints& constraints, const SoftConstraint& s)
{
  return mesh.vertexComponent(softCorners(mesh, constraints, s)[0]);
}

// Hard values sorted by vertex, with conflicting duplicates refused.
std::vector<std::pair<int, double>> sortedDirichlet(const FieldConstraints& c, int vertexCount)
{
  if (c.dirichletVertices.size() != c.dirichletValues.size())
  {
    throw Error("the hard constraints have " + std::to_string(c.dirichletVertices.size()) + " vertices but " +
      std::to_string(c.dirichletValues.size()) + " values");
  }
  std::vector<std::pair<int, double>> pairs;
  for (std::size_t i = 0; i < c.dirichletVertices.size(); ++i)
  {
    const int v = c.dirichletVertices[i];
    if (v < 0 || v >= vertexCount)
    {
      throw Error("hard constraint on vertex " + std::to_string(v) + ", which is not a vertex of the mesh");
    }
    if (!std::isfinite(c.dirichletValues[i]))
    {
      throw Error("the hard constraint on vertex " + std::to_string(v) + " has a NaN or infinite value");
    }
    pairs.emplace_back(v, c.dirichletValues[i]);
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<std::pair<int, double>> unique;
  for (const auto& p : pairs)
  {
    if (!unique.empty() && unique.back().first == p.first)
    {
      if (unique.back().second != p.second)
      {
        throw Error("vertex " + std::to_string(p.first) + " is given two different hard values");
      }
      continue;
    }
    unique.push_back(p);
  }
  return unique;
}

// The hard value of vertex v, if it has one.
const std::pair<int, double>* findHard(const std::vector<std::pair<int, double>>& dirichlet, int v)
{
  const auto found = std::lower_bound(dirichlet.begin(), dirichlet.end(), std::make_pair(v, -HUGE_VAL));
  return found != dirichlet.end() && found->first == v ? &*found : nullptr;
}

// The rows and columns of a compressed column-major matrix mapped to new indices (-1: dropped),
// both maps increasing where defined, so the entries come out in order: one pass, no sorting.
Eigen::SparseMatrix<double> submatrix(const Eigen::SparseMatrix<double>& matrix, const std::vector<int>& row, int rows,
  const std::vector<int>& column, int columns)
{
  Eigen::SparseMatrix<double> out(rows, columns);
  std::vector<int> starts(1, 0);
  std::vector<int> indices;
  std::vector<double> values;
  for (int c = 0; c < static_cast<int>(matrix.outerSize()); ++c)
  {
    if (column[c] < 0)
    {
      continue;
    }
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, c); it; ++it)
    {
      const int r = row[static_cast<int>(it.row())];
      if (r >= 0)
      {
        indices.push_back(r);
        values.push_back(it.value());
      }
    }
    starts.push_back(static_cast<int>(indices.size()));
  }
  out.resizeNonZeros(static_cast<Eigen::Index>(indices.size()));
  std::copy(starts.begin(), starts.end(), out.outerIndexPtr());
  std::copy(indices.begin(), indices.end(), out.innerIndexPtr());
  std::copy(values.begin(), values.end(), out.valuePtr());
  return out;
}

// The weight w of the constraint term w^2 sum_i (C_i f - c_i)^2.
double penaltyWeight(const FieldConstraints& constraints)
{
  return constraints.formulation == SoftConstraintFormulation::PointValues
    ? std::sqrt(HarmonicFieldSolver::PointValueStiffness * constraints.softWeight)
    : constraints.softWeight;
}

} // namespace

/// One call's constraints, checked: the hard values sorted by vertex, and which components have
/// hard values.
struct HarmonicFieldSolver::Problem
{
  std::vector<std::pair<int, double>> dirichlet;
  std::vector<int> dirichletVertices;
  std::vector<double> hardValues;
  std::vector<char> hasHard; // per component
  bool softMode = false;
  bool squared = false; // least squares: the squared Laplacian is factored
};

struct HarmonicFieldSolver::Cache
{
  // What the factorization was built from.
  int vertexCount = -1;
  std::vector<Triangle> triangles;
  std::vector<double> weights;
  std::vector<int> dirichlet; // sorted vertices
  bool softMode = false;
  bool squared = false;
  bool factored = false;

  // Unknowns: `column[v]` indexes vertex v among the free columns, or is -1 for hard and pinned
  // vertices and points used by no triangle. In soft mode one vertex per component without hard
  // values is pinned; its component's offset is a separate unknown (one entry of `offsetIndex`).
  // The rows are the columns' vertices, and in least squares also the pins.
  std::vector<int> column;
  std::vector<int> columnVertices;
  std::vector<int> offsetIndex; // component -> offset unknown, or -1
  int offsets = 0;
  Eigen::SparseMatrix<double> laplacian;
  Eigen::SparseMatrix<double> rowsFree, rowsHard; // L_RF and L_RD
  Eigen::SparseMatrix<double> base;               // L_FF, or L_RF^T L_RF (least squares)
  SparseCholesky cholesky;

  // Hard-value part, for the current hard values.
  std::vector<double> hardValues;
  Eigen::VectorXd hardSolution; // B^-1 b_D
  bool hardSolved = false;

  // Soft part, for the current constraint locations and weight.
  std::vector<SoftConstraint> softLocations; // values ignored
  std::vector<Triangle> softCornerList;      // the corners each one interpolates
  double softWeight = 0.0;
  SoftConstraintFormulation formulation = SoftConstraintFormulation::LeastSquares;
  bool prepared = false;
  bool direct = false;           // the prepared form: Woodbury (false) or the direct factor
  Eigen::SparseMatrix<double> u; // w C_F^T
  SparseCholesky::LowRank lowRank;
  Eigen::LLT<Eigen::MatrixXd> capacitance; // I + U^T B^-1 U
  // Many constraints: [B + U U^T, w U E; w E^T U^T, w^2 E^T E] over the free values and the
  // offsets, factored as a whole.
  SparseCholesky directCholesky;

  int columns() const { return static_cast<int>(this->columnVertices.size()); }
};

HarmonicFieldSolver::HarmonicFieldSolver()
  : GeometricRows(GeometricOrderingRows)
  , GeometricSquaredRows(GeometricOrderingRowsSquared)
  , State(new Cache)
{
}

HarmonicFieldSolver::~HarmonicFieldSolver() = default;

void HarmonicFieldSolver::reset()
{
  this->State.reset(new Cache);
}

std::vector<int> HarmonicFieldSolver::factorPermutation() const
{
  return this->State->factored ? this->State->cholesky.permutation() : std::vector<int>();
}

HarmonicFieldSolver::Problem HarmonicFieldSolver::checkProblem(
  const TriangleMesh& mesh, const std::vector<double>& edgeWeights, const FieldConstraints& constraints)
{
  Problem problem;
  if (static_cast<int>(edgeWeights.size()) != mesh.edgeCount())
  {
    throw Error("there must be one Laplacian weight per edge");
  }
  problem.dirichlet = sortedDirichlet(constraints, mesh.vertexCount());
  problem.softMode = !constraints.soft.empty();
  if (constraints.formulation != SoftConstraintFormulation::PointValues &&
    constraints.formulation != SoftConstraintFormulation::LeastSquares)
  {
    throw Error("unknown soft constraint formulation");
  }
  problem.squared = problem.softMode && constraints.formulation == SoftConstraintFormulation::LeastSquares;
  if (problem.dirichlet.empty() && !problem.softMode)
  {
    throw Error("the field has no constraint");
  }
  if (problem.softMode && !(constraints.softWeight > 0.0 && std::isfinite(constraints.softWeight)))
  {
    throw Error("the soft constraint weight must be a positive number");
  }
  for (std::size_t i = 0; i < constraints.soft.size(); ++i)
  {
    const SoftConstraint& s = constraints.soft[i];
    const int faces =
      constraints.softTriangles ? static_cast<int>(constraints.softTriangles->size()) : mesh.faceCount();
    if (s.face < 0 || s.face >= faces)
    {
      throw Error("soft constraint " + std::to_string(i) + " lies on face " + std::to_string(s.face) +
        ", which is not a face of the mesh");
    }
    for (int corner : softCorners(mesh, constraints, s))
    {
      if (corner < 0 || corner >= mesh.vertexCount() || mesh.vertexComponent(corner) < 0)
      {
        throw Error("soft constraint " + std::to_string(i) + " lies on a triangle whose corner " +
          std::to_string(corner) + " is not a vertex of the solver's triangles");
      }
    }
    if (!s.barycentric.allFinite() || !std::isfinite(s.value))
    {
      throw Error("soft constraint " + std::to_string(i) + " has a NaN or infinite coordinate or value");
    }
  }

  // Every component needs a constraint, or its field is undefined.
  problem.hasHard.assign(mesh.componentCount(), 0);
  std::vector<char> constrained(mesh.componentCount(), 0);
  for (const auto& d : problem.dirichlet)
  {
    if (mesh.vertexComponent(d.first) >= 0)
    {
      problem.hasHard[mesh.vertexComponent(d.first)] = 1;
      constrained[mesh.vertexComponent(d.first)] = 1;
    }
  }
  for (const SoftConstraint& s : constraints.soft)
  {
    constrained[softComponent(mesh, constraints, s)] = 1;
  }
  for (int c = 0; c < mesh.componentCount(); ++c)
  {
    if (!constrained[c])
    {
      int faces = 0;
      for (int f = 0; f < mesh.faceCount(); ++f)
      {
        faces += mesh.faceComponent(f) == c ? 1 : 0;
      }
      throw Error("connected component " + std::to_string(c) + " (" + std::to_string(faces) +
        " triangles) has no constraint, so its field is undefined");
    }
  }
  for (const auto& d : problem.dirichlet)
  {
    problem.dirichletVertices.push_back(d.first);
    problem.hardValues.push_back(d.second);
  }
  return problem;
}

bool HarmonicFieldSolver::factorIfChanged(
  const TriangleMesh& mesh, const std::vector<double>& edgeWeights, const Problem& problem)
{
  Cache& cache = *this->State;
  const int n = mesh.vertexCount();
  // The factored term depends on the operator, the hard vertices and the mode.
  const bool operatorChanged =
    cache.vertexCount != n || cache.triangles != mesh.triangles() || cache.weights != edgeWeights;
  if (!operatorChanged && cache.factored && cache.dirichlet == problem.dirichletVertices &&
    cache.softMode == problem.softMode && cache.squared == problem.squared)
  {
    return false;
  }
  cache.factored = false;
  cache.prepared = false;
  cache.hardSolved = false;
  if (operatorChanged)
  {
    cache.laplacian = assembleLaplacian(mesh, edgeWeights);
    cache.vertexCount = n;
    cache.triangles = mesh.triangles();
    cache.weights = edgeWeights;
  }
  cache.dirichlet = problem.dirichletVertices;
  cache.softMode = problem.softMode;
  cache.squared = problem.squared;
  std::vector<char> isHard(n, 0);
  for (int v : problem.dirichletVertices)
  {
    isHard[v] = 1;
  }
  // Rows: every non-hard vertex used by a triangle. Columns: the same but the pins.
  std::vector<int> row(n, -1);
  int rows = 0;
  cache.column.assign(n, -1);
  cache.columnVertices.clear();
  cache.offsetIndex.assign(mesh.componentCount(), -1);
  cache.offsets = 0;
  for (int v = 0; v < n; ++v)
  {
    if (isHard[v] || mesh.vertexFaces(v).empty())
    {
      continue;
    }
    const int c = mesh.vertexComponent(v);
    if (problem.softMode && !problem.hasHard[c] && cache.offsetIndex[c] < 0)
    {
      cache.offsetIndex[c] = cache.offsets++; // v is the component's pin
      if (problem.squared)
      {
        row[v] = rows++;
      }
      continue;
    }
    row[v] = rows++;
    cache.column[v] = static_cast<int>(cache.columnVertices.size());
    cache.columnVertices.push_back(v);
  }
  std::vector<int> hardIndex(n, -1);
  for (std::size_t i = 0; i < problem.dirichletVertices.size(); ++i)
  {
    hardIndex[problem.dirichletVertices[i]] = static_cast<int>(i);
  }
  const int columns = cache.columns();
  cache.rowsFree = submatrix(cache.laplacian, row, rows, cache.column, columns);
  cache.rowsHard = submatrix(cache.laplacian, row, rows, hardIndex, static_cast<int>(problem.dirichletVertices.size()));
  if (problem.squared)
  {
    // SeamCut, Eq. 1: the squared Laplacian of the non-hard rows.
    cache.base = Eigen::SparseMatrix<double>(cache.rowsFree.transpose()) * cache.rowsFree;
  }
  else
  {
    cache.base = cache.rowsFree; // square: rows and columns are the free vertices
  }
  cache.base.makeCompressed();
  // AMD: its ordering costs less than the fill it leaves (see SparseCholesky::Ordering), except
  // on large meshes, where the geometric nested dissection halves the flops (and, for the
  // squared Laplacian, shortens what a new stroke's columns sweep).
  bool factored = true;
  if (columns > 0 && columns >= (problem.squared ? this->GeometricSquaredRows : this->GeometricRows))
  {
    std::vector<Vector3> points(static_cast<std::size_t>(columns));
    for (int c = 0; c < columns; ++c)
    {
      points[c] = mesh.point(cache.columnVertices[c]);
    }
    factored = cache.cholesky.factor(cache.base, geometricNestedDissection(points, cache.base));
  }
  else if (columns > 0)
  {
    factored = cache.cholesky.factor(cache.base, SparseCholesky::Ordering::AMD);
  }
  if (!factored)
  {
    throw Error("the Laplacian system could not be factored (it is not positive definite)");
  }
  cache.factored = true;
  return true;
}

Eigen::VectorXd HarmonicFieldSolver::solveHardValues(const Problem& problem)
{
  Cache& cache = *this->State;
  const int columns = cache.columns();
  // The hard values' part of the right-hand side and its solution x_D = B^-1 b_D.
  const Eigen::VectorXd hard =
    Eigen::Map<const Eigen::VectorXd>(problem.hardValues.data(), static_cast<Eigen::Index>(problem.hardValues.size()));
  Eigen::VectorXd hardRhs = Eigen::VectorXd::Zero(columns);
  if (!problem.dirichlet.empty() && columns > 0)
  {
    const Eigen::VectorXd flux = cache.rowsHard * hard;
    hardRhs = problem.squared ? Eigen::VectorXd(-(cache.rowsFree.transpose() * flux)) : Eigen::VectorXd(-flux);
  }
  if (!cache.hardSolved || cache.hardValues != problem.hardValues)
  {
    cache.hardSolution =
      columns > 0 && !problem.dirichlet.empty() ? cache.cholesky.solve(hardRhs) : Eigen::VectorXd::Zero(columns);
    cache.hardValues = problem.hardValues;
    cache.hardSolved = true;
  }
  return hardRhs;
}

bool HarmonicFieldSolver::prepareSoftConstraints(
  const TriangleMesh& mesh, const FieldConstraints& constraints, bool direct)
{
  Cache& cache = *this->State;
  std::vector<Triangle> corners;
  for (const SoftConstraint& s : constraints.soft)
  {
    corners.push_back(softCorners(mesh, constraints, s));
  }
  if (cache.prepared && cache.direct == direct && sameSoftLocations(cache.softLocations, constraints.soft) &&
    cache.softCornerList == corners && cache.softWeight == constraints.softWeight &&
    cache.formulation == constraints.formulation)
  {
    return false;
  }
  const int columns = cache.columns();
  const int k = static_cast<int>(constraints.soft.size());
  // Built aside and kept only once all of it exists, so a failure leaves no half update.
  cache.prepared = false;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < k; ++i)
  {
    const SoftConstraint& s = constraints.soft[i];
    for (int j = 0; j < 3; ++j)
    {
      const int c = cache.column[softCorners(mesh, constraints, s)[j]];
      if (c >= 0 && s.barycentric[j] != 0.0)
      {
        entries.emplace_back(c, i, penaltyWeight(constraints) * s.barycentric[j]);
      }
    }
  }
  Eigen::SparseMatrix<double> u(columns, k);
  u.setFromTriplets(entries.begin(), entries.end());
  u.makeCompressed();
  SparseCholesky::LowRank lowRank;
  Eigen::LLT<Eigen::MatrixXd> capacitance;
  if (direct)
  {
    this->factorWithConstraints(mesh, constraints, u);
  }
  else
  {
    // New constraint locations: A^-1 U and the capacitance matrix I + U^T A^-1 U.
    if (columns > 0)
    {
      lowRank = cache.cholesky.prepare(u);
    }
    Eigen::MatrixXd matrix = Eigen::MatrixXd::Identity(k, k);
    if (columns > 0)
    {
      matrix += lowRank.gram;
    }
    capacitance.compute(matrix);
    if (capacitance.info() != Eigen::Success)
    {
      throw Error("the constraints' capacitance matrix could not be factored");
    }
    cache.capacitance = std::move(capacitance);
  }
  std::vector<SoftConstraint> locations = constraints.soft;
  cache.u = std::move(u);
  cache.lowRank = std::move(lowRank);
  cache.direct = direct;
  cache.softLocations = std::move(locations);
  cache.softCornerList = std::move(corners);
  cache.softWeight = constraints.softWeight;
  cache.formulation = constraints.formulation;
  cache.prepared = true;
  return true;
}

void HarmonicFieldSolver::factorWithConstraints(
  const TriangleMesh& mesh, const FieldConstraints& constraints, const Eigen::SparseMatrix<double>& u)
{
  Cache& cache = *this->State;
  const int columns = cache.columns();
  const int k = static_cast<int>(constraints.soft.size());
  // The offsets' coupling w U E: column c sums the constraint columns of component c.
  std::vector<Eigen::Triplet<double>> byComponent;
  std::vector<double> counts(cache.offsets, 0.0);
  for (int i = 0; i < k; ++i)
  {
    const int c = cache.offsetIndex[softComponent(mesh, constraints, constraints.soft[i])];
    if (c >= 0)
    {
      byComponent.emplace_back(i, c, penaltyWeight(constraints));
      counts[c] += 1.0;
    }
  }
  Eigen::SparseMatrix<double> wE(k, cache.offsets);
  wE.setFromTriplets(byComponent.begin(), byComponent.end());
  const Eigen::SparseMatrix<double> coupling = u * wE;
  const Eigen::SparseMatrix<double> corner = Eigen::SparseMatrix<double>(cache.base + u * u.transpose());
  std::vector<Eigen::Triplet<double>> whole;
  whole.reserve(static_cast<std::size_t>(corner.nonZeros() + 2 * coupling.nonZeros() + cache.offsets));
  for (int c = 0; c < corner.outerSize(); ++c)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(corner, c); it; ++it)
    {
      whole.emplace_back(static_cast<int>(it.row()), c, it.value());
    }
  }
  for (int c = 0; c < coupling.outerSize(); ++c)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(coupling, c); it; ++it)
    {
      whole.emplace_back(static_cast<int>(it.row()), columns + c, it.value());
      whole.emplace_back(columns + c, static_cast<int>(it.row()), it.value());
    }
  }
  for (int c = 0; c < cache.offsets; ++c)
  {
    whole.emplace_back(columns + c, columns + c, penaltyWeight(constraints) * penaltyWeight(constraints) * counts[c]);
  }
  Eigen::SparseMatrix<double> system(columns + cache.offsets, columns + cache.offsets);
  system.setFromTriplets(whole.begin(), whole.end());
  system.makeCompressed();
  if (!cache.directCholesky.factor(system))
  {
    throw Error("the system with the constraints could not be factored");
  }
}

void HarmonicFieldSolver::solveSoftConstraints(const TriangleMesh& mesh, const FieldConstraints& constraints,
  const Problem& problem, const Eigen::VectorXd& hardRhs, Eigen::VectorXd& x, std::vector<double>& offset) const
{
  const Cache& cache = *this->State;
  const int columns = cache.columns();
  const int k = static_cast<int>(constraints.soft.size());
  // q = w (c - C_D f_D) - U^T x_D; E marks each constraint's component offset.
  Eigen::VectorXd q(k);
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(k, cache.offsets);
  for (int i = 0; i < k; ++i)
  {
    const SoftConstraint& s = constraints.soft[i];
    double known = 0.0;
    for (int j = 0; j < 3; ++j)
    {
      if (const auto* hard = findHard(problem.dirichlet, softCorners(mesh, constraints, s)[j]))
      {
        known += s.barycentric[j] * hard->second;
      }
    }
    q[i] = penaltyWeight(constraints) * (s.value - known);
    const int c = cache.offsetIndex[softComponent(mesh, constraints, s)];
    if (c >= 0)
    {
      E(i, c) = 1.0;
    }
  }
  if (cache.direct)
  {
    // The normal equations of ||R x - r||^2 + ||U^T x + w E alpha - q||^2, as a whole.
    Eigen::VectorXd rhs(columns + cache.offsets);
    rhs.head(columns) = hardRhs + cache.u * q;
    rhs.tail(cache.offsets) = penaltyWeight(constraints) * (E.transpose() * q);
    const Eigen::VectorXd whole = cache.directCholesky.solve(rhs);
    x = whole.head(columns);
    for (int c = 0; c < cache.offsets; ++c)
    {
      offset[c] = whole[columns + c];
    }
    return;
  }
  if (columns > 0)
  {
    q -= cache.u.transpose() * x;
  }
  // Offsets of the pinned components: alpha = (w E^T K E)^-1 E^T K q, K = (I + W)^-1.
  Eigen::VectorXd alpha = Eigen::VectorXd::Zero(cache.offsets);
  if (cache.offsets > 0)
  {
    const Eigen::MatrixXd KE = cache.capacitance.solve(E);
    alpha = (penaltyWeight(constraints) * (E.transpose() * KE)).ldlt().solve(KE.transpose() * q);
  }
  // The free values: x = x_D + A^-1 U s with s = K (q - w E alpha).
  const Eigen::VectorXd shift = cache.capacitance.solve(q - penaltyWeight(constraints) * (E * alpha));
  if (columns > 0)
  {
    x += cache.cholesky.apply(cache.lowRank, shift);
  }
  for (int c = 0; c < cache.offsets; ++c)
  {
    offset[c] = alpha[c];
  }
}

double HarmonicFieldSolver::relativeResidual(const TriangleMesh& mesh, const FieldConstraints& constraints,
  const Problem& problem, const Eigen::VectorXd& hardRhs, const Eigen::VectorXd& x,
  const std::vector<double>& offset) const
{
  const Cache& cache = *this->State;
  if (cache.columns() == 0)
  {
    return 0.0;
  }
  // The normal equations of the whole least-squares problem. The factored matrix is symmetric:
  // its transpose's product reads it column by column without scattered writes.
  Eigen::VectorXd residual = cache.base.transpose() * x - hardRhs;
  double scale = hardRhs.norm();
  if (problem.softMode)
  {
    // The constraint term at the solution, u including the component offsets.
    const int k = static_cast<int>(constraints.soft.size());
    Eigen::VectorXd misfit(k);
    for (int i = 0; i < k; ++i)
    {
      const SoftConstraint& s = constraints.soft[i];
      double value = 0.0;
      for (int j = 0; j < 3; ++j)
      {
        const int v = softCorners(mesh, constraints, s)[j];
        const int c = cache.column[v];
        const int o = cache.offsetIndex[softComponent(mesh, constraints, s)];
        const auto* hard = findHard(problem.dirichlet, v);
        const double hardValue = hard ? hard->second : 0.0;
        value += s.barycentric[j] * ((c >= 0 ? x[c] : hardValue) + (o >= 0 ? offset[o] : 0.0));
      }
      misfit[i] = penaltyWeight(constraints) * (value - s.value);
    }
    residual += cache.u * misfit;
    scale += (cache.u * Eigen::VectorXd::Ones(k)).norm();
  }
  return scale > 0.0 ? residual.norm() / scale : residual.norm();
}

std::vector<double> HarmonicFieldSolver::assembleField(
  const TriangleMesh& mesh, const Problem& problem, const Eigen::VectorXd& x, const std::vector<double>& offset) const
{
  const Cache& cache = *this->State;
  std::vector<double> field(mesh.vertexCount(), 0.0);
  for (const auto& d : problem.dirichlet)
  {
    field[d.first] = d.second;
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    if (cache.column[v] >= 0)
    {
      field[v] = x[cache.column[v]];
    }
    const int c = mesh.vertexComponent(v);
    if (c >= 0 && cache.offsetIndex[c] >= 0 &&
      !std::binary_search(problem.dirichletVertices.begin(), problem.dirichletVertices.end(), v))
    {
      field[v] += offset[cache.offsetIndex[c]];
    }
  }
  return field;
}

HarmonicFieldSolution HarmonicFieldSolver::solve(
  const TriangleMesh& mesh, const std::vector<double>& edgeWeights, const FieldConstraints& constraints)
{
  const Problem problem = checkProblem(mesh, edgeWeights, constraints);
  HarmonicFieldSolution solution;
  solution.work = this->factorIfChanged(mesh, edgeWeights, problem) ? HarmonicFieldSolution::Work::Factorization
                                                                    : HarmonicFieldSolution::Work::BackSubstitution;
  const Eigen::VectorXd hardRhs = this->solveHardValues(problem);
  const Cache& cache = *this->State;
  Eigen::VectorXd x = cache.hardSolution;
  std::vector<double> offset(cache.offsets, 0.0);
  if (problem.softMode)
  {
    // Many constraints make the dense k x k capacitance matrix cost more than factoring the
    // whole system: past DirectConstraintCount constraints, or more than half the unknowns, the
    // constraint term is added to B and factored with it.
    const int k = static_cast<int>(constraints.soft.size());
    const bool direct = cache.columns() > 0 && (k > DirectConstraintCount || 2 * k > cache.columns());
    if (this->prepareSoftConstraints(mesh, constraints, direct) &&
      solution.work == HarmonicFieldSolution::Work::BackSubstitution)
    {
      solution.work = HarmonicFieldSolution::Work::Update;
    }
    this->solveSoftConstraints(mesh, constraints, problem, hardRhs, x, offset);
  }
  if (!x.allFinite())
  {
    throw Error("the solve produced NaN values");
  }
  solution.relativeResidual = this->relativeResidual(mesh, constraints, problem, hardRhs, x, offset);
  solution.field = this->assembleField(mesh, problem, x, offset);
  return solution;
}

std::vector<double> clampToConstraintRange(const std::vector<double>& field, const FieldConstraints& constraints)
{
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const double value : constraints.dirichletValues)
  {
    low = std::min(low, value);
    high = std::max(high, value);
  }
  for (const SoftConstraint& constraint : constraints.soft)
  {
    low = std::min(low, constraint.value);
    high = std::max(high, constraint.value);
  }
  std::vector<double> clamped = field;
  if (low <= high)
  {
    for (double& value : clamped)
    {
      value = std::clamp(value, low, high);
    }
  }
  return clamped;
}

} // namespace kerf
