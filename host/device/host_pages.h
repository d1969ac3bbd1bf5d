// Host memory in pages the operating system may back with 2 MiB huge pages,
// for a CPU device's large buffers (docs/devices.md, "Where a buffer's memory
// lives"; what it is worth, docs/accel.md, "What the size costs each side, and
// huge pages").
#pragma once

#include <cstddef>

namespace prism {

constexpr std::size_t kHugePageBytes = std::size_t{1} << 21;

struct HostPages {
  void* data = nullptr;
  std::size_t bytes = 0;  // a whole number of huge pages
};

// At least `bytes` of fresh, zeroed memory of its own mapping, aligned to a
// huge page and advised to use them; data is null where none could be had.
HostPages allocateHostPages(std::size_t bytes);
void freeHostPages(const HostPages& pages);

}  // namespace prism
