#include "accel/accel_buffers.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace prism {
namespace {

// A device buffer holding v (one element's worth of zeros when v is empty:
// OpenCL has no empty buffers).
template <typename T>
Buffer uploadVector(Context& context, const std::vector<T>& v) {
  Buffer b(context, std::max<std::size_t>(1, v.size()) * sizeof(T));
  b.writeVector(v);
  return b;
}

}  // namespace

void GeometryBuffers::upload(Context& context, const SceneGeometry& geometry) {
  constexpr std::size_t kMaxInt = static_cast<std::size_t>(std::numeric_limits<int>::max());
  if (geometry.primitive_count > kMaxInt || geometry.mesh_data.size() > kMaxInt)
    throw std::invalid_argument("scene too large: more than 2^31 - 1 primitives or mesh values");
  m_objects = uploadVector(context, deviceRecords(geometry));
  m_triangles = uploadVector(context, geometry.triangles);
  m_mesh_data = uploadVector(context, geometry.mesh_data);
  m_prim_count = static_cast<int>(geometry.primitive_count);
  m_triangle_base = static_cast<int>(geometry.triangle_base);
  m_mesh_count = static_cast<int>(geometry.mesh_count);
}

KernelLaunch& GeometryBuffers::bind(KernelLaunch& launch) const {
  return launch.arg(m_objects).arg(m_prim_count).arg(m_triangle_base).arg(m_mesh_count).arg(m_triangles).arg(
      m_mesh_data);
}

void AccelBuffers::upload(Context& context, const DeviceAccel& accel) {
  m_nodes = Buffer(context, accel.nodes.size() * sizeof(AccelWord));
  m_nodes.writeVector(accel.nodes);
  m_packets = Buffer(context, accel.packets.size() * sizeof(TriPacketGpu));
  m_packets.writeVector(accel.packets);
  m_unbounded = Buffer(context, accel.unbounded.size() * sizeof(std::int32_t));
  m_unbounded.writeVector(accel.unbounded);
  m_unbounded_count = static_cast<int>(accel.unbounded.size());
}

KernelLaunch& AccelBuffers::bind(KernelLaunch& launch, const GeometryBuffers& geometry) const {
  return geometry.bind(launch).arg(m_nodes).arg(m_packets).arg(m_unbounded).arg(m_unbounded_count);
}

}  // namespace prism
