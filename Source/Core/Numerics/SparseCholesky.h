// Sparse Cholesky factorization (CHOLMOD, or Eigen's SimplicialLDLT without it) and low-rank corrections.
#pragma once

#include "Numerics/SupernodalFactorization.h"

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
/// With CHOLMOD the factor is a supernodal L L^T with a fill-reducing permutation P. For a sparse
/// U, Y = L^-1 P U is nonzero only on the supernodes on the paths from U's rows to the root of the
/// elimination tree (the "reach"), which constraints confined to a region of the surface keep
/// short: one sweep over the reach computes all k columns together with dense vector kernels
/// (faster than CHOLMOD's sparse solves; the figures are in Documentation/filters/
/// HarmonicCuts.md), U^T A^-1 U is Y^T Y (the BLAS's syrk, supernode by supernode on the
/// columns that can be nonzero there), and A^-1 U s is one backward solve
/// P^T L^-T Y s (Kerf's SupernodalSolve::backward). The last prepare()'s Y is kept, so a U that adds columns to the
/// previous one only sweeps the new ones. Each column's arithmetic in the sweep is the same
/// whatever the others are, and the Gram matrix is formed from U's distinct columns in a fixed
/// order, so every result depends only on A and U, never on earlier calls or on the order of U's
/// columns (bit for bit on one machine: the BLAS and the sweep pick their kernels per
/// processor). Without CHOLMOD, G is formed by k solves. One object serves one thread at a time
/// (its const methods share workspace).
class SparseCholesky
{
public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Fill-reducing orderings of the factorization. On the cotangent Laplacians of surface meshes
  /// AMD's ordering costs far less than the flops METIS' nested dissection saves, on one core.
  enum class Ordering
  {
    AMD,  ///< approximate minimum degree: fast to compute, more fill
    METIS ///< nested dissection: less fill, slower to compute
  };

  /// Factors the symmetric matrix A (only its lower triangle is read). False if A is not
  /// positive definite. Without CHOLMOD the ordering is Eigen's AMD.
  bool factor(const Eigen::SparseMatrix<double>& A, Ordering ordering = Ordering::AMD);
  /// Factors A with a given fill-reducing permutation (row permutation[k] is eliminated k-th),
  /// which skips the ordering: for a sequence of matrices that differ locally, the permutation of
  /// an earlier one extended by the new rows. Throws kerf::Error if it is not a permutation of
  /// A's rows. Without CHOLMOD, Eigen's AMD ordering is used instead.
  bool factor(const Eigen::SparseMatrix<double>& A, const std::vector<int>& permutation);
  /// The fill-reducing permutation of the current factorization (empty without one, or without
  /// CHOLMOD).
  std::vector<int> permutation() const;

  /// Nonzeros of the factor L (0 before the first factorization).
  std::size_t factorNonZeros() const;

  /// Who computes the supernodal factor's values in the next factorizations (Automatic by
  /// default: Kerf's kernels for the processor, see Numerics/SupernodalFactorization.h). A route
  /// this processor cannot run falls back to CHOLMOD's. Without CHOLMOD it changes nothing.
  void setSupernodalRoute(SupernodalRoute route);

  /// A^-1 b.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// A^-1 B for several right-hand sides at once with CHOLMOD's own solve (one pass over the
  /// factor, with BLAS 3): the reference solveBlock() is measured against.
  Eigen::MatrixXd solveColumns(const Eigen::MatrixXd& b) const;
  /// A^-1 B with Kerf's supernodal kernels, all columns in one sweep over the factor (column j
  /// equals solve(b.col(j)) bit for bit). Three columns on the 100k dumbbell's Laplacian take
  /// 0.88 of solveColumns()'s time (BM_SolveThree; Documentation/filters/GeometrySeamCarving.md).
  /// Throws kerf::Error without a factorization or for another number of rows. Without CHOLMOD,
  /// Eigen's solve.
  Eigen::MatrixXd solveBlock(const Eigen::MatrixXd& b) const;

  /// What applies A^-1 U for one U.
  struct LowRankFactor;
  struct LowRank
  {
    Eigen::MatrixXd gram;                        ///< U^T A^-1 U (k x k)
    std::shared_ptr<const LowRankFactor> factor; ///< what apply() reads
    std::size_t reachRows = 0;                   ///< rows of L^-1 P U that can be nonzero
    /// Multiply-adds that formed the Gram matrix: the rows of each supernode of the reach times
    /// the products of the columns that can be nonzero there (about m(m+1)/2 for m columns),
    /// where the dense product would take reachRows k(k+1)/2 for U's k distinct columns.
    std::size_t gramProducts = 0;
  };

  /// How prepare() computes Y = L^-1 P U. The CHOLMOD routes are the references the sweep is
  /// measured and tested against; they do not reuse the last call's columns. Without CHOLMOD
  /// every route is Eigen's solve.
  enum class LowRankRoute
  {
    SupernodalSweep, ///< one sweep over the supernodes of the reach with dense vector kernels
    CholmodSolve2,   ///< one cholmod_solve2 per column with its entries as sparse right-hand side
                     ///< (Bset), on a simplicial copy of the factor made on first use
    CholmodSpsolve   ///< cholmod_spsolve on all columns (dense blocks of four)
  };

  /// Prepares A^-1 U for a sparse U with A's number of rows. Throws kerf::Error for another
  /// number of rows, no factorization, or NaN or infinite entries.
  LowRank prepare(const Eigen::SparseMatrix<double>& U, LowRankRoute route = LowRankRoute::SupernodalSweep) const;

  /// A^-1 U s. Throws kerf::Error if lowRank came from an earlier factorization or s has
  /// another size than U's number of columns.
  Eigen::VectorXd apply(const LowRank& lowRank, const Eigen::VectorXd& s) const;

  /// "CHOLMOD" or "Eigen SimplicialLDLT".
  static std::string backend();

private:
  bool factorOrdered(const Eigen::SparseMatrix<double>& A, Ordering ordering, const std::vector<int>* given);
  struct Implementation;
  std::unique_ptr<Implementation> Impl;
};

} // namespace kerf
