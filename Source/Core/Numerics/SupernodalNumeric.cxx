// Left-looking supernodal numeric Cholesky factorization (Ng and Peyton 1993; the layout and the
// descendant lists of CHOLMOD's supernodal factorization, Chen, Davis, Hager and Rajamanickam
// 2008) with Eigen's dense kernels. This file is compiled once per instruction-set level into its
// own shared library with hidden symbols (Source/Core/CMakeLists.txt), so that Eigen's
// instantiations for one level never stand in for another's; Numerics/SupernodalFactorization.cxx
// calls the level the processor has.
#include "Numerics/SupernodalNumeric.h"
#include "Numerics/HugePages.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

#ifndef KERF_SUPERNODAL_ENTRY
#error "KERF_SUPERNODAL_ENTRY names the entry point of this instruction-set level"
#endif

namespace
{

// L L^H = P A P^T for Scalar double (L L^T) or std::complex<double>.
template <typename Scalar>
int factorize(const kerf::SupernodalProblem& p, const Scalar* ax, Scalar* values)
{
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  using Block = Eigen::Map<Matrix, 0, Eigen::OuterStride<>>;
  using BlockRef = Eigen::Ref<Matrix, 0, Eigen::OuterStride<>>;
  const int n = p.n;
  const int supernodes = p.supernodes;
  std::fill(values, values + p.px[supernodes], Scalar(0));

  // C = P A P^T, lower triangle, in compressed columns.
  std::vector<int> inverse(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
  {
    inverse[p.perm[k]] = k;
  }
  std::vector<int> cp(static_cast<std::size_t>(n) + 1, 0);
  for (int j = 0; j < n; ++j)
  {
    for (int q = p.ap[j]; q < p.ap[j + 1]; ++q)
    {
      if (p.ai[q] >= j)
      {
        ++cp[std::min(inverse[p.ai[q]], inverse[j]) + 1];
      }
    }
  }
  for (int j = 0; j < n; ++j)
  {
    cp[j + 1] += cp[j];
  }
  kerf::HugePageVector<int> ci(static_cast<std::size_t>(cp[n]));
  kerf::HugePageVector<Scalar> cx(static_cast<std::size_t>(cp[n]));
  {
    std::vector<int> next(cp.begin(), cp.end() - 1);
    for (int j = 0; j < n; ++j)
    {
      for (int q = p.ap[j]; q < p.ap[j + 1]; ++q)
      {
        if (p.ai[q] >= j)
        {
          // A(i, j) lands at (a, b); above the diagonal its lower twin is conj(A(i, j)).
          const int a = inverse[p.ai[q]], b = inverse[j];
          const int at = next[std::min(a, b)]++;
          ci[at] = std::max(a, b);
          cx[at] = a >= b ? ax[q] : Eigen::numext::conj(ax[q]);
        }
      }
    }
  }

  std::vector<int> supernodeOf(static_cast<std::size_t>(n));
  for (int s = 0; s < supernodes; ++s)
  {
    std::fill(supernodeOf.begin() + p.super[s], supernodeOf.begin() + p.super[s + 1], s);
  }
  // map: a row's place in the current supernode (-1 outside it); head/next: the supernodes that
  // update each supernode next; position: where in its rows each such supernode's next update
  // starts.
  std::vector<int> map(static_cast<std::size_t>(n), -1);
  std::vector<int> head(static_cast<std::size_t>(supernodes), -1), next(static_cast<std::size_t>(supernodes), -1);
  std::vector<int> position(static_cast<std::size_t>(supernodes), 0);
  kerf::HugePageVector<Scalar> update;
  std::vector<Scalar, Eigen::aligned_allocator<Scalar>> aligned;
  for (int s = 0; s < supernodes; ++s)
  {
    const int k1 = p.super[s], k2 = p.super[s + 1], columns = k2 - k1;
    const int firstRow = p.pi[s], rows = p.pi[s + 1] - firstRow;
    Scalar* target = values + p.px[s];
    for (int k = 0; k < rows; ++k)
    {
      map[p.s[firstRow + k]] = k;
    }
    for (int j = k1; j < k2; ++j)
    {
      Scalar* column = target + static_cast<std::size_t>(j - k1) * rows;
      for (int q = cp[j]; q < cp[j + 1]; ++q)
      {
        const int at = map[ci[q]];
        if (at < 0)
        {
          return kerf::SupernodalOutsidePattern; // A is not the matrix that was analysed
        }
        column[at] += cx[q];
      }
    }
    // Each descendant d with rows in [k1, k2): subtract L_d(r, :) L_d(r1, :)^H, r its rows from
    // the first one in this supernode down, r1 those inside [k1, k2).
    for (int d = head[s]; d != -1;)
    {
      const int following = next[d];
      const int dFirst = p.pi[d], dRows = p.pi[d + 1] - dFirst, dColumns = p.super[d + 1] - p.super[d];
      const int begin = dFirst + position[d];
      int inside = begin;
      while (inside < p.pi[d + 1] && p.s[inside] < k2)
      {
        ++inside;
      }
      const int rows1 = inside - begin, rows2 = p.pi[d + 1] - begin;
      const Block ld(values + p.px[d] + position[d], rows2, dColumns, Eigen::OuterStride<>(dRows));
      update.resize(static_cast<std::size_t>(rows2) * rows1);
      Eigen::Map<Matrix> c(update.data(), rows2, rows1);
      c.topRows(rows1).template triangularView<Eigen::Lower>() = ld.topRows(rows1) * ld.topRows(rows1).adjoint();
      if (rows2 > rows1)
      {
        c.bottomRows(rows2 - rows1).noalias() = ld.bottomRows(rows2 - rows1) * ld.topRows(rows1).adjoint();
      }
      for (int j = 0; j < rows1; ++j)
      {
        Scalar* column = target + static_cast<std::size_t>(map[p.s[begin + j]]) * rows;
        const Scalar* from = update.data() + static_cast<std::size_t>(j) * rows2;
        for (int i = j; i < rows2; ++i)
        {
          column[map[p.s[begin + i]]] -= from[i];
        }
      }
      position[d] = inside - dFirst;
      if (position[d] < dRows)
      {
        const int t = supernodeOf[p.s[inside]];
        next[d] = head[t];
        head[t] = d;
      }
      d = following;
    }
    // The diagonal block's Cholesky factor, then the rows below: L21 = A21 L11^-H, on a copy
    // aligned for Eigen's widest vectors: some of Eigen's complex kernels sum in an order that
    // depends on where their data starts, and the factor's values may start anywhere.
    aligned.assign(target, target + static_cast<std::size_t>(rows) * columns);
    Block block(aligned.data(), rows, columns, Eigen::OuterStride<>(rows));
    BlockRef diagonal = block.topRows(columns);
    Eigen::LLT<BlockRef> llt(diagonal); // L L^H, lower triangle, in place
    if (llt.info() != Eigen::Success)
    {
      return k1;
    }
    // Eigen's test (a pivot <= 0) lets a NaN through: a factor with one is refused too.
    for (int r = 0; r < columns; ++r)
    {
      if (!std::isfinite(Eigen::numext::real(diagonal(r, r))))
      {
        return k1 + r;
      }
    }
    if (rows > columns)
    {
      diagonal.template triangularView<Eigen::Lower>().adjoint().template solveInPlace<Eigen::OnTheRight>(
        block.bottomRows(rows - columns));
      const int t = supernodeOf[p.s[firstRow + columns]];
      position[s] = columns;
      next[s] = head[t];
      head[t] = s;
    }
    std::copy(aligned.begin(), aligned.end(), target);
    for (int k = 0; k < rows; ++k)
    {
      map[p.s[firstRow + k]] = -1;
    }
  }
  return -1;
}

} // namespace

extern "C" __attribute__((visibility("default"))) int KERF_SUPERNODAL_ENTRY(const kerf::SupernodalProblem* problem)
{
  if (problem->complex)
  {
    using Complex = std::complex<double>;
    return factorize<Complex>(
      *problem, reinterpret_cast<const Complex*>(problem->ax), reinterpret_cast<Complex*>(problem->values));
  }
  return factorize<double>(*problem, problem->ax, problem->values);
}
