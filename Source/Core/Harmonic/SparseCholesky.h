// Sparse Cholesky factorization (CHOLMOD, or Eigen's SimplicialLDLT without it) and low-rank corrections.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace kerf
{

/// Factors a sparse symmetric positive-definite matrix A once; then solves with A, and with
/// A + U U^T for any sparse U (n x k) through the Woodbury identity without touching the factor:
/// (A + U U^T)^-1 = A^-1 - G (I + U^T G)^-1 G^T, G = A^-1 U.
///
/// With CHOLMOD the factor is a supernodal L L^T with a fill-reducing (METIS) permutation P. For
/// a sparse U, Y = L^-1 P U is nonzero only on the supernodes on the paths from U's rows to the
/// root of the elimination tree (the "reach"), which constraints confined to a region of the
/// surface keep short: one sweep over the reach computes all k columns together with dense
/// kernels, U^T A^-1 U is Y^T Y, and A^-1 U s is one backward solve P^T L^-T Y s. The last
/// prepare()'s Y is kept, so a U that adds columns to the previous one only sweeps the new
/// ones. Each column's arithmetic is the same whatever the others are, so every result depends
/// only on A and U, never on earlier calls. Without CHOLMOD, G is formed by k solves. One object
/// serves one thread at a time (its const methods share workspace).
class SparseCholesky
{
public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Factors A (only its lower triangle is read). False if A is not positive definite.
  bool factor(const Eigen::SparseMatrix<double>& A);

  /// A^-1 b.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  /// What applies A^-1 U for one U.
  struct LowRankFactor;
  struct LowRank
  {
    Eigen::MatrixXd gram; ///< U^T A^-1 U (k x k)
    std::shared_ptr<const LowRankFactor> factor; ///< what apply() reads
  };

  /// Prepares A^-1 U for a sparse U with A's number of rows. Throws kerf::Error for another
  /// number of rows, no factorization, or NaN or infinite entries.
  LowRank prepare(const Eigen::SparseMatrix<double>& U) const;

  /// A^-1 U s. Throws kerf::Error if lowRank came from an earlier factorization or s has
  /// another size than U's number of columns.
  Eigen::VectorXd apply(const LowRank& lowRank, const Eigen::VectorXd& s) const;

  /// "CHOLMOD" or "Eigen SimplicialLDLT".
  static std::string backend();

private:
  struct Implementation;
  std::unique_ptr<Implementation> Impl;
};

} // namespace kerf
