// Buffer transfers for Oclgrind's uninitialised-value checker (PRISM_HOST_TRANSFERS=1,
// tests/oclgrind/check.sh), which tracks what kernels and the host wrote in shadow
// memory but has two blind spots prism's transfers would fall into:
//  - it does not see clEnqueueFillBuffer or clEnqueueCopyBuffer, so what they wrote
//    would read as unwritten;
//  - each host write gives the whole buffer new shadow memory the size of that write
//    (Oclgrind's Uninitialized::hostMemoryStore allocates it afresh), so after a
//    write of part of a buffer every byte beyond it reads as unwritten and kernels'
//    later stores there are dropped.
//  - it keeps a released buffer's shadow memory, and a buffer made later in the same
//    slot takes it over: stale sizes and contents again.
// So in that mode a fill, a copy and a write of part of a buffer all go through a
// copy kernel, whose loads and stores the checker follows byte for byte (the bytes
// of a fill or a partial write are first written whole to a staging buffer of their
// exact size), and buffers are never released. Slow, and for that check only.
#pragma once

#include <cstddef>

#include <CL/cl.h>

namespace prism {

// Whether PRISM_HOST_TRANSFERS=1 (read once).
bool checkedTransfers();

// Copies `bytes` from `from` at `from_offset` to `to` at `to_offset` with a kernel.
void checkedCopy(cl_command_queue queue, cl_mem from, size_t from_offset, cl_mem to, size_t to_offset, size_t bytes);
// Writes host bytes to `to` at `offset` through a staging buffer and the copy kernel.
void checkedWrite(cl_command_queue queue, cl_mem to, size_t offset, const void* data, size_t bytes);
// clReleaseMemObject, except in that mode, where the buffer is kept to the end of
// the process so that no later buffer takes its slot.
void releaseBuffer(cl_mem buffer);

}  // namespace prism
