// The harmonic-field solver: validation, cached factorizations, rank updates for soft constraints.
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
  std::vector<SoftConstraint> softLocations; // values ignored
  double softWeight = 0.0;
  bool factored = false;
  bool updated = false;

  // Derived operators.
  Eigen::SparseMatrix<double> laplacian;
  std::vector<int> freeIndex; // vertex -> unknown, or -1
  std::vector<int> freeVertices;
  Eigen::SparseMatrix<double> lff, lfd, base, u;
  Eigen::SparseMatrix<double> pins; // free x components: sqrt(delta) at each pinned vertex
  SparseCholesky cholesky;
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
  std::vector<char> constrained(mesh.componentCount(), 0);
  for (const auto& d : dirichlet)
  {
    if (mesh.vertexComponent(d.first) >= 0)
    {
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
  for (const auto& d : dirichlet)
  {
    dirichletVertices.push_back(d.first);
  }
  const bool operatorChanged = cache.vertexCount != n || cache.triangles != mesh.triangles() ||
    cache.weights != edgeWeights;
  if (operatorChanged || !cache.factored || cache.dirichlet != dirichletVertices || cache.softMode != softMode)
  {
    cache.factored = false;
    cache.updated = false;
    if (operatorChanged)
    {
      cache.laplacian = assembleLaplacian(mesh, edgeWeights);
      cache.vertexCount = n;
      cache.triangles = mesh.triangles();
      cache.weights = edgeWeights;
    }
    cache.dirichlet = dirichletVertices;
    cache.softMode = softMode;
    cache.freeIndex.assign(n, -1);
    cache.freeVertices.clear();
    std::vector<char> isDirichlet(n, 0);
    for (int v : dirichletVertices)
    {
      isDirichlet[v] = 1;
    }
    for (int v = 0; v < n; ++v)
    {
      if (!isDirichlet[v] && !mesh.vertexFaces(v).empty())
      {
        cache.freeIndex[v] = static_cast<int>(cache.freeVertices.size());
        cache.freeVertices.push_back(v);
      }
    }
    // L_FF and L_FD from the Laplacian's columns.
    std::vector<int> dirichletIndex(n, -1);
    for (std::size_t i = 0; i < dirichletVertices.size(); ++i)
    {
      dirichletIndex[dirichletVertices[i]] = static_cast<int>(i);
    }
    std::vector<Eigen::Triplet<double>> ff, fd;
    for (int col = 0; col < n; ++col)
    {
      for (Eigen::SparseMatrix<double>::InnerIterator it(cache.laplacian, col); it; ++it)
      {
        const int row = cache.freeIndex[static_cast<int>(it.row())];
        if (row < 0)
        {
          continue;
        }
        if (cache.freeIndex[col] >= 0)
        {
          ff.emplace_back(row, cache.freeIndex[col], it.value());
        }
        else if (dirichletIndex[col] >= 0)
        {
          fd.emplace_back(row, dirichletIndex[col], it.value());
        }
      }
    }
    const int free = static_cast<int>(cache.freeVertices.size());
    cache.lff.resize(free, free);
    cache.lff.setFromTriplets(ff.begin(), ff.end());
    cache.lfd.resize(free, static_cast<int>(dirichletVertices.size()));
    cache.lfd.setFromTriplets(fd.begin(), fd.end());
    if (softMode)
    {
      // seamcut.txt Eq. 1: the squared Laplacian of the free rows, pinned where no hard value is.
      cache.base = Eigen::SparseMatrix<double>(cache.lff.transpose()) * cache.lff;
      double meanDiagonal = 0.0;
      for (int i = 0; i < free; ++i)
      {
        meanDiagonal += cache.base.coeff(i, i);
      }
      meanDiagonal = free > 0 ? meanDiagonal / free : 1.0;
      std::vector<char> hasDirichlet(mesh.componentCount(), 0);
      for (int v : dirichletVertices)
      {
        if (mesh.vertexComponent(v) >= 0)
        {
          hasDirichlet[mesh.vertexComponent(v)] = 1;
        }
      }
      // The pins make the factored term definite; the update removes them again (a downdate),
      // once the soft constraints have made the system definite on their own.
      std::vector<Eigen::Triplet<double>> pinEntries;
      const double delta = 1e-10 * meanDiagonal;
      for (int v : cache.freeVertices)
      {
        const int c = mesh.vertexComponent(v);
        if (!hasDirichlet[c])
        {
          cache.base.coeffRef(cache.freeIndex[v], cache.freeIndex[v]) += delta;
          pinEntries.emplace_back(cache.freeIndex[v], static_cast<int>(pinEntries.size()), std::sqrt(delta));
          hasDirichlet[c] = 1; // one pin per component
        }
      }
      cache.pins.resize(free, static_cast<int>(pinEntries.size()));
      cache.pins.setFromTriplets(pinEntries.begin(), pinEntries.end());
    }
    else
    {
      cache.base = cache.lff;
    }
    cache.base.makeCompressed();
    if (free > 0 && !cache.cholesky.factor(cache.base))
    {
      throw Error("the Laplacian system could not be factored (it is not positive definite)");
    }
    cache.factored = true;
    solution.work = HarmonicFieldSolution::Work::Factorization;
  }

  const int free = static_cast<int>(cache.freeVertices.size());
  // Soft constraint rows C (k x n) split into free and hard columns.
  const int k = static_cast<int>(constraints.soft.size());
  Eigen::VectorXd hard(static_cast<int>(dirichlet.size()));
  for (std::size_t i = 0; i < dirichlet.size(); ++i)
  {
    hard[static_cast<int>(i)] = dirichlet[i].second;
  }
  if (softMode &&
    (!cache.updated || !sameSoftLocations(cache.softLocations, constraints.soft) ||
      cache.softWeight != constraints.softWeight))
  {
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < k; ++i)
    {
      const SoftConstraint& s = constraints.soft[i];
      for (int j = 0; j < 3; ++j)
      {
        const int column = cache.freeIndex[mesh.triangle(s.face)[j]];
        if (column >= 0 && s.barycentric[j] != 0.0)
        {
          entries.emplace_back(column, i, constraints.softWeight * s.barycentric[j]);
        }
      }
    }
    cache.u.resize(free, k);
    cache.u.setFromTriplets(entries.begin(), entries.end());
    cache.u.makeCompressed();
    if (free > 0 && !cache.cholesky.update(cache.u, &cache.pins))
    {
      throw Error("the factorization could not be updated with the soft constraints");
    }
    cache.softLocations = constraints.soft;
    cache.softWeight = constraints.softWeight;
    cache.updated = true;
    if (solution.work == HarmonicFieldSolution::Work::BackSubstitution)
    {
      solution.work = HarmonicFieldSolution::Work::Update;
    }
  }

  // Right-hand side.
  Eigen::VectorXd b = Eigen::VectorXd::Zero(free);
  if (!dirichlet.empty() && free > 0)
  {
    const Eigen::VectorXd flux = cache.lfd * hard;
    b = softMode ? Eigen::VectorXd(-(cache.lff.transpose() * flux)) : Eigen::VectorXd(-flux);
  }
  if (softMode)
  {
    // w^2 C_F^T (c - C_D f_D): U = w C_F^T, so this is U w (c - C_D f_D).
    Eigen::VectorXd target(k);
    for (int i = 0; i < k; ++i)
    {
      const SoftConstraint& s = constraints.soft[i];
      double known = 0.0;
      for (int j = 0; j < 3; ++j)
      {
        const int v = mesh.triangle(s.face)[j];
        if (cache.freeIndex[v] < 0)
        {
          const auto found = std::lower_bound(dirichlet.begin(), dirichlet.end(), std::make_pair(v, -HUGE_VAL));
          known += s.barycentric[j] * (found != dirichlet.end() && found->first == v ? found->second : 0.0);
        }
      }
      target[i] = constraints.softWeight * (s.value - known);
    }
    if (free > 0)
    {
      b += cache.u * target;
    }
  }

  Eigen::VectorXd x = free > 0 ? cache.cholesky.solve(b) : Eigen::VectorXd();
  if (!x.allFinite())
  {
    throw Error("the solve produced NaN values");
  }
  if (free > 0)
  {
    Eigen::VectorXd residual = cache.base * x - b;
    if (softMode)
    {
      residual += cache.u * (cache.u.transpose() * x) - cache.pins * (cache.pins.transpose() * x);
    }
    const double scale = b.norm();
    solution.relativeResidual = scale > 0.0 ? residual.norm() / scale : residual.norm();
  }

  solution.field.assign(n, 0.0);
  for (const auto& d : dirichlet)
  {
    solution.field[d.first] = d.second;
  }
  for (int i = 0; i < free; ++i)
  {
    solution.field[cache.freeVertices[i]] = x[i];
  }
  return solution;
}

Vector3 faceGradient(const TriangleMesh& mesh, const std::vector<double>& field, int face)
{
  const Triangle& t = mesh.triangle(face);
  const Vector3& p0 = mesh.point(t[0]);
  const Vector3& p1 = mesh.point(t[1]);
  const Vector3& p2 = mesh.point(t[2]);
  const Vector3 normal = (p1 - p0).cross(p2 - p0);
  const double twiceArea = normal.norm();
  const double longest = std::max({ (p1 - p0).squaredNorm(), (p2 - p1).squaredNorm(), (p0 - p2).squaredNorm() });
  if (twiceArea <= ZeroAreaTolerance * longest)
  {
    return Vector3::Zero();
  }
  const Vector3 n = normal / twiceArea;
  // e_j is the edge opposite corner j, counter-clockwise.
  return (field[t[0]] * n.cross(p2 - p1) + field[t[1]] * n.cross(p0 - p2) + field[t[2]] * n.cross(p1 - p0)) /
    twiceArea;
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
