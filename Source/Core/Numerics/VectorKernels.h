// Eight-wide double vectors and the per-processor clones of the dense solve kernels (AVX-512, AVX2 with FMA, baseline).
#pragma once

// The kernels inline their vector helpers, so no vector crosses a call boundary.
#pragma GCC diagnostic ignored "-Wpsabi"

/// A kernel compiled for AVX-512, AVX2 with FMA and the x86-64 baseline; the processor picks one
/// when the library loads.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define KERF_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define KERF_VECTOR_CLONES
#endif
#define KERF_INLINE inline __attribute__((always_inline))

namespace kerf
{
/// Eight doubles, lowered to one AVX-512, two AVX2 or four SSE2 registers by each clone.
typedef double Vector8 __attribute__((vector_size(8 * sizeof(double))));

KERF_INLINE Vector8 loadVector8(const double* p)
{
  Vector8 v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

KERF_INLINE void storeVector8(double* p, const Vector8& v)
{
  __builtin_memcpy(p, &v, sizeof v);
}
} // namespace kerf
