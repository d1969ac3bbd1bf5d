#include "accel/accel_buffers.h"

namespace prism {

void AccelBuffers::upload(Context& context, const DeviceAccel& accel) {
  m_nodes = Buffer(context, accel.nodes.size() * sizeof(AccelWord));
  m_nodes.writeVector(accel.nodes);
  m_packets = Buffer(context, accel.packets.size() * sizeof(TriPacketGpu));
  m_packets.writeVector(accel.packets);
  m_unbounded = Buffer(context, accel.unbounded.size() * sizeof(std::int32_t));
  m_unbounded.writeVector(accel.unbounded);
  m_unbounded_count = static_cast<int>(accel.unbounded.size());
}

KernelLaunch& AccelBuffers::bind(KernelLaunch& launch, const Buffer& objects, int object_count) const {
  return launch.arg(objects).arg(object_count).arg(m_nodes).arg(m_packets).arg(m_unbounded).arg(m_unbounded_count);
}

}  // namespace prism
