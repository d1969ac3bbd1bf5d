#include "render/ray_kernel.h"

#include <string>

namespace prism {

namespace {

// The structures with a packet walk (kernels/accel/packet_queries.h): the
// octree, the BSP, and the BVH without linear motion bounds (its packet walk
// reads a node's boxes at one instant) or k-DOP node bounds (whose slabs it
// does not test).
bool packetsWalk(const DeviceAccel& accel) {
  const std::string& o = accel.kernel_options;
  if (accel.kind == AccelKind::Octree || accel.kind == AccelKind::Bsp) return true;
  return accel.kind == AccelKind::Bvh && o.find("-DPRISM_BVH_MOTION") == std::string::npos &&
         o.find("-DPRISM_BVH_KDOP") == std::string::npos;
}

}  // namespace

double packetPrimsPerRay(AccelKind kind, RayQuery query) {
  const bool closest = query == RayQuery::ClosestHits;
  switch (kind) {
    case AccelKind::Octree: return closest ? 2.0 : 1.25;
    case AccelKind::Bsp: return closest ? 0.35 : 0.0;
    default: return closest ? 1.5 : 0.25;
  }
}

bool packetsPay(const DeviceAccel& accel, const DeviceDescription& device) {
  return packetsWalk(accel) && (device.type & CL_DEVICE_TYPE_CPU) != 0;
}

RayKernel::RayKernel(Context& context, const DeviceAccel& accel, RayQuery query, PacketUse use)
    : m_context(&context),
      m_primitives(accel.stats.primitives),
      m_prims_per_ray(packetPrimsPerRay(accel.kind, query)),
      m_use(use) {
  const char* entry_file = query == RayQuery::ClosestHits ? "extend.cl" : "occlude.cl";
  const char* name = query == RayQuery::ClosestHits ? "extend" : "occlude";
  m_single = context.kernel(entry_file, name, accel.kernel_options);
  const bool compile = use == PacketUse::Always      ? packetsWalk(accel)
                       : use == PacketUse::WherePays ? packetsPay(accel, context.device())
                                                     : false;
  if (compile)
    m_packets = context.kernel(entry_file, std::string(name) + "_packets", accel.kernel_options);
}

bool RayKernel::packets(RayCoherence coherence, std::uint64_t view_rays) const {
  return m_packets && coherence == RayCoherence::Coherent &&
         (m_use == PacketUse::Always ||
          static_cast<double>(m_primitives) <= m_prims_per_ray * static_cast<double>(view_rays));
}

KernelLaunch RayKernel::launch(bool packets) const { return m_context->launch(packets ? m_packets : m_single); }

std::size_t RayKernel::workItems(std::size_t rays, bool packets) const {
  return packets ? (rays + kPacketRays - 1) / kPacketRays : rays;
}

}  // namespace prism
