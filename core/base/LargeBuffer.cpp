// Large buffers in huge pages; see LargeBuffer.h.
#include "core/base/LargeBuffer.h"

#include <sys/mman.h>

#include <cstdlib>

namespace relief::core::inline base {

void* allocateLargeBuffer(std::size_t bytes) {
  const std::size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
  void* memory = std::aligned_alloc(kHugePageBytes, rounded);
  if (!memory)
    throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
  madvise(memory, rounded, MADV_HUGEPAGE);  // advice only: a failure changes nothing
#endif
  return memory;
}

void freeLargeBuffer(void* memory) noexcept {
  std::free(memory);
}

}  // namespace relief::core::inline base
