// CHOLMOD-backed sparse Cholesky with rank-k updates; Eigen's SimplicialLDLT as the fallback.
#include "Harmonic/SparseCholesky.h"

#include "Error.h"

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
} // namespace

struct SparseCholesky::Implementation
{
  cholmod_common common;
  cholmod_factor* base = nullptr;
  cholmod_factor* current = nullptr; // base itself, or an updated copy
  bool simplicial = false;

  Implementation()
  {
    cholmod_start(&this->common);
    this->common.print = 0;
    this->common.error_handler = nullptr;
  }
  ~Implementation()
  {
    this->release();
    cholmod_finish(&this->common);
  }
  void releaseCurrent()
  {
    if (this->current && this->current != this->base)
    {
      cholmod_free_factor(&this->current, &this->common);
    }
    this->current = nullptr;
  }
  void release()
  {
    this->releaseCurrent();
    if (this->base)
    {
      cholmod_free_factor(&this->base, &this->common);
    }
    this->simplicial = false;
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
  m.release();
  Eigen::SparseMatrix<double> compressed = A;
  compressed.makeCompressed();
  cholmod_sparse s = cholmodView(compressed, -1);
  m.base = cholmod_analyze(&s, &m.common);
  if (!m.base)
  {
    return false;
  }
  const int ok = cholmod_factorize(&s, m.base, &m.common);
  if (!ok || m.common.status != CHOLMOD_OK || m.base->minor < m.base->n)
  {
    m.release();
    return false;
  }
  m.current = m.base;
  return true;
}

bool SparseCholesky::update(const Eigen::SparseMatrix<double>& U, const Eigen::SparseMatrix<double>* D)
{
  Implementation& m = *this->Impl;
  if (!m.base || U.rows() != static_cast<Eigen::Index>(m.base->n))
  {
    return false;
  }
  // Rank updates need a simplicial LDL' factor; convert the base once.
  if (!m.simplicial)
  {
    if (!cholmod_change_factor(CHOLMOD_REAL, 0, 0, 1, 1, m.base, &m.common))
    {
      return false;
    }
    m.simplicial = true;
  }
  m.releaseCurrent();
  m.current = cholmod_copy_factor(m.base, &m.common);
  if (!m.current)
  {
    return false;
  }
  // The rows of U and D follow the factor's fill-reducing permutation.
  auto modify = [&m](const Eigen::SparseMatrix<double>& M, int up) {
    if (M.cols() == 0)
    {
      return true;
    }
    Eigen::SparseMatrix<double> compressed = M;
    compressed.makeCompressed();
    cholmod_sparse view = cholmodView(compressed, 0);
    cholmod_sparse* permuted = cholmod_submatrix(
      &view, static_cast<int*>(m.base->Perm), static_cast<long>(m.base->n), nullptr, -1, 1, 1, &m.common);
    if (!permuted)
    {
      return false;
    }
    const int ok = cholmod_updown(up, permuted, m.current, &m.common);
    cholmod_free_sparse(&permuted, &m.common);
    return ok && m.common.status == CHOLMOD_OK;
  };
  return modify(U, 1) && (!D || modify(*D, 0));
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const
{
  Implementation& m = *this->Impl;
  if (!m.current)
  {
    throw Error("no factorization to solve with");
  }
  cholmod_dense rhs{};
  rhs.nrow = static_cast<std::size_t>(b.size());
  rhs.ncol = 1;
  rhs.nzmax = rhs.nrow;
  rhs.d = rhs.nrow;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, m.current, &rhs, &m.common);
  if (!x)
  {
    throw Error("the sparse solve failed");
  }
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(x->x), b.size());
  cholmod_free_dense(&x, &m.common);
  return out;
}

#else

struct SparseCholesky::Implementation
{
  Eigen::SparseMatrix<double> base;
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
  m.base = A;
  m.solver.compute(A);
  m.ready = m.solver.info() == Eigen::Success && (m.solver.vectorD().array() > 0.0).all();
  return m.ready;
}

bool SparseCholesky::update(const Eigen::SparseMatrix<double>& U, const Eigen::SparseMatrix<double>* D)
{
  Implementation& m = *this->Impl;
  const Eigen::SparseMatrix<double> updated = m.base + Eigen::SparseMatrix<double>(U * U.transpose());
  m.solver.compute(updated);
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

#endif

} // namespace kerf
