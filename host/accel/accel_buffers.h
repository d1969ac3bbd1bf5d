// The device copies of a DeviceAccel and the one way kernels get them: bind()
// appends ACCEL_PARAMS (kernels/accel/accel.h) to a launch, the same list for
// every structure.
#pragma once

#include "accel/accel_structure.h"
#include "device/context.h"

namespace prism {

class AccelBuffers {
 public:
  AccelBuffers() = default;
  AccelBuffers(Context& context, const DeviceAccel& accel) { upload(context, accel); }

  void upload(Context& context, const DeviceAccel& accel);
  // objects, object_count, nodes, packets, unbounded, unbounded_count.
  KernelLaunch& bind(KernelLaunch& launch, const Buffer& objects, int object_count) const;

 private:
  Buffer m_nodes, m_packets, m_unbounded;
  int m_unbounded_count = 0;
};

}  // namespace prism
