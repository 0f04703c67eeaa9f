// CHOLMOD-backed sparse Cholesky with sparse multi-column forward solves for low-rank corrections.
#include "Harmonic/SparseCholesky.h"

#include "Error.h"

#include <algorithm>
#include <map>

#ifdef KERF_HAVE_CHOLMOD
#include <cholmod.h>
#else
#include <Eigen/SparseCholesky>
#endif

namespace kerf
{

#ifdef KERF_HAVE_CHOLMOD

namespace
{
// A cholmod_sparse view of a compressed column-major Eigen matrix (no copy).
cholmod_sparse cholmodView(const Eigen::SparseMatrix<double>& A, int stype)
{
  cholmod_sparse s{};
  s.nrow = static_cast<std::size_t>(A.rows());
  s.ncol = static_cast<std::size_t>(A.cols());
  s.nzmax = static_cast<std::size_t>(A.nonZeros());
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<double*>(A.valuePtr());
  s.stype = stype;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

cholmod_dense cholmodView(const double* values, std::size_t n)
{
  cholmod_dense d{};
  d.nrow = n;
  d.ncol = 1;
  d.nzmax = n;
  d.d = n;
  d.x = const_cast<double*>(values);
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}
} // namespace

struct SparseCholesky::Implementation
{
  cholmod_common common;
  cholmod_factor* factor = nullptr; // simplicial L D L^T after factor()
  std::vector<int> inversePermutation; // original row -> permuted row
  std::vector<int> parent;             // elimination tree
  mutable std::vector<int> position;   // workspace: permuted row -> index in a reach, or -1
  // L^-1 P u for the columns u of the last prepare(), keyed by u's entries: a constraint set that
  // keeps earlier columns (a refined cut) only solves for its new ones. Each column's values do
  // not depend on the others solved with it, so reuse gives the same bits as solving afresh.
  using ColumnKey = std::vector<std::pair<int, double>>;
  using Column = std::vector<std::pair<int, double>>; // permuted row, value
  mutable std::map<ColumnKey, Column> columns;

  Implementation()
  {
    cholmod_start(&this->common);
    this->common.print = 0;
    this->common.error_handler = nullptr;
  }
  ~Implementation()
  {
    if (this->factor)
    {
      cholmod_free_factor(&this->factor, &this->common);
    }
    cholmod_finish(&this->common);
  }
};

SparseCholesky::SparseCholesky()
  : Impl(new Implementation)
{
}

SparseCholesky::~SparseCholesky() = default;

std::string SparseCholesky::backend()
{
  return "CHOLMOD";
}

bool SparseCholesky::factor(const Eigen::SparseMatrix<double>& A)
{
  Implementation& m = *this->Impl;
  if (m.factor)
  {
    cholmod_free_factor(&m.factor, &m.common);
  }
  Eigen::SparseMatrix<double> compressed = A;
  compressed.makeCompressed();
  cholmod_sparse s = cholmodView(compressed, -1);
  // Nested dissection (METIS): less fill than AMD on surface meshes, and faster to factor.
  m.common.nmethods = 1;
  m.common.method[0].ordering = CHOLMOD_METIS;
  m.factor = cholmod_analyze(&s, &m.common);
  if (!m.factor)
  {
    return false;
  }
  // Supernodal numeric factorization (fast), then the simplicial L D L^T the sparse solves read.
  if (!cholmod_factorize(&s, m.factor, &m.common) || m.common.status != CHOLMOD_OK ||
    m.factor->minor < m.factor->n ||
    !cholmod_change_factor(CHOLMOD_REAL, 0, 0, 1, 1, m.factor, &m.common))
  {
    cholmod_free_factor(&m.factor, &m.common);
    return false;
  }
  const int n = static_cast<int>(m.factor->n);
  const int* perm = static_cast<const int*>(m.factor->Perm);
  const int* p = static_cast<const int*>(m.factor->p);
  const int* nz = static_cast<const int*>(m.factor->nz);
  const int* rows = static_cast<const int*>(m.factor->i);
  m.inversePermutation.assign(n, 0);
  m.parent.assign(n, -1);
  for (int j = 0; j < n; ++j)
  {
    m.inversePermutation[perm[j]] = j;
    // The parent of column j is the smallest row below the diagonal.
    for (int e = p[j] + 1; e < p[j] + nz[j]; ++e)
    {
      if (m.parent[j] < 0 || rows[e] < m.parent[j])
      {
        m.parent[j] = rows[e];
      }
    }
  }
  m.position.assign(n, -1);
  m.columns.clear();
  return true;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const
{
  Implementation& m = *this->Impl;
  if (!m.factor)
  {
    throw Error("no factorization to solve with");
  }
  cholmod_dense rhs = cholmodView(b.data(), static_cast<std::size_t>(b.size()));
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, m.factor, &rhs, &m.common);
  if (!x)
  {
    throw Error("the sparse solve failed");
  }
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(x->x), b.size());
  cholmod_free_dense(&x, &m.common);
  return out;
}

SparseCholesky::LowRank SparseCholesky::prepare(const Eigen::SparseMatrix<double>& U) const
{
  const Implementation& m = *this->Impl;
  if (!m.factor || U.rows() != static_cast<Eigen::Index>(m.factor->n))
  {
    throw Error("the low-rank term does not match the factored matrix");
  }
  const int* p = static_cast<const int*>(m.factor->p);
  const int* nz = static_cast<const int*>(m.factor->nz);
  const int* rows = static_cast<const int*>(m.factor->i);
  const double* values = static_cast<const double*>(m.factor->x);
  const int k = static_cast<int>(U.cols());

  // Each column's key: its entries; columns seen in the last call are reused.
  std::vector<Implementation::ColumnKey> keys(k);
  std::vector<int> fresh;
  for (int c = 0; c < k; ++c)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(U, c); it; ++it)
    {
      keys[c].emplace_back(static_cast<int>(it.row()), it.value());
    }
    if (!m.columns.count(keys[c]))
    {
      fresh.push_back(c);
    }
  }

  // The reach of a set of columns: every ancestor of their permuted rows, sorted.
  auto reachOf = [&m](const std::vector<int>& starts) {
    std::vector<int> reach;
    for (int start : starts)
    {
      for (int j = start; j >= 0 && m.position[j] < 0; j = m.parent[j])
      {
        m.position[j] = 0;
        reach.push_back(j);
      }
    }
    std::sort(reach.begin(), reach.end());
    for (std::size_t r = 0; r < reach.size(); ++r)
    {
      m.position[reach[r]] = static_cast<int>(r);
    }
    return reach;
  };
  auto clearPositions = [&m](const std::vector<int>& reach) {
    for (int j : reach)
    {
      m.position[j] = -1;
    }
  };

  // New columns: Y = L^-1 P U in one sweep over their reach (rows of column j are its ancestors).
  std::map<Implementation::ColumnKey, Implementation::Column> solved;
  if (!fresh.empty())
  {
    std::vector<int> starts;
    for (int c : fresh)
    {
      for (const auto& entry : keys[c])
      {
        starts.push_back(m.inversePermutation[entry.first]);
      }
    }
    const std::vector<int> reach = reachOf(starts);
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> y =
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>::Zero(
        static_cast<Eigen::Index>(reach.size()), static_cast<Eigen::Index>(fresh.size()));
    for (std::size_t f = 0; f < fresh.size(); ++f)
    {
      for (const auto& entry : keys[fresh[f]])
      {
        y(m.position[m.inversePermutation[entry.first]], static_cast<Eigen::Index>(f)) += entry.second;
      }
    }
    for (std::size_t r = 0; r < reach.size(); ++r)
    {
      const int j = reach[r];
      for (int e = p[j] + 1; e < p[j] + nz[j]; ++e)
      {
        y.row(m.position[rows[e]]) -= values[e] * y.row(static_cast<Eigen::Index>(r));
      }
    }
    for (std::size_t f = 0; f < fresh.size(); ++f)
    {
      Implementation::Column column;
      for (std::size_t r = 0; r < reach.size(); ++r)
      {
        const double value = y(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(f));
        if (value != 0.0)
        {
          column.emplace_back(reach[r], value);
        }
      }
      solved[keys[fresh[f]]] = std::move(column);
    }
    clearPositions(reach);
  }
  std::map<Implementation::ColumnKey, Implementation::Column> current;
  for (int c = 0; c < k; ++c)
  {
    auto found = solved.find(keys[c]);
    current[keys[c]] = found != solved.end() ? found->second : m.columns.at(keys[c]);
  }
  m.columns = std::move(current);

  // All columns on the union of their reaches, and U^T A^-1 U = Y^T D^-1 Y (D on L's diagonal).
  LowRank out;
  std::vector<int> starts;
  for (int c = 0; c < k; ++c)
  {
    for (const auto& entry : m.columns.at(keys[c]))
    {
      starts.push_back(entry.first);
    }
  }
  out.reach = reachOf(starts);
  out.y.setZero(static_cast<Eigen::Index>(out.reach.size()), k);
  for (int c = 0; c < k; ++c)
  {
    for (const auto& entry : m.columns.at(keys[c]))
    {
      out.y(m.position[entry.first], c) = entry.second;
    }
  }
  Eigen::VectorXd inverseD(static_cast<Eigen::Index>(out.reach.size()));
  for (std::size_t r = 0; r < out.reach.size(); ++r)
  {
    inverseD[static_cast<Eigen::Index>(r)] = 1.0 / values[p[out.reach[r]]];
  }
  out.gram = out.y.transpose() * inverseD.asDiagonal() * out.y;
  clearPositions(out.reach);
  return out;
}

Eigen::VectorXd SparseCholesky::apply(const LowRank& lowRank, const Eigen::VectorXd& s) const
{
  const Implementation& m = *this->Impl;
  const int n = static_cast<int>(m.factor->n);
  const int* p = static_cast<const int*>(m.factor->p);
  const double* values = static_cast<const double*>(m.factor->x);
  // z = D^-1 Y s on the reach, then P^T L^-T z.
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd ys = lowRank.y * s;
  for (std::size_t r = 0; r < lowRank.reach.size(); ++r)
  {
    const int j = lowRank.reach[r];
    z[j] = ys[static_cast<Eigen::Index>(r)] / values[p[j]];
  }
  cholmod_dense rhs = cholmodView(z.data(), static_cast<std::size_t>(n));
  cholmod_dense* x = cholmod_solve(CHOLMOD_Lt, m.factor, &rhs, &this->Impl->common);
  if (!x)
  {
    throw Error("the sparse solve failed");
  }
  const double* solved = static_cast<const double*>(x->x);
  const int* perm = static_cast<const int*>(m.factor->Perm);
  Eigen::VectorXd out(n);
  for (int r = 0; r < n; ++r)
  {
    out[perm[r]] = solved[r];
  }
  cholmod_free_dense(&x, &this->Impl->common);
  return out;
}

#else

struct SparseCholesky::Implementation
{
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool ready = false;
};

SparseCholesky::SparseCholesky()
  : Impl(new Implementation)
{
}

SparseCholesky::~SparseCholesky() = default;

std::string SparseCholesky::backend()
{
  return "Eigen SimplicialLDLT";
}

bool SparseCholesky::factor(const Eigen::SparseMatrix<double>& A)
{
  Implementation& m = *this->Impl;
  m.solver.compute(A);
  m.ready = m.solver.info() == Eigen::Success && (m.solver.vectorD().array() > 0.0).all();
  return m.ready;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const
{
  if (!this->Impl->ready)
  {
    throw Error("no factorization to solve with");
  }
  return this->Impl->solver.solve(b);
}

SparseCholesky::LowRank SparseCholesky::prepare(const Eigen::SparseMatrix<double>& U) const
{
  LowRank out;
  const Eigen::MatrixXd dense = Eigen::MatrixXd(U);
  out.y = this->Impl->solver.solve(dense); // A^-1 U, one solve per column
  out.gram = U.transpose() * out.y;
  return out;
}

Eigen::VectorXd SparseCholesky::apply(const LowRank& lowRank, const Eigen::VectorXd& s) const
{
  return lowRank.y * s;
}

#endif

} // namespace kerf
