// The numeric supernodal Cholesky factorization of a CHOLMOD symbolic factor with Kerf's
// driver and Eigen's dense kernels for the processor, CHOLMOD's own factorization otherwise.
#pragma once

#ifdef KERF_HAVE_CHOLMOD
#include <cholmod.h>

#include <Eigen/SparseCore>

#include <complex>
#include <type_traits>
#endif

namespace kerf
{

/// Who computes a supernodal factor's values.
enum class SupernodalRoute
{
  Automatic, ///< Kerf's kernels where the processor has AVX2 and FMA (the widest level it has), else CHOLMOD
  CHOLMOD,   ///< cholmod_factorize, with the BLAS CHOLMOD was linked with
  AVX2,      ///< Kerf's driver, Eigen's kernels for x86-64-v3 (AVX2, FMA)
  AVX512     ///< Kerf's driver, Eigen's kernels for x86-64-v4 (AVX-512)
};

/// True if `route` can run here (CHOLMOD always; Kerf's levels when built for this processor
/// family and the processor has the instructions).
bool supernodalRouteAvailable(SupernodalRoute route);

/// The route Automatic takes on this processor: the widest it has, or the narrower one the
/// environment variable KERF_SUPERNODAL_ROUTE names ("avx2", or "cholmod"), read once.
SupernodalRoute automaticSupernodalRoute();

#ifdef KERF_HAVE_CHOLMOD
/// A cholmod_sparse view (no copy) of a compressed column-major Eigen matrix of doubles or complex
/// doubles: stype -1 reads its lower triangle, 0 the whole matrix.
template <typename Scalar>
cholmod_sparse cholmodView(const Eigen::SparseMatrix<Scalar, Eigen::ColMajor, int>& A, int stype)
{
  static_assert(std::is_same<Scalar, double>::value || std::is_same<Scalar, std::complex<double>>::value,
    "CHOLMOD views hold doubles or complex doubles");
  cholmod_sparse s{};
  s.nrow = static_cast<std::size_t>(A.rows());
  s.ncol = static_cast<std::size_t>(A.cols());
  s.nzmax = static_cast<std::size_t>(A.nonZeros());
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<Scalar*>(A.valuePtr());
  s.stype = stype;
  s.itype = CHOLMOD_INT;
  s.xtype = std::is_same<Scalar, double>::value ? CHOLMOD_REAL : CHOLMOD_COMPLEX;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

/// cholmod_start(common), the way every Kerf CHOLMOD workspace starts.
int startCholmod(cholmod_common* common);

/// While one is alive, on any thread, SuiteSparse's allocator is Kerf's: blocks of
/// HugePageMinimumBytes and more (factor values, the analysis's workspace) aligned to 2 MiB and
/// advised for transparent huge pages, so that fresh memory faults in 2 MiB at a time, not 4 KiB
/// (HugePages.h). The first scope installs it only if SuiteSparse's allocator is then the C
/// library's malloc; the last to end puts malloc back, so the process's allocator is its own
/// outside Kerf's analyses and factorizations, which hold one (factorizeSupernodal does itself).
/// Every block is freed by free(), whichever allocator is installed when it is freed. Another
/// SuiteSparse user allocating on another thread while a scope is alive gets the same blocks.
class CholmodAllocatorScope
{
public:
  CholmodAllocatorScope();
  ~CholmodAllocatorScope();
  CholmodAllocatorScope(const CholmodAllocatorScope&) = delete;
  CholmodAllocatorScope& operator=(const CholmodAllocatorScope&) = delete;
};

/// Whether Kerf's allocator is SuiteSparse's now (a CholmodAllocatorScope is alive and installed it).
bool cholmodAllocatorInstalled();

/// Drop-in for cholmod_factorize(A, L, common): factors the real symmetric or complex Hermitian A
/// (stype -1, lower triangle read; CHOLMOD_REAL or CHOLMOD_COMPLEX) into L, whose symbolic
/// analysis (cholmod_analyze or cholmod_analyze_p) it must be. Kerf's route runs when L is
/// supernodal (symbolic, or with values of A's kind already allocated, which it overwrites), A
/// packed, and the route available: it fills L's values as cholmod_factorize would (L L^H, values to rounding; a
/// supernode's diagonal block keeps zeros above its diagonal) and sets L->minor to n, or to the
/// first column of the supernode that is not positive definite (then it returns true and
/// common->status is CHOLMOD_NOT_POSDEF, as with CHOLMOD). Otherwise, and for the CHOLMOD route,
/// it calls cholmod_factorize. Returns false when the factorization could not run (out of memory,
/// invalid input; on Kerf's route also an A with an entry outside the analysed pattern, which
/// cholmod_factorize does not check: common->status is then CHOLMOD_INVALID). Deterministic: one
/// route on one machine gives the same bits every time.
bool factorizeSupernodal(
  cholmod_sparse* A, cholmod_factor* L, cholmod_common* common, SupernodalRoute route = SupernodalRoute::Automatic);
#endif

} // namespace kerf
