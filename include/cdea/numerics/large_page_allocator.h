#pragma once
// An allocator for the arrays that outgrow the caches (the band tangent and
// its LU factors of a fine mesh: 28 MiB at 16384 elements). Each pass over
// such an array touches one 4 KiB page per 512 doubles, and the TLB misses
// of a pass cost as much as its arithmetic; blocks of at least 4 MiB are
// aligned to 2 MiB and offered to the kernel as transparent huge pages
// (madvise; the kernel may decline, and nothing else changes). Smaller
// blocks come from malloc as before.

#include <cstddef>
#include <new>

namespace cdea
{
  /// @p bytes of storage (huge-page aligned from large_block_bytes on);
  /// nullptr if there is no memory.
  void *allocate_possibly_large(std::size_t bytes);
  void  release_possibly_large(void *block);

  /// Blocks from this size on are offered as huge pages.
  constexpr std::size_t large_block_bytes = std::size_t(4) << 20;

  template <typename T>
  struct LargePageAllocator
  {
    using value_type = T;

    LargePageAllocator() = default;
    template <typename U>
    LargePageAllocator(const LargePageAllocator<U> &)
    {}

    T *allocate(const std::size_t n)
    {
      if (n > std::size_t(-1) / sizeof(T))
        throw std::bad_alloc();
      void *block = allocate_possibly_large(n * sizeof(T));
      if (block == nullptr)
        throw std::bad_alloc();
      return static_cast<T *>(block);
    }
    void deallocate(T *block, std::size_t) { release_possibly_large(block); }

    template <typename U>
    bool operator==(const LargePageAllocator<U> &) const
    {
      return true;
    }
    template <typename U>
    bool operator!=(const LargePageAllocator<U> &) const
    {
      return false;
    }
  };
} // namespace cdea
