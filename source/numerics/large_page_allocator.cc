#include <cdea/numerics/large_page_allocator.h>

#include <sys/mman.h>

#include <cstdlib>

namespace cdea
{
  void *allocate_possibly_large(const std::size_t bytes)
  {
    constexpr std::size_t huge_page = std::size_t(2) << 20;
    if (bytes < large_block_bytes)
      return std::malloc(bytes == 0 ? 1 : bytes);
    // aligned_alloc wants a multiple of the alignment.
    const std::size_t rounded = (bytes + huge_page - 1) / huge_page * huge_page;
    void *const       block   = std::aligned_alloc(huge_page, rounded);
#ifdef MADV_HUGEPAGE
    if (block != nullptr)
      madvise(block, rounded, MADV_HUGEPAGE); // a hint: its failure changes nothing
#endif
    return block;
  }

  void release_possibly_large(void *const block) { std::free(block); }
} // namespace cdea
