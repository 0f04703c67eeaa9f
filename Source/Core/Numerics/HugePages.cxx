// Transparent huge pages for large work buffers (madvise MADV_HUGEPAGE on Linux).
#include "Numerics/HugePages.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace kerf
{

namespace
{
constexpr std::size_t HugePageBytes = std::size_t(2) << 20;
}

void adviseHugePages(void* data, std::size_t bytes) noexcept
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (!data || bytes < HugePageMinimumBytes)
  {
    return;
  }
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + HugePageBytes - 1) & ~(HugePageBytes - 1);
  const std::uintptr_t last = (begin + bytes) & ~(HugePageBytes - 1);
  if (first < last)
  {
    // Advice only: a refusal (EINVAL where the kernel has no huge pages) leaves 4 KiB pages.
    (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  }
#else
  (void)data;
  (void)bytes;
#endif
}

namespace detail
{
void* allocateHugePageBytes(std::size_t bytes)
{
  return bytes < HugePageMinimumBytes ? ::operator new(bytes) : allocateAlignedHugePages(bytes);
}

void* allocateAlignedHugePages(std::size_t bytes)
{
  // aligned_alloc wants a multiple of the alignment; the rounding is address space, never touched.
  const std::size_t rounded = (bytes + HugePageBytes - 1) & ~(HugePageBytes - 1);
  if (rounded < bytes)
  {
    throw std::bad_alloc();
  }
  void* p = std::aligned_alloc(HugePageBytes, rounded);
  if (!p)
  {
    throw std::bad_alloc();
  }
  adviseHugePages(p, rounded);
  return p;
}

void deallocateHugePageBytes(void* p, std::size_t bytes) noexcept
{
  if (bytes < HugePageMinimumBytes)
  {
    ::operator delete(p);
  }
  else
  {
    std::free(p);
  }
}
} // namespace detail

} // namespace kerf
