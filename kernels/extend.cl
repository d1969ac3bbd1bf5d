/* extend: the closest hit of each ray in a queue. */
#include "accel/accel.h"
#include "accel/packet_queries.h"
#include "shading/ray_io.h"

__kernel void extend(__global const RayGpu* rays, int count, ACCEL_KERNEL_PARAMS, __global HitGpu* hits) {
  ACCEL_GEOMETRY;
  int k = get_global_id(0);
  if (k >= count) return;
  RayGpu r = rays[k];
  HitGpu hit;
  accel_closest(ACCEL_ARGS, ray_origin(r), ray_dir(r), r.time, r.tmin, r.tmax, &hit);
  hits[k] = hit;
}

#ifdef PACKET_RAYS
/* The same for a queue of rays that travel alike (host/render/ray_kernel.h):
 * work-item k answers rays 8k to 8k + 7. */
__kernel void extend_packets(__global const RayGpu* rays, int count, ACCEL_KERNEL_PARAMS, __global HitGpu* hits) {
  ACCEL_GEOMETRY;
  int first = get_global_id(0) * PACKET_RAYS;
  if (first >= count) return;
  rays8_closest(ACCEL_ARGS, rays + first, min(PACKET_RAYS, count - first), hits + first);
}
#endif
