// An exclusive prefix sum of a buffer of non-negative ints on the device
// (kernels/scan.cl): out[i] = in[0] + ... + in[i-1] for i <= n, so out[n] is the
// total; sums past INT_MAX read INT_MAX (kScanSaturated). Three launches, no
// round trip to the host.
#pragma once

#include <cstddef>

#include "device/context.h"

namespace prism {

constexpr int kScanSaturated = 0x7fffffff;

class DeviceScan {
 public:
  explicit DeviceScan(Context& context);
  // `out` holds at least n + 1 ints; n < 2^31.
  void exclusive(const Buffer& in, std::size_t n, Buffer& out);

 private:
  static constexpr int kBlock = 256;  // entries summed by one work-item
  Context& m_context;
  cl_kernel m_sums, m_offsets, m_apply;
  Buffer m_block_sums;
};

}  // namespace prism
