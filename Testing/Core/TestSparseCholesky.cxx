// Sparse Cholesky against dense references for both orderings and every low-rank route; results
// that do not depend on earlier calls or on the order of the low-rank columns.
#include "Error.h"
#include "Mesh/MeshGenerators.h"
#include "Numerics/NestedDissection.h"
#include "Numerics/SparseCholesky.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <numeric>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace kerf;

namespace
{
// The squared 5-point Laplacian of a side x side grid plus a small multiple of the identity:
// symmetric positive definite, with the wide stencil and fill of the biharmonic systems.
Eigen::SparseMatrix<double> gridSystem(int side)
{
  const int n = side * side;
  std::vector<Eigen::Triplet<double>> entries;
  for (int y = 0; y < side; ++y)
  {
    for (int x = 0; x < side; ++x)
    {
      const int v = y * side + x;
      int degree = 0;
      const int neighbours[4][2] = { { x - 1, y }, { x + 1, y }, { x, y - 1 }, { x, y + 1 } };
      for (const auto& p : neighbours)
      {
        if (p[0] >= 0 && p[0] < side && p[1] >= 0 && p[1] < side)
        {
          entries.emplace_back(v, p[1] * side + p[0], -1.0);
          ++degree;
        }
      }
      entries.emplace_back(v, v, degree);
    }
  }
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseMatrix<double> identity(n, n);
  identity.setIdentity();
  Eigen::SparseMatrix<double> system = Eigen::SparseMatrix<double>(laplacian.transpose() * laplacian) + 1e-3 * identity;
  system.makeCompressed();
  return system;
}

// k columns with one to three entries each, like barycentric constraint rows.
Eigen::SparseMatrix<double> lowRankColumns(int n, int k, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> row(0, n - 1);
  std::uniform_int_distribution<int> count(1, 3);
  std::uniform_real_distribution<double> value(0.1, 2.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < k; ++c)
  {
    const int first = row(random);
    const int entriesInColumn = count(random);
    for (int e = 0; e < entriesInColumn; ++e)
    {
      entries.emplace_back(std::min(n - 1, first + e), c, value(random));
    }
  }
  Eigen::SparseMatrix<double> U(n, k);
  U.setFromTriplets(entries.begin(), entries.end());
  U.makeCompressed();
  return U;
}

bool bitwiseEqual(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
  return a.rows() == b.rows() && a.cols() == b.cols() &&
    std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

double relativeError(const Eigen::MatrixXd& value, const Eigen::MatrixXd& reference)
{
  return (value - reference).norm() / reference.norm();
}

struct Fixture
{
  Eigen::SparseMatrix<double> A = gridSystem(30);
  Eigen::MatrixXd dense = Eigen::MatrixXd(A);
  Eigen::LDLT<Eigen::MatrixXd> reference{ dense };
};
} // namespace

TEST(SparseCholesky, SolveMatchesDenseReference)
{
  const Fixture f;
  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factor(f.A));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(f.A.rows(), -1.0, 2.0);
  EXPECT_LT(relativeError(cholesky.solve(b), f.reference.solve(b)), 1e-9);
}

TEST(SparseCholesky, SolveMatchesTheLibrarysSolve)
{
  // solve() runs Kerf's supernodal kernels; solveColumns() CHOLMOD's own solve (the BLAS). They
  // agree to rounding on a chain (which CHOLMOD's amalgamation may merge into wider
  // supernodes), grids (whose fill gives supernodes of many widths) and a dense block (one
  // supernode of 61 columns, a remainder of one past the blocks of four), and the kernels give
  // the same bits on every call.
  std::vector<Eigen::SparseMatrix<double>> matrices = { gridSystem(40), gridSystem(7) };
  const int n = 300;
  std::vector<Eigen::Triplet<double>> chain, dense;
  for (int i = 0; i < n; ++i)
  {
    chain.emplace_back(i, i, 2.5);
    if (i > 0)
    {
      chain.emplace_back(i, i - 1, -1.0);
      chain.emplace_back(i - 1, i, -1.0);
    }
  }
  for (int i = 0; i < 61; ++i)
  {
    for (int j = 0; j < 61; ++j)
    {
      dense.emplace_back(i, j, i == j ? 70.0 : 1.0 / (1.0 + std::abs(i - j)));
    }
  }
  matrices.emplace_back(n, n);
  matrices.back().setFromTriplets(chain.begin(), chain.end());
  matrices.emplace_back(61, 61);
  matrices.back().setFromTriplets(dense.begin(), dense.end());
  for (Eigen::SparseMatrix<double>& A : matrices)
  {
    A.makeCompressed();
    SparseCholesky cholesky;
    ASSERT_TRUE(cholesky.factor(A));
    Eigen::VectorXd b(A.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i)
    {
      b[i] = std::sin(0.37 * static_cast<double>(i)) + 0.25;
    }
    const Eigen::VectorXd x = cholesky.solve(b);
    const Eigen::VectorXd reference = cholesky.solveColumns(b);
    EXPECT_LT(relativeError(x, reference), 1e-13) << A.rows();
    // As accurate as the library's: residuals within twice its own.
    EXPECT_LE((A * x - b).norm(), 2.0 * (A * reference - b).norm() + 1e-15 * b.norm()) << A.rows();
    EXPECT_TRUE(bitwiseEqual(cholesky.solve(b), x));
  }
}

TEST(SparseCholesky, GivenPermutationSolvesAlike)
{
  const Fixture f;
  SparseCholesky ordered;
  ASSERT_TRUE(ordered.factor(f.A));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(f.A.rows(), -1.0, 2.0);
  const std::vector<int> amd = ordered.permutation();
  if (SparseCholesky::backend() == "CHOLMOD")
  {
    ASSERT_EQ(amd.size(), static_cast<std::size_t>(f.A.rows()));
  }
  // Its own ordering gives the same factor; the identity ordering a denser one, the same solution.
  std::vector<int> identity(static_cast<std::size_t>(f.A.rows()));
  std::iota(identity.begin(), identity.end(), 0);
  for (const std::vector<int>& permutation : { amd.empty() ? identity : amd, identity })
  {
    SparseCholesky given;
    ASSERT_TRUE(given.factor(f.A, permutation));
    EXPECT_LT(relativeError(given.solve(b), f.reference.solve(b)), 1e-9);
    if (permutation == amd)
    {
      EXPECT_EQ(given.factorNonZeros(), ordered.factorNonZeros());
      EXPECT_EQ(given.permutation(), amd);
    }
  }
  SparseCholesky refused;
  std::vector<int> repeated = identity;
  repeated[1] = 0;
  if (SparseCholesky::backend() == "CHOLMOD")
  {
    EXPECT_THROW(refused.factor(f.A, repeated), Error);
  }
  EXPECT_THROW(refused.factor(f.A, std::vector<int>{ 0, 1 }), Error);
}

TEST(SparseCholesky, SolveColumnsMatchesOneColumnAtATime)
{
  const Fixture f;
  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factor(f.A));
  Eigen::MatrixXd b(f.A.rows(), 3);
  b.col(0) = Eigen::VectorXd::LinSpaced(f.A.rows(), -1.0, 2.0);
  b.col(1) = Eigen::VectorXd::Ones(f.A.rows());
  b.col(2) = Eigen::VectorXd::LinSpaced(f.A.rows(), 3.0, -5.0);
  const Eigen::MatrixXd x = cholesky.solveColumns(b);
  ASSERT_EQ(x.rows(), b.rows());
  ASSERT_EQ(x.cols(), 3);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_LT(relativeError(x.col(c), f.reference.solve(b.col(c))), 1e-9);
  }
  EXPECT_THROW(cholesky.solveColumns(Eigen::MatrixXd::Ones(f.A.rows() + 1, 2)), Error);
  EXPECT_THROW(cholesky.solve(Eigen::VectorXd::Ones(f.A.rows() - 1)), Error);
  SparseCholesky empty;
  EXPECT_THROW(empty.solveColumns(b), Error);
}

// solveBlock() sweeps the factor once for all columns with solve()'s kernels: each column is
// solve()'s bit for bit (with CHOLMOD; Eigen's solve without it), and the reference's to 1e-9.
TEST(SparseCholesky, SolveBlockEqualsSolveColumnByColumn)
{
  const Fixture f;
  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factor(f.A));
  Eigen::MatrixXd b(f.A.rows(), 4);
  b.col(0) = Eigen::VectorXd::LinSpaced(f.A.rows(), -1.0, 2.0);
  b.col(1) = Eigen::VectorXd::Ones(f.A.rows());
  b.col(2) = Eigen::VectorXd::LinSpaced(f.A.rows(), 3.0, -5.0);
  b.col(3) = b.col(0).cwiseProduct(b.col(2));
  const Eigen::MatrixXd x = cholesky.solveBlock(b);
  ASSERT_EQ(x.rows(), b.rows());
  ASSERT_EQ(x.cols(), 4);
  for (int c = 0; c < 4; ++c)
  {
    const Eigen::VectorXd one = cholesky.solve(b.col(c));
    if (SparseCholesky::backend() == "CHOLMOD")
    {
      EXPECT_EQ(std::memcmp(x.col(c).data(), one.data(), sizeof(double) * one.size()), 0) << "column " << c;
    }
    EXPECT_LT(relativeError(x.col(c), f.reference.solve(b.col(c))), 1e-9) << "column " << c;
  }
  EXPECT_EQ(cholesky.solveBlock(Eigen::MatrixXd::Zero(f.A.rows(), 2)).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(cholesky.solveBlock(Eigen::MatrixXd(f.A.rows(), 0)).cols(), 0);
  EXPECT_THROW(cholesky.solveBlock(Eigen::MatrixXd::Ones(f.A.rows() + 1, 2)), Error);
  SparseCholesky empty;
  EXPECT_THROW(empty.solveBlock(b), Error);
}

TEST(SparseCholesky, LowRankMatchesDenseReference)
{
  const Fixture f;
  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factor(f.A));
  // 37 columns: several chunks of right-hand sides and a partial one.
  const Eigen::SparseMatrix<double> U = lowRankColumns(static_cast<int>(f.A.rows()), 37, 7);
  const SparseCholesky::LowRank lowRank = cholesky.prepare(U);
  const Eigen::MatrixXd inverseU = f.reference.solve(Eigen::MatrixXd(U));
  EXPECT_LT(relativeError(lowRank.gram, Eigen::MatrixXd(U.transpose()) * inverseU), 1e-9);
  EXPECT_TRUE(bitwiseEqual(lowRank.gram, lowRank.gram.transpose()));
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(37, 1.0, -0.5);
  EXPECT_LT(relativeError(cholesky.apply(lowRank, s), inverseU * s), 1e-9);

  // Woodbury: (A + U U^T)^-1 b from the pieces equals the dense solve of the updated matrix.
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(f.A.rows(), 0.5, -1.5);
  const Eigen::VectorXd x0 = cholesky.solve(b);
  const Eigen::MatrixXd capacitance = Eigen::MatrixXd::Identity(37, 37) + lowRank.gram;
  const Eigen::VectorXd correction =
    cholesky.apply(lowRank, capacitance.ldlt().solve(Eigen::MatrixXd(U.transpose()) * x0));
  const Eigen::MatrixXd updated = f.dense + Eigen::MatrixXd(U) * Eigen::MatrixXd(U.transpose());
  EXPECT_LT(relativeError(x0 - correction, updated.ldlt().solve(b)), 1e-8);
}

TEST(SparseCholesky, LowRankDoesNotDependOnEarlierCalls)
{
  const Fixture f;
  const int n = static_cast<int>(f.A.rows());
  const Eigen::SparseMatrix<double> first = lowRankColumns(n, 20, 11);
  const Eigen::SparseMatrix<double> second = lowRankColumns(n, 19, 12);
  Eigen::SparseMatrix<double> both(n, 39);
  both.leftCols(20) = first;
  both.rightCols(19) = second;
  both.makeCompressed();

  // One solver sees the first columns, then all of them (the first reused); another sees all
  // of them at once.
  SparseCholesky refined, fresh;
  ASSERT_TRUE(refined.factor(f.A));
  ASSERT_TRUE(fresh.factor(f.A));
  refined.prepare(first);
  const SparseCholesky::LowRank a = refined.prepare(both);
  const SparseCholesky::LowRank b = fresh.prepare(both);
  EXPECT_TRUE(bitwiseEqual(a.gram, b.gram));
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(39, -2.0, 1.0);
  EXPECT_TRUE(bitwiseEqual(refined.apply(a, s), fresh.apply(b, s)));
  // The same when the kept columns are the last ones.
  SparseCholesky later;
  ASSERT_TRUE(later.factor(f.A));
  later.prepare(second);
  const SparseCholesky::LowRank d = later.prepare(both);
  EXPECT_TRUE(bitwiseEqual(d.gram, b.gram));
  EXPECT_TRUE(bitwiseEqual(later.apply(d, s), fresh.apply(b, s)));

  // Swapping the two groups permutes the Gram matrix exactly, whether the columns are new (a
  // new solver) or kept from the last call at other places.
  Eigen::SparseMatrix<double> swapped(n, 39);
  swapped.leftCols(19) = second;
  swapped.rightCols(20) = first;
  swapped.makeCompressed();
  Eigen::MatrixXd permuted(39, 39);
  for (int i = 0; i < 39; ++i)
  {
    for (int j = 0; j < 39; ++j)
    {
      permuted((i + 19) % 39, (j + 19) % 39) = b.gram(i, j);
    }
  }
  SparseCholesky other;
  ASSERT_TRUE(other.factor(f.A));
  EXPECT_TRUE(bitwiseEqual(other.prepare(swapped).gram, permuted));
  EXPECT_TRUE(bitwiseEqual(fresh.prepare(swapped).gram, permuted));
}

TEST(SparseCholesky, GramSumsOnlyWhereColumnsCanBeNonzero)
{
  // A larger grid, whose elimination tree spreads constraints scattered over it into separate
  // branches: the Gram matrix sums each supernode's rows over the columns that can be nonzero
  // there, and still equals the dense reference. Half the columns join two distant rows, so
  // that their nonzero supernodes are not those of one branch.
  const Eigen::SparseMatrix<double> A = gridSystem(60);
  const int n = static_cast<int>(A.rows());
  Eigen::SparseMatrix<double> U(n, 64);
  U.leftCols(32) = lowRankColumns(n, 32, 31);
  const Eigen::SparseMatrix<double> near = lowRankColumns(n, 32, 32);
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < 32; ++c)
  {
    for (Eigen::SparseMatrix<double>::InnerIterator it(near, c); it; ++it)
    {
      entries.emplace_back(static_cast<int>(it.row()), c, it.value());
      entries.emplace_back((static_cast<int>(it.row()) + n / 2 + 7 * c) % n, c, 0.5 * it.value());
    }
  }
  Eigen::SparseMatrix<double> joined(n, 32);
  joined.setFromTriplets(entries.begin(), entries.end());
  U.rightCols(32) = joined;
  U.makeCompressed();

  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factor(A));
  const SparseCholesky::LowRank lowRank = cholesky.prepare(U);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> reference(A);
  const Eigen::MatrixXd inverseU = reference.solve(Eigen::MatrixXd(U));
  EXPECT_LT(relativeError(lowRank.gram, Eigen::MatrixXd(U.transpose()) * inverseU), 1e-9);
  EXPECT_TRUE(bitwiseEqual(lowRank.gram, lowRank.gram.transpose()));
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(64, -1.0, 2.0);
  EXPECT_LT(relativeError(cholesky.apply(lowRank, s), inverseU * s), 1e-9);
  if (SparseCholesky::backend() == "CHOLMOD")
  {
    const std::size_t denseProducts = lowRank.reachRows * 64 * 65 / 2;
    EXPECT_GT(lowRank.gramProducts, 0u);
    EXPECT_LT(lowRank.gramProducts, denseProducts / 2) << lowRank.gramProducts << " of " << denseProducts;
  }
}

TEST(SparseCholesky, LowRankEdgeCases)
{
  const Fixture f;
  const int n = static_cast<int>(f.A.rows());
  SparseCholesky cholesky, reference;
  ASSERT_TRUE(cholesky.factor(f.A));
  ASSERT_TRUE(reference.factor(f.A));

  // No column at all.
  const SparseCholesky::LowRank none = cholesky.prepare(Eigen::SparseMatrix<double>(n, 0));
  EXPECT_EQ(none.gram.size(), 0);
  EXPECT_EQ(cholesky.apply(none, Eigen::VectorXd(0)).norm(), 0.0);

  // An empty column and a repeated one, first new, then all kept (the same U twice).
  const Eigen::SparseMatrix<double> base = lowRankColumns(n, 5, 21);
  Eigen::SparseMatrix<double> odd(n, 7);
  odd.leftCols(5) = base;
  odd.col(6) = base.col(2); // column 5 stays empty
  odd.makeCompressed();
  const SparseCholesky::LowRank once = cholesky.prepare(odd);
  const SparseCholesky::LowRank twice = cholesky.prepare(odd);
  const SparseCholesky::LowRank alone = reference.prepare(odd);
  EXPECT_TRUE(bitwiseEqual(once.gram, alone.gram));
  EXPECT_TRUE(bitwiseEqual(twice.gram, alone.gram));
  EXPECT_EQ(alone.gram.row(5).norm(), 0.0);
  EXPECT_EQ(alone.gram(6, 6), alone.gram(2, 2));
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(7, 1.0, 2.0);
  EXPECT_TRUE(bitwiseEqual(cholesky.apply(twice, s), reference.apply(alone, s)));
  const Eigen::MatrixXd inverseU = f.reference.solve(Eigen::MatrixXd(odd));
  EXPECT_LT(relativeError(alone.gram, Eigen::MatrixXd(odd.transpose()) * inverseU), 1e-9);

  // Kept columns between new ones.
  Eigen::SparseMatrix<double> mixed(n, 9);
  mixed.leftCols(2) = lowRankColumns(n, 2, 22);
  mixed.middleCols(2, 5) = base;
  mixed.rightCols(2) = lowRankColumns(n, 2, 23);
  mixed.makeCompressed();
  SparseCholesky direct;
  ASSERT_TRUE(direct.factor(f.A));
  const SparseCholesky::LowRank kept = cholesky.prepare(mixed);
  const SparseCholesky::LowRank afresh = direct.prepare(mixed);
  EXPECT_TRUE(bitwiseEqual(kept.gram, afresh.gram));
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(9, -1.0, 1.0);
  EXPECT_TRUE(bitwiseEqual(cholesky.apply(kept, t), direct.apply(afresh, t)));
}

TEST(SparseCholesky, RefusesMismatchedLowRank)
{
  const Fixture f;
  const int n = static_cast<int>(f.A.rows());
  SparseCholesky cholesky;
  EXPECT_THROW(cholesky.prepare(lowRankColumns(n, 3, 31)), Error);
  ASSERT_TRUE(cholesky.factor(f.A));
  EXPECT_THROW(cholesky.prepare(lowRankColumns(n + 1, 3, 31)), Error);
  Eigen::SparseMatrix<double> bad = lowRankColumns(n, 3, 31);
  bad.valuePtr()[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(cholesky.prepare(bad), Error);
  // The same check on a matrix that is not compressed (its value array has spare slots).
  Eigen::SparseMatrix<double> loose(n, 2);
  loose.reserve(Eigen::VectorXi::Constant(2, 4));
  loose.insert(0, 0) = 1.0;
  loose.insert(5, 1) = std::numeric_limits<double>::infinity();
  ASSERT_FALSE(loose.isCompressed());
  EXPECT_THROW(cholesky.prepare(loose), Error);

  const SparseCholesky::LowRank lowRank = cholesky.prepare(lowRankColumns(n, 3, 32));
  EXPECT_THROW(cholesky.apply(lowRank, Eigen::VectorXd::Ones(2)), Error);
  EXPECT_NO_THROW(cholesky.apply(lowRank, Eigen::VectorXd::Ones(3)));
  // A new factorization: the old term no longer applies, and the kept columns are forgotten.
  ASSERT_TRUE(cholesky.factor(2.0 * f.A));
  EXPECT_THROW(cholesky.apply(lowRank, Eigen::VectorXd::Ones(3)), Error);
  const SparseCholesky::LowRank scaled = cholesky.prepare(lowRankColumns(n, 3, 32));
  EXPECT_LT(relativeError(2.0 * scaled.gram, lowRank.gram), 1e-9);
}

TEST(SparseCholesky, RefusesIndefiniteMatrix)
{
  const Fixture f;
  SparseCholesky cholesky;
  const Eigen::SparseMatrix<double> negative = -f.A;
  EXPECT_FALSE(cholesky.factor(negative));
}

TEST(SparseCholesky, OrderingsAndLowRankRoutesAgree)
{
  const Fixture f;
  const int n = static_cast<int>(f.A.rows());
  const Eigen::SparseMatrix<double> U = lowRankColumns(n, 21, 41);
  const Eigen::MatrixXd inverseU = f.reference.solve(Eigen::MatrixXd(U));
  const Eigen::MatrixXd gramReference = Eigen::MatrixXd(U.transpose()) * inverseU;
  const Eigen::VectorXd s = Eigen::VectorXd::LinSpaced(21, 0.5, -1.0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  for (const SparseCholesky::Ordering ordering : { SparseCholesky::Ordering::AMD, SparseCholesky::Ordering::METIS })
  {
    SparseCholesky cholesky;
    ASSERT_TRUE(cholesky.factor(f.A, ordering));
    EXPECT_GT(cholesky.factorNonZeros(), static_cast<std::size_t>(n));
    EXPECT_LT(relativeError(cholesky.solve(b), f.reference.solve(b)), 1e-9);
    for (const SparseCholesky::LowRankRoute route : { SparseCholesky::LowRankRoute::SupernodalSweep,
           SparseCholesky::LowRankRoute::CholmodSolve2, SparseCholesky::LowRankRoute::CholmodSpsolve })
    {
      const SparseCholesky::LowRank lowRank = cholesky.prepare(U, route);
      EXPECT_LT(relativeError(lowRank.gram, gramReference), 1e-9) << static_cast<int>(route);
      EXPECT_TRUE(bitwiseEqual(lowRank.gram, lowRank.gram.transpose())) << static_cast<int>(route);
      EXPECT_LT(relativeError(cholesky.apply(lowRank, s), inverseU * s), 1e-9) << static_cast<int>(route);
      EXPECT_GT(lowRank.reachRows, 0u);
      EXPECT_LE(lowRank.reachRows, static_cast<std::size_t>(n));
    }
    // The reference routes forget nothing the sweep relies on: after them, the sweep still
    // reuses its own last columns and gives the same bits as afresh.
    SparseCholesky fresh;
    ASSERT_TRUE(fresh.factor(f.A, ordering));
    const SparseCholesky::LowRank afresh = fresh.prepare(U);
    const SparseCholesky::LowRank again = cholesky.prepare(U);
    EXPECT_TRUE(bitwiseEqual(again.gram, afresh.gram));
    EXPECT_TRUE(bitwiseEqual(cholesky.apply(again, s), fresh.apply(afresh, s)));
  }
}

namespace
{
// The lower triangle of a mesh's vertex adjacency plus a dominant diagonal.
Eigen::SparseMatrix<double> meshSystem(const TriangleMesh& mesh)
{
  std::vector<Eigen::Triplet<double>> entries;
  for (int e = 0; e < mesh.edgeCount(); ++e)
  {
    const std::array<int, 2>& ev = mesh.edgeVertices(e);
    entries.emplace_back(std::max(ev[0], ev[1]), std::min(ev[0], ev[1]), -1.0);
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    entries.emplace_back(v, v, 12.0);
  }
  Eigen::SparseMatrix<double> A(mesh.vertexCount(), mesh.vertexCount());
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}
} // namespace

TEST(NestedDissection, IsADeterministicDissectingPermutation)
{
  const TriangleMesh sphere = makeIcosphere(1.0, 4); // 2,562 vertices
  const Eigen::SparseMatrix<double> A = meshSystem(sphere);
  const std::vector<int> perm = geometricNestedDissection(sphere.points(), A, 16);
  std::vector<int> sorted = perm;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < sphere.vertexCount(); ++k)
  {
    ASSERT_EQ(sorted[k], k);
  }
  EXPECT_EQ(perm, geometricNestedDissection(sphere.points(), A, 16));
  // One dissection (halves no larger than the leaf size): the rows come as three increasing
  // runs, two halves and their separator, and no edge joins the two halves.
  const int n = sphere.vertexCount();
  const std::vector<int> once = geometricNestedDissection(sphere.points(), A, n - 1);
  std::vector<int> runStarts{ 0 };
  for (int k = 1; k < n; ++k)
  {
    if (once[k] < once[k - 1])
    {
      runStarts.push_back(k);
    }
  }
  ASSERT_EQ(runStarts.size(), 3u);
  std::vector<int> run(n);
  for (int r = 0; r < 3; ++r)
  {
    const int end = r + 1 < 3 ? runStarts[r + 1] : n;
    for (int k = runStarts[r]; k < end; ++k)
    {
      run[once[k]] = r;
    }
  }
  const int separator = n - runStarts[2];
  RecordProperty("TopSeparator", std::to_string(separator));
  EXPECT_GT(separator, 0);
  EXPECT_LT(separator, n / 10); // about a great circle: 2 pi / (edge length 0.08) = 80 rows
  for (int e = 0; e < sphere.edgeCount(); ++e)
  {
    const std::array<int, 2>& ev = sphere.edgeVertices(e);
    EXPECT_FALSE(run[ev[0]] + run[ev[1]] == 1) << "edge " << e << " joins the two halves";
  }
  // The factor is sparser than with AMD on a closed surface (flops are halved at 1M triangles).
  SparseCholesky given, amd;
  ASSERT_TRUE(given.factor(A, perm));
  ASSERT_TRUE(amd.factor(A, SparseCholesky::Ordering::AMD));
  RecordProperty("GeometricFactorNonZeros", std::to_string(given.factorNonZeros()));
  RecordProperty("AMDFactorNonZeros", std::to_string(amd.factorNonZeros()));
  EXPECT_LE(given.factorNonZeros(), amd.factorNonZeros() * 11 / 10);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  EXPECT_LE((given.solve(b) - amd.solve(b)).norm(), 1e-12 * b.norm());
  EXPECT_THROW(geometricNestedDissection(std::vector<Vector3>(3), A), Error);
}
