// The device copies of the scene's geometry and of a DeviceAccel, and the one
// way kernels get them: bind() appends GEOMETRY_KERNEL_PARAMS
// (kernels/geometry/primitive.h) and ACCEL_KERNEL_PARAMS
// (kernels/accel/accel.h) to a launch, the same list for every structure.
#pragma once

#include "accel/accel_structure.h"
#include "accel/scene_geometry.h"
#include "device/context.h"

namespace prism {

class GeometryBuffers {
 public:
  GeometryBuffers() = default;
  GeometryBuffers(Context& context, const SceneGeometry& geometry) { upload(context, geometry); }

  void upload(Context& context, const SceneGeometry& geometry);
  // objects, prim_count, triangle_base, mesh_count, triangles, mesh_data.
  KernelLaunch& bind(KernelLaunch& launch) const;
  std::size_t bytes() const { return m_objects.bytes() + m_triangles.bytes() + m_mesh_data.bytes(); }

 private:
  Buffer m_objects, m_triangles, m_mesh_data;
  int m_prim_count = 0, m_triangle_base = 0, m_mesh_count = 0;
};

class AccelBuffers {
 public:
  AccelBuffers() = default;
  AccelBuffers(Context& context, const DeviceAccel& accel) { upload(context, accel); }

  void upload(Context& context, const DeviceAccel& accel);
  // The geometry's arguments, then nodes, packets, unbounded, unbounded_count.
  KernelLaunch& bind(KernelLaunch& launch, const GeometryBuffers& geometry) const;

 private:
  Buffer m_nodes, m_packets, m_unbounded;
  int m_unbounded_count = 0;
};

}  // namespace prism
