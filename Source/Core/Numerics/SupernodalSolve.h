// Triangular solves with one or several right-hand sides on a CHOLMOD supernodal factor, with vector kernels chosen per
// processor.
#pragma once

#ifdef KERF_HAVE_CHOLMOD
#include <cholmod.h>

#include <complex>
#include <vector>

namespace kerf
{

/// Solves with a real supernodal CHOLMOD factor L L^T = P A P^T (or a complex L L^H), one right-hand side, the
/// dense kernels inline: each supernode's triangle and the block below it are swept column by
/// column with vector instructions compiled for AVX-512, AVX2 with FMA and the x86-64 baseline
/// (the processor picks one when the library loads). CHOLMOD's own solve calls the BLAS once or
/// twice per supernode (dtrsv, dgemv), whose kernels are chosen when the BLAS loads and can miss
/// the processor (OpenBLAS 0.3.21 runs its SSE3 kernels on some AVX-512 Xeons);
/// Documentation/filters/HarmonicCuts.md ("Low-rank kernels") compares the two. The results
/// differ from CHOLMOD's in the last bits only; on one machine they are the same bit for bit
/// run after run. Workspace is resized as needed.
class SupernodalSolve
{
public:
  /// True if `factor` is one these solves take: supernodal, real, double precision.
  static bool supports(const cholmod_factor& factor);

  /// y := L^-1 y, y in the factor's (permuted) row order.
  static void forward(const cholmod_factor& factor, double* y, std::vector<double>& workspace);
  /// y := L^-T y, y in the factor's (permuted) row order.
  static void backward(const cholmod_factor& factor, double* y, std::vector<double>& workspace);
  /// x = A^-1 b (b and x in A's row order; they may be the same array).
  static void solve(const cholmod_factor& factor, const double* b, double* x, std::vector<double>& workspace);
  /// X = A^-1 B for `columns` right-hand sides (B and X column-major, n x columns; they may be
  /// the same array) in one sweep over the factor: each supernode's block is read from memory
  /// once and applied to every column while it is in the cache. Each column's arithmetic is
  /// solve()'s, so the columns equal solve()'s bit for bit.
  static void solveColumns(
    const cholmod_factor& factor, const double* b, double* x, int columns, std::vector<double>& workspace);

  /// True if `factor` is one solveComplex takes: supernodal, complex (L L^H), double precision.
  static bool supportsComplex(const cholmod_factor& factor);
  /// x = A^-1 b for a Hermitian A factored by CHOLMOD into a complex supernodal L L^H (b and x in
  /// A's row order; they may be the same array). The same kernels, four complex numbers per vector.
  static void solveComplex(const cholmod_factor& factor, const std::complex<double>* b, std::complex<double>* x,
    std::vector<double>& workspace);
};

} // namespace kerf
#endif
