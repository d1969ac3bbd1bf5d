/* occlude: trace each shadow feeler and turn it into the light it brings to its
 * pixel: none through an opaque object, k_trans of each semitransparent one. */
#include "accel/accel.h"
#include "shading/ray_io.h"
#include "shared/contribution_gpu.h"

__kernel void occlude(__global const RayGpu* rays, int count, ACCEL_KERNEL_PARAMS,
                      __global const MaterialGpu* materials, __global ContributionGpu* out) {
  ACCEL_GEOMETRY;
  int k = get_global_id(0);
  if (k >= count) return;
  RayGpu r = rays[k];
  float carried = accel_transmittance(ACCEL_ARGS, materials, ray_origin(r), ray_dir(r), r.time, r.tmin, r.tmax);
  float3 light = ray_weight(r) * carried;
  ContributionGpu c;
  c.r = light.x;
  c.g = light.y;
  c.b = light.z;
  c.a = 0.0f;
  c.pixel = r.pixel;
  c.pad[0] = c.pad[1] = c.pad[2] = 0;
  out[k] = c;
}
