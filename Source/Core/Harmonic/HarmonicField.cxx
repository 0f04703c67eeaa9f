// The harmonic-field solver: validation, cached factorizations, low-rank corrections for soft constraints.
#include "Harmonic/HarmonicField.h"

#include "Error.h"
#include "Harmonic/LaplacianWeights.h"
#include "Mesh/MeshValidation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace kerf
{

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

// Hard values sorted by vertex, with conflicting duplicates refused.
std::vector<std::pair<int, double>> sortedDirichlet(const FieldConstraints& c, int vertexCount)
{
  if (c.dirichletVertices.size() != c.dirichletValues.size())
  {
    throw Error("the hard constraints have " + std::to_string(c.dirichletVertices.size()) +
      " vertices but " + std::to_string(c.dirichletValues.size()) + " values");
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
} // namespace

struct HarmonicFieldSolver::Cache
{
  // What the factorization was built from.
  int vertexCount = -1;
  std::vector<Triangle> triangles;
  std::vector<double> weights;
  std::vector<int> dirichlet; // sorted vertices
  bool softMode = false;
  bool factored = false;

  // Unknowns: `column[v]` indexes vertex v among the free columns, or is -1 for hard and pinned
  // vertices and points used by no triangle. In soft mode the rows are all non-hard vertices and
  // one vertex per component without hard values is pinned; its component's offset is a separate
  // unknown (one entry of `offsetComponent`).
  std::vector<int> column;
  std::vector<int> columnVertices;
  std::vector<int> offsetIndex; // component -> offset unknown, or -1
  int offsets = 0;
  Eigen::SparseMatrix<double> laplacian;
  Eigen::SparseMatrix<double> rowsFree, rowsHard; // L_RF and L_RD
  Eigen::SparseMatrix<double> base;               // L_FF, or L_RF^T L_RF
  SparseCholesky cholesky;

  // Hard-value part, for the current hard values.
  std::vector<double> hardValues;
  Eigen::VectorXd hardSolution; // B^-1 b_D
  bool hardSolved = false;

  // Soft part, for the current constraint locations and weight.
  std::vector<SoftConstraint> softLocations; // values ignored
  double softWeight = 0.0;
  bool prepared = false;
  bool direct = false;           // the prepared form: Woodbury (false) or the direct factor
  Eigen::SparseMatrix<double> u; // w C_F^T
  SparseCholesky::LowRank lowRank;
  Eigen::LLT<Eigen::MatrixXd> capacitance; // I + U^T B^-1 U
  // Many constraints: [B + U U^T, w U E; w E^T U^T, w^2 E^T E] over the free values and the
  // offsets, factored as a whole.
  SparseCholesky directCholesky;
};

HarmonicFieldSolver::HarmonicFieldSolver()
  : State(new Cache)
{
}

HarmonicFieldSolver::~HarmonicFieldSolver() = default;

void HarmonicFieldSolver::reset()
{
  this->State.reset(new Cache);
}

HarmonicFieldSolution HarmonicFieldSolver::solve(
  const TriangleMesh& mesh, const std::vector<double>& edgeWeights, const FieldConstraints& constraints)
{
  Cache& cache = *this->State;
  const int n = mesh.vertexCount();
  if (static_cast<int>(edgeWeights.size()) != mesh.edgeCount())
  {
    throw Error("there must be one Laplacian weight per edge");
  }
  const std::vector<std::pair<int, double>> dirichlet = sortedDirichlet(constraints, n);
  const bool softMode = !constraints.soft.empty();
  if (dirichlet.empty() && !softMode)
  {
    throw Error("the field has no constraint");
  }
  if (softMode && !(constraints.softWeight > 0.0 && std::isfinite(constraints.softWeight)))
  {
    throw Error("the soft constraint weight must be a positive number");
  }
  for (std::size_t i = 0; i < constraints.soft.size(); ++i)
  {
    const SoftConstraint& s = constraints.soft[i];
    if (s.face < 0 || s.face >= mesh.faceCount())
    {
      throw Error("soft constraint " + std::to_string(i) + " lies on face " + std::to_string(s.face) +
        ", which is not a face of the mesh");
    }
    if (!s.barycentric.allFinite() || !std::isfinite(s.value))
    {
      throw Error("soft constraint " + std::to_string(i) + " has a NaN or infinite coordinate or value");
    }
  }

  // Every component needs a constraint, or its field is undefined.
  std::vector<char> hasHard(mesh.componentCount(), 0), constrained(mesh.componentCount(), 0);
  for (const auto& d : dirichlet)
  {
    if (mesh.vertexComponent(d.first) >= 0)
    {
      hasHard[mesh.vertexComponent(d.first)] = 1;
      constrained[mesh.vertexComponent(d.first)] = 1;
    }
  }
  for (const SoftConstraint& s : constraints.soft)
  {
    constrained[mesh.faceComponent(s.face)] = 1;
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

  HarmonicFieldSolution solution;
  solution.work = HarmonicFieldSolution::Work::BackSubstitution;
  std::vector<int> dirichletVertices;
  std::vector<double> hardValues;
  for (const auto& d : dirichlet)
  {
    dirichletVertices.push_back(d.first);
    hardValues.push_back(d.second);
  }

  // The factored term depends on the operator, the hard vertices and the mode.
  const bool operatorChanged = cache.vertexCount != n || cache.triangles != mesh.triangles() ||
    cache.weights != edgeWeights;
  if (operatorChanged || !cache.factored || cache.dirichlet != dirichletVertices || cache.softMode != softMode)
  {
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
    cache.dirichlet = dirichletVertices;
    cache.softMode = softMode;
    std::vector<char> isHard(n, 0);
    for (int v : dirichletVertices)
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
      row[v] = rows++;
      const int c = mesh.vertexComponent(v);
      if (softMode && !hasHard[c] && cache.offsetIndex[c] < 0)
      {
        cache.offsetIndex[c] = cache.offsets++; // v is the component's pin
        continue;
      }
      cache.column[v] = static_cast<int>(cache.columnVertices.size());
      cache.columnVertices.push_back(v);
    }
    std::vector<int> hardIndex(n, -1);
    for (std::size_t i = 0; i < dirichletVertices.size(); ++i)
    {
      hardIndex[dirichletVertices[i]] = static_cast<int>(i);
    }
    std::vector<Eigen::Triplet<double>> free, hard;
    for (int v = 0; v < n; ++v)
    {
      for (Eigen::SparseMatrix<double>::InnerIterator it(cache.laplacian, v); it; ++it)
      {
        const int r = row[static_cast<int>(it.row())];
        if (r < 0)
        {
          continue;
        }
        if (cache.column[v] >= 0)
        {
          free.emplace_back(r, cache.column[v], it.value());
        }
        else if (hardIndex[v] >= 0)
        {
          hard.emplace_back(r, hardIndex[v], it.value());
        }
      }
    }
    const int columns = static_cast<int>(cache.columnVertices.size());
    cache.rowsFree.resize(rows, columns);
    cache.rowsFree.setFromTriplets(free.begin(), free.end());
    cache.rowsHard.resize(rows, static_cast<int>(dirichletVertices.size()));
    cache.rowsHard.setFromTriplets(hard.begin(), hard.end());
    if (softMode)
    {
      // seamcut.txt Eq. 1: the squared Laplacian of the non-hard rows.
      cache.base = Eigen::SparseMatrix<double>(cache.rowsFree.transpose()) * cache.rowsFree;
    }
    else
    {
      cache.base = cache.rowsFree; // square: rows and columns are the free vertices
    }
    cache.base.makeCompressed();
    if (columns > 0 && !cache.cholesky.factor(cache.base))
    {
      throw Error("the Laplacian system could not be factored (it is not positive definite)");
    }
    cache.factored = true;
    solution.work = HarmonicFieldSolution::Work::Factorization;
  }
  const int columns = static_cast<int>(cache.columnVertices.size());

  // The hard values' part of the right-hand side and its solution x_D = B^-1 b_D.
  const Eigen::VectorXd hard = Eigen::Map<const Eigen::VectorXd>(hardValues.data(), static_cast<Eigen::Index>(hardValues.size()));
  Eigen::VectorXd hardRhs = Eigen::VectorXd::Zero(columns);
  if (!dirichlet.empty() && columns > 0)
  {
    const Eigen::VectorXd flux = cache.rowsHard * hard;
    hardRhs = softMode ? Eigen::VectorXd(-(cache.rowsFree.transpose() * flux)) : Eigen::VectorXd(-flux);
  }
  if (!cache.hardSolved || cache.hardValues != hardValues)
  {
    cache.hardSolution = columns > 0 && !dirichlet.empty() ? cache.cholesky.solve(hardRhs) : Eigen::VectorXd::Zero(columns);
    cache.hardValues = hardValues;
    cache.hardSolved = true;
  }

  Eigen::VectorXd x = cache.hardSolution;
  std::vector<double> offset(cache.offsets, 0.0);
  const int k = static_cast<int>(constraints.soft.size());
  if (softMode)
  {
    // Many constraints make the dense k x k capacitance matrix cost more than factoring the
    // whole system: past DirectConstraintCount constraints, or more than half the unknowns, the
    // constraint term is added to B and factored with it.
    const bool direct = columns > 0 && (k > DirectConstraintCount || 2 * k > columns);
    // New constraint locations: A^-1 U and the capacitance matrix I + U^T A^-1 U.
    if (!cache.prepared || cache.direct != direct || !sameSoftLocations(cache.softLocations, constraints.soft) ||
      cache.softWeight != constraints.softWeight)
    {
      // Built aside and kept only once all of it exists, so a failure leaves no half update.
      cache.prepared = false;
      std::vector<Eigen::Triplet<double>> entries;
      for (int i = 0; i < k; ++i)
      {
        const SoftConstraint& s = constraints.soft[i];
        for (int j = 0; j < 3; ++j)
        {
          const int c = cache.column[mesh.triangle(s.face)[j]];
          if (c >= 0 && s.barycentric[j] != 0.0)
          {
            entries.emplace_back(c, i, constraints.softWeight * s.barycentric[j]);
          }
        }
      }
      Eigen::SparseMatrix<double> u(columns, k);
      u.setFromTriplets(entries.begin(), entries.end());
      u.makeCompressed();
      SparseCholesky::LowRank lowRank;
      Eigen::LLT<Eigen::MatrixXd> factored;
      if (direct)
      {
        // The offsets' coupling w U E: column c sums the constraint columns of component c.
        std::vector<Eigen::Triplet<double>> byComponent;
        std::vector<double> counts(cache.offsets, 0.0);
        for (int i = 0; i < k; ++i)
        {
          const int c = cache.offsetIndex[mesh.faceComponent(constraints.soft[i].face)];
          if (c >= 0)
          {
            byComponent.emplace_back(i, c, constraints.softWeight);
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
          whole.emplace_back(columns + c, columns + c, constraints.softWeight * constraints.softWeight * counts[c]);
        }
        Eigen::SparseMatrix<double> system(columns + cache.offsets, columns + cache.offsets);
        system.setFromTriplets(whole.begin(), whole.end());
        system.makeCompressed();
        if (!cache.directCholesky.factor(system))
        {
          throw Error("the system with the constraints could not be factored");
        }
      }
      else
      {
        if (columns > 0)
        {
          lowRank = cache.cholesky.prepare(u);
        }
        Eigen::MatrixXd capacitance = Eigen::MatrixXd::Identity(k, k);
        if (columns > 0)
        {
          capacitance += lowRank.gram;
        }
        factored.compute(capacitance);
        if (factored.info() != Eigen::Success)
        {
          throw Error("the constraints' capacitance matrix could not be factored");
        }
      }
      std::vector<SoftConstraint> locations = constraints.soft;
      cache.u = std::move(u);
      cache.lowRank = std::move(lowRank);
      cache.capacitance = std::move(factored);
      cache.direct = direct;
      cache.softLocations = std::move(locations);
      cache.softWeight = constraints.softWeight;
      cache.prepared = true;
      if (solution.work == HarmonicFieldSolution::Work::BackSubstitution)
      {
        solution.work = HarmonicFieldSolution::Work::Update;
      }
    }
    // q = w (c - C_D f_D) - U^T x_D; E marks each constraint's component offset.
    Eigen::VectorXd q(k);
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(k, cache.offsets);
    for (int i = 0; i < k; ++i)
    {
      const SoftConstraint& s = constraints.soft[i];
      double known = 0.0;
      for (int j = 0; j < 3; ++j)
      {
        const int v = mesh.triangle(s.face)[j];
        const auto found = std::lower_bound(dirichlet.begin(), dirichlet.end(), std::make_pair(v, -HUGE_VAL));
        if (found != dirichlet.end() && found->first == v)
        {
          known += s.barycentric[j] * found->second;
        }
      }
      q[i] = constraints.softWeight * (s.value - known);
      const int c = cache.offsetIndex[mesh.faceComponent(s.face)];
      if (c >= 0)
      {
        E(i, c) = 1.0;
      }
    }
    if (direct)
    {
      // The normal equations of ||R x - r||^2 + ||U^T x + w E alpha - q||^2, as a whole.
      Eigen::VectorXd rhs(columns + cache.offsets);
      rhs.head(columns) = hardRhs + cache.u * q;
      rhs.tail(cache.offsets) = constraints.softWeight * (E.transpose() * q);
      const Eigen::VectorXd whole = cache.directCholesky.solve(rhs);
      x = whole.head(columns);
      for (int c = 0; c < cache.offsets; ++c)
      {
        offset[c] = whole[columns + c];
      }
    }
    else
    {
      if (columns > 0)
      {
        q -= cache.u.transpose() * x;
      }
      // Offsets of the pinned components: alpha = (w E^T K E)^-1 E^T K q, K = (I + W)^-1.
      Eigen::VectorXd alpha = Eigen::VectorXd::Zero(cache.offsets);
      if (cache.offsets > 0)
      {
        const Eigen::MatrixXd KE = cache.capacitance.solve(E);
        alpha = (constraints.softWeight * (E.transpose() * KE)).ldlt().solve(KE.transpose() * q);
      }
      // The free values: x = x_D + A^-1 U s with s = K (q - w E alpha).
      const Eigen::VectorXd shift = cache.capacitance.solve(q - constraints.softWeight * (E * alpha));
      if (columns > 0)
      {
        x += cache.cholesky.apply(cache.lowRank, shift);
      }
      for (int c = 0; c < cache.offsets; ++c)
      {
        offset[c] = alpha[c];
      }
    }
  }
  if (!x.allFinite())
  {
    throw Error("the solve produced NaN values");
  }

  // Relative residual of the normal equations of the whole least-squares problem.
  if (columns > 0)
  {
    // The factored matrix is symmetric: its transpose's product reads it column by column
    // without scattered writes.
    Eigen::VectorXd residual = cache.base.transpose() * x - hardRhs;
    if (softMode)
    {
      // The constraint term at the solution, u including the component offsets.
      Eigen::VectorXd misfit(k);
      for (int i = 0; i < k; ++i)
      {
        const SoftConstraint& s = constraints.soft[i];
        double value = 0.0;
        for (int j = 0; j < 3; ++j)
        {
          const int v = mesh.triangle(s.face)[j];
          const int c = cache.column[v];
          const int o = cache.offsetIndex[mesh.faceComponent(s.face)];
          const auto found = std::lower_bound(dirichlet.begin(), dirichlet.end(), std::make_pair(v, -HUGE_VAL));
          const double hardValue = found != dirichlet.end() && found->first == v ? found->second : 0.0;
          value += s.barycentric[j] * ((c >= 0 ? x[c] : hardValue) + (o >= 0 ? offset[o] : 0.0));
        }
        misfit[i] = constraints.softWeight * (value - s.value);
      }
      residual += cache.u * misfit;
      const double scale = hardRhs.norm() + (cache.u * Eigen::VectorXd::Ones(k)).norm();
      solution.relativeResidual = scale > 0.0 ? residual.norm() / scale : residual.norm();
    }
    else
    {
      const double scale = hardRhs.norm();
      solution.relativeResidual = scale > 0.0 ? residual.norm() / scale : residual.norm();
    }
  }

  solution.field.assign(n, 0.0);
  for (const auto& d : dirichlet)
  {
    solution.field[d.first] = d.second;
  }
  for (int v = 0; v < n; ++v)
  {
    if (cache.column[v] >= 0)
    {
      solution.field[v] = x[cache.column[v]];
    }
    const int c = mesh.vertexComponent(v);
    if (c >= 0 && cache.offsetIndex[c] >= 0 && !std::binary_search(dirichletVertices.begin(), dirichletVertices.end(), v))
    {
      solution.field[v] += offset[cache.offsetIndex[c]];
    }
  }
  return solution;
}

Vector3 faceGradient(const TriangleMesh& mesh, const std::vector<double>& field, int face)
{
  const Triangle& t = mesh.triangle(face);
  const Vector3& p0 = mesh.point(t[0]);
  const Vector3& p1 = mesh.point(t[1]);
  const Vector3& p2 = mesh.point(t[2]);
  // e_j is the edge opposite corner j, counter-clockwise; N = e_1 x e_2, |N| = 2A.
  const Vector3 e0 = p2 - p1;
  const Vector3 e1 = p0 - p2;
  const Vector3 e2 = p1 - p0;
  const Vector3 normal = e1.cross(e2);
  const double squaredTwiceArea = normal.squaredNorm();
  const double longest = std::max(std::max(e0.squaredNorm(), e1.squaredNorm()), e2.squaredNorm());
  if (squaredTwiceArea <= ZeroAreaTolerance * ZeroAreaTolerance * longest * longest)
  {
    return Vector3::Zero();
  }
  // roi-scissor.txt 4.2: sum_j f_j (n x e_j) / 2A = N x (sum_j f_j e_j) / |N|^2.
  return normal.cross(field[t[0]] * e0 + field[t[1]] * e1 + field[t[2]] * e2) * (1.0 / squaredTwiceArea);
}

std::vector<Vector3> computeFaceGradients(const TriangleMesh& mesh, const std::vector<double>& field)
{
  std::vector<Vector3> gradients(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f)
  {
    gradients[f] = faceGradient(mesh, field, f);
  }
  return gradients;
}

} // namespace kerf
