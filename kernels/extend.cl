/* extend: the closest hit of each ray in a queue. */
#include "accel/accel.h"
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
