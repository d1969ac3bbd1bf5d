#include "device/host_pages.h"

#include <sys/mman.h>

#include <cstdint>

namespace prism {

// A mapping of its own, not the heap's: the advice stays with the pages, and
// must not reach the small allocations that would reuse them after a free.
HostPages allocateHostPages(std::size_t bytes) {
  const std::size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
  if (rounded < bytes || rounded > SIZE_MAX - kHugePageBytes) return {};
  // One huge page more than asked, then the ends cut off to the alignment.
  void* mapped = mmap(nullptr, rounded + kHugePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) return {};
  const auto start = reinterpret_cast<std::uintptr_t>(mapped);
  const std::uintptr_t aligned = (start + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
  if (aligned > start) munmap(mapped, aligned - start);
  const std::size_t tail = start + kHugePageBytes - aligned;
  if (tail > 0) munmap(reinterpret_cast<void*>(aligned + rounded), tail);
  void* data = reinterpret_cast<void*>(aligned);
#if defined(MADV_HUGEPAGE)
  // Advice only: where the system keeps huge pages off, the memory is the
  // same, in small pages.
  madvise(data, rounded, MADV_HUGEPAGE);
#endif
  return {data, rounded};
}

void freeHostPages(const HostPages& pages) {
  if (pages.data) munmap(pages.data, pages.bytes);
}

}  // namespace prism
