// Sparse Cholesky factorization (CHOLMOD, or Eigen's SimplicialLDLT without it) with low-rank updates.
#pragma once

#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace kerf
{

/// Factors a sparse symmetric positive-definite matrix A once, and then A + U U^T - D D^T for
/// sparse U and D from that base factor, without factoring again: with CHOLMOD this is a rank-k
/// update and downdate of a copy of the base factor (cholmod_updown); without CHOLMOD, Eigen's
/// SimplicialLDLT factors the updated matrix afresh. Updating always starts from the base factor, so the result depends
/// only on A and U, not on earlier updates.
class SparseCholesky
{
public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Factors A (only its lower triangle is read). False if A is not positive definite.
  bool factor(const Eigen::SparseMatrix<double>& A);

  /// Makes the current factor that of A + U U^T - D D^T (U and D have A's number of rows; D may
  /// be null). The result must be positive definite. False on failure.
  bool update(const Eigen::SparseMatrix<double>& U, const Eigen::SparseMatrix<double>* D = nullptr);

  /// Solves with the current factor (A's, or A + U U^T's after update()).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  /// "CHOLMOD" or "Eigen SimplicialLDLT".
  static std::string backend();

private:
  struct Implementation;
  std::unique_ptr<Implementation> Impl;
};

} // namespace kerf
