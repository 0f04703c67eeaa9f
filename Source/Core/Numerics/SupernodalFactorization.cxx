// Dispatch of the numeric supernodal factorization: Kerf's driver with Eigen's kernels for the
// processor's instruction-set level (Numerics/SupernodalNumeric.cxx), or CHOLMOD's.
#include "Numerics/SupernodalFactorization.h"

#include "Numerics/HugePages.h"

#include "Numerics/SupernodalNumeric.h"

#include <cstdlib>
#include <limits>
#include <mutex>
#include <new>
#include <string>

namespace kerf
{

namespace
{

using Entry = int (*)(const SupernodalProblem*);

bool processorHas(SupernodalRoute route)
{
#if defined(KERF_HAVE_CHOLMOD) && defined(KERF_HAVE_SUPERNODAL_KERNELS) && (defined(__x86_64__) || defined(_M_X64))
  __builtin_cpu_init();
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
  switch (route)
  {
    case SupernodalRoute::AVX2:
      return avx2;
    case SupernodalRoute::AVX512:
      return avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512cd");
    default:
      return false;
  }
#else
  (void)route;
  return false;
#endif
}

Entry entryOf(SupernodalRoute route)
{
#if defined(KERF_HAVE_CHOLMOD) && defined(KERF_HAVE_SUPERNODAL_KERNELS)
  switch (route)
  {
    case SupernodalRoute::AVX2:
      return &kerf_supernodal_numeric_x86_64_v3;
    case SupernodalRoute::AVX512:
      return &kerf_supernodal_numeric_x86_64_v4;
    default:
      return nullptr;
  }
#else
  (void)route;
  return nullptr;
#endif
}

} // namespace

bool supernodalRouteAvailable(SupernodalRoute route)
{
  return route == SupernodalRoute::Automatic || route == SupernodalRoute::CHOLMOD || processorHas(route);
}

SupernodalRoute automaticSupernodalRoute()
{
  static const SupernodalRoute route = [] {
    // KERF_SUPERNODAL_ROUTE names a narrower route (to compare the routes' last bits, or to
    // make the baselines of a processor without AVX-512); a route this processor cannot run, or
    // another value, leaves the widest one.
    const char* named = std::getenv("KERF_SUPERNODAL_ROUTE");
    const std::string name = named ? named : "";
    if (name == "cholmod")
    {
      return SupernodalRoute::CHOLMOD;
    }
    if (name == "avx2" && processorHas(SupernodalRoute::AVX2))
    {
      return SupernodalRoute::AVX2;
    }
    return processorHas(SupernodalRoute::AVX512) ? SupernodalRoute::AVX512
      : processorHas(SupernodalRoute::AVX2)      ? SupernodalRoute::AVX2
                                                 : SupernodalRoute::CHOLMOD;
  }();
  return route;
}

#ifdef KERF_HAVE_CHOLMOD
namespace
{
// SuiteSparse's allocator while it is the C library's: large blocks aligned to 2 MiB and advised
// for huge pages (HugePages.h); every block is freed by free().
void* hugePageMalloc(std::size_t bytes)
{
  if (bytes < HugePageMinimumBytes)
  {
    return std::malloc(bytes);
  }
  try
  {
    return detail::allocateAlignedHugePages(bytes);
  }
  catch (const std::bad_alloc&)
  {
    return nullptr;
  }
}

using Allocator = void* (*)(std::size_t);

Allocator suiteSparseMalloc()
{
#if SUITESPARSE_MAIN_VERSION >= 7
  return SuiteSparse_config_malloc_func_get();
#else
  return SuiteSparse_config.malloc_func;
#endif
}

void setSuiteSparseMalloc(Allocator allocator)
{
#if SUITESPARSE_MAIN_VERSION >= 7
  SuiteSparse_config_malloc_func_set(allocator);
#else
  SuiteSparse_config.malloc_func = allocator;
#endif
}

// The scopes alive and whether the first installed Kerf's allocator.
std::mutex ScopeMutex;
int ScopeCount = 0;
bool ScopeInstalled = false;
} // namespace

int startCholmod(cholmod_common* common)
{
  return cholmod_start(common);
}

CholmodAllocatorScope::CholmodAllocatorScope()
{
  const std::lock_guard<std::mutex> lock(ScopeMutex);
  if (ScopeCount++ == 0 && suiteSparseMalloc() == &std::malloc)
  {
    setSuiteSparseMalloc(&hugePageMalloc);
    ScopeInstalled = true;
  }
}

CholmodAllocatorScope::~CholmodAllocatorScope()
{
  const std::lock_guard<std::mutex> lock(ScopeMutex);
  if (--ScopeCount == 0 && ScopeInstalled)
  {
    if (suiteSparseMalloc() == &hugePageMalloc)
    {
      setSuiteSparseMalloc(&std::malloc);
    }
    ScopeInstalled = false;
  }
}

bool cholmodAllocatorInstalled()
{
  const std::lock_guard<std::mutex> lock(ScopeMutex);
  return suiteSparseMalloc() == &hugePageMalloc;
}

bool factorizeSupernodal(cholmod_sparse* A, cholmod_factor* L, cholmod_common* common, SupernodalRoute route)
{
  const CholmodAllocatorScope allocator;
  if (route == SupernodalRoute::Automatic)
  {
    route = automaticSupernodalRoute();
  }
  const Entry entry = supernodalRouteAvailable(route) ? entryOf(route) : nullptr;
  // A real symmetric or complex Hermitian A (lower triangle) into a supernodal factor of the
  // same kind, symbolic or with its values' memory (a supernodal factor is always L L^H).
  const bool complex = A && A->xtype == CHOLMOD_COMPLEX;
  const int xtype = complex ? CHOLMOD_COMPLEX : CHOLMOD_REAL;
  const bool kerfRoute = entry && A && L && common && L->is_super && A->stype < 0 &&
    (A->xtype == CHOLMOD_REAL || complex) && A->dtype == CHOLMOD_DOUBLE && A->itype == CHOLMOD_INT &&
    L->itype == CHOLMOD_INT && A->packed && A->nrow == L->n && A->ncol == L->n &&
    L->n <= static_cast<std::size_t>(std::numeric_limits<int>::max()) &&
    (L->xtype == CHOLMOD_PATTERN || (L->xtype == xtype && L->x != nullptr));
  if (!kerfRoute)
  {
    return cholmod_factorize(A, L, common) != 0;
  }
  L->is_ll = 1;
  if (L->xtype == CHOLMOD_PATTERN)
  {
    // A symbolic supernodal factor gets its values' memory, as cholmod_factorize gives it.
    if (!cholmod_change_factor(xtype, 1, 1, 1, 1, L, common))
    {
      return false;
    }
  }
  SupernodalProblem problem;
  problem.complex = complex;
  problem.n = static_cast<int>(L->n);
  problem.supernodes = static_cast<int>(L->nsuper);
  problem.super = static_cast<const int*>(L->super);
  problem.pi = static_cast<const int*>(L->pi);
  problem.px = static_cast<const int*>(L->px);
  problem.s = static_cast<const int*>(L->s);
  problem.perm = static_cast<const int*>(L->Perm);
  problem.ap = static_cast<const int*>(A->p);
  problem.ai = static_cast<const int*>(A->i);
  problem.ax = static_cast<const double*>(A->x); // interleaved pairs when complex
  problem.values = static_cast<double*>(L->x);
  int failed = -1;
  try
  {
    failed = entry(&problem);
  }
  catch (const std::bad_alloc&)
  {
    common->status = CHOLMOD_OUT_OF_MEMORY;
    return false;
  }
  if (failed == SupernodalOutsidePattern)
  {
    common->status = CHOLMOD_INVALID;
    return false;
  }
  common->status = CHOLMOD_OK;
  L->minor = L->n;
  if (failed >= 0)
  {
    L->minor = static_cast<std::size_t>(failed);
    common->status = CHOLMOD_NOT_POSDEF;
  }
  return true;
}
#endif

} // namespace kerf
