/* occlude: trace each shadow feeler and turn it into the light it brings to its
 * pixel: none through an opaque object, k_trans of each semitransparent one. */
#include "accel/accel.h"
#include "accel/packet_queries.h"
#include "shading/ray_io.h"
#include "shared/contribution_gpu.h"

PRISM_HOT ContributionGpu occlude_contribution(RayGpu r, float carried) {
  float3 light = ray_weight(r) * carried;
  ContributionGpu c;
  c.r = light.x;
  c.g = light.y;
  c.b = light.z;
  c.a = 0.0f;
  c.pixel = r.pixel;
  c.pad[0] = c.pad[1] = c.pad[2] = 0;
  return c;
}

__kernel void occlude(__global const RayGpu* rays, int count, ACCEL_KERNEL_PARAMS,
                      __global const MaterialGpu* materials, __global ContributionGpu* out) {
  ACCEL_GEOMETRY;
  int k = get_global_id(0);
  if (k >= count) return;
  RayGpu r = rays[k];
  out[k] = occlude_contribution(r, accel_transmittance(ACCEL_ARGS, materials, ray_origin(r), ray_dir(r), r.time,
                                                        r.tmin, r.tmax));
}

#ifdef PACKET_RAYS
/* The same for a queue of feelers that travel alike (host/render/ray_kernel.h):
 * work-item k answers feelers 8k to 8k + 7. */
__kernel void occlude_packets(__global const RayGpu* rays, int count, ACCEL_KERNEL_PARAMS,
                              __global const MaterialGpu* materials, __global ContributionGpu* out) {
  ACCEL_GEOMETRY;
  int first = get_global_id(0) * PACKET_RAYS;
  if (first >= count) return;
  int lanes = min(PACKET_RAYS, count - first);
  float carried[PACKET_RAYS];
  rays8_transmittance(ACCEL_ARGS, materials, rays + first, lanes, carried);
  for (int l = 0; l < lanes; ++l) out[first + l] = occlude_contribution(rays[first + l], carried[l]);
}
#endif
