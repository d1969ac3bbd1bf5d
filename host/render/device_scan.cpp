#include "render/device_scan.h"

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace prism {

DeviceScan::DeviceScan(Context& context)
    : m_context(context),
      m_sums(context.kernel("scan.cl", "scan_block_sums")),
      m_offsets(context.kernel("scan.cl", "scan_block_offsets")),
      m_apply(context.kernel("scan.cl", "scan_apply")) {}

void DeviceScan::exclusive(const Buffer& in, std::size_t n, Buffer& out) {
  if (n >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument("DeviceScan: more than 2^31 - 1 entries");
  if (out.bytes() < (n + 1) * sizeof(std::int32_t)) throw std::invalid_argument("DeviceScan: output too small");
  if (n == 0) {
    const std::int32_t zero = 0;
    out.write(&zero, sizeof zero);
    return;
  }
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  m_block_sums.reserve(m_context, (blocks + 1) * sizeof(std::int32_t));
  m_context.launch(m_sums).arg(in).arg(static_cast<cl_int>(n)).arg(static_cast<cl_int>(kBlock)).arg(m_block_sums).run(blocks);
  m_context.launch(m_offsets).arg(m_block_sums).arg(static_cast<cl_int>(blocks)).run(1);
  m_context.launch(m_apply)
      .arg(in)
      .arg(static_cast<cl_int>(n))
      .arg(static_cast<cl_int>(kBlock))
      .arg(m_block_sums)
      .arg(static_cast<cl_int>(blocks))
      .arg(out)
      .run(blocks);
}

}  // namespace prism
