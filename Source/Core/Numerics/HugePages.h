// Large work buffers backed by transparent huge pages, where the system offers them.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace kerf
{

/// Buffers of at least this many bytes are worth huge pages: 2 MiB, one of them.
constexpr std::size_t HugePageMinimumBytes = std::size_t(2) << 20;

/// Asks the kernel to back the whole 2 MiB pages inside [data, data + bytes) with transparent
/// huge pages (madvise MADV_HUGEPAGE), for a buffer of at least HugePageMinimumBytes that has not
/// been written yet. Each first write to a fresh page costs a page fault; a huge page takes one
/// fault where 4 KiB pages take 512. Where the system has no transparent huge pages (or they are
/// disabled) this does nothing, and results never depend on it. Documentation/filters/Geodesics.md
/// (*Huge pages*) has the figures, the cost included.
void adviseHugePages(void* data, std::size_t bytes) noexcept;

namespace detail
{
/// A block from aligned_alloc, aligned to 2 MiB, its size rounded up to whole 2 MiB pages, and
/// advised (adviseHugePages); free() releases it. Throws std::bad_alloc.
void* allocateAlignedHugePages(std::size_t bytes);
/// Blocks of at least HugePageMinimumBytes: allocateAlignedHugePages; smaller ones: operator new.
/// Freed by the same rule, from the size the block was allocated with.
void* allocateHugePageBytes(std::size_t bytes);
void deallocateHugePageBytes(void* p, std::size_t bytes) noexcept;
}

/// An allocator whose blocks of at least HugePageMinimumBytes are aligned to 2 MiB and advised
/// with adviseHugePages; smaller blocks come from operator new.
template <class T>
struct HugePageAllocator
{
  static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__, "small blocks come from operator new");
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept
  {
  }

  T* allocate(std::size_t n)
  {
    if (n > static_cast<std::size_t>(-1) / sizeof(T))
    {
      throw std::bad_array_new_length();
    }
    return static_cast<T*>(detail::allocateHugePageBytes(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { detail::deallocateHugePageBytes(p, n * sizeof(T)); }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept
  {
    return true;
  }
  template <class U>
  bool operator!=(const HugePageAllocator<U>&) const noexcept
  {
    return false;
  }
};

/// A std::vector for large work buffers (HugePageAllocator).
template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

} // namespace kerf
