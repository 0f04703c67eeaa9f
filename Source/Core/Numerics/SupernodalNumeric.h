// The numeric supernodal Cholesky factorization on a symbolic analysis (the interface of the
// kernels compiled per instruction set; Numerics/SupernodalFactorization.h is the one to call).
#pragma once

#include <cstddef>

namespace kerf
{

/// A symmetric (real) or Hermitian (complex) matrix and the symbolic supernodal factor
/// L L^H = P A P^T of CHOLMOD's layout (cholmod_factor: super, pi, px, s, Perm; int indices), with
/// the values to fill. Complex values are interleaved (real, imaginary), as CHOLMOD_COMPLEX and
/// std::complex<double> store them.
struct SupernodalProblem
{
  bool complex = false;
  int n = 0;
  int supernodes = 0;
  const int* super = nullptr; ///< supernodes + 1: the first column of each supernode
  const int* pi = nullptr;    ///< supernodes + 1: where each supernode's row indices start in s
  const int* px = nullptr;    ///< supernodes + 1: where each supernode's values start
  const int* s = nullptr;     ///< the row indices (a supernode's own columns first, in order)
  const int* perm = nullptr;  ///< n: perm[k] is the row of A eliminated k-th
  // A in compressed columns (packed); only the entries with row >= column are read (values:
  // one double each, or two when complex).
  const int* ap = nullptr;
  const int* ai = nullptr;
  const double* ax = nullptr;
  double* values = nullptr; ///< px[supernodes] values (doubles, or pairs when complex): each supernode a column-major
                            ///< rows x columns block
};

} // namespace kerf

namespace kerf
{
/// What the kernels return when A has an entry outside the pattern the factor was analysed for.
constexpr int SupernodalOutsidePattern = -2;
}

/// Fills problem->values with the factor. Returns -1; or the first column (in elimination
/// order) of the supernode whose diagonal block is not positive definite; or
/// kerf::SupernodalOutsidePattern, when A has an entry the analysis did not see (nothing is
/// written outside the factor's values).
extern "C" int kerf_supernodal_numeric_x86_64_v3(const kerf::SupernodalProblem* problem);
extern "C" int kerf_supernodal_numeric_x86_64_v4(const kerf::SupernodalProblem* problem);
