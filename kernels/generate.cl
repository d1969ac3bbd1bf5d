/* generate: one primary ray per film position. Sample k of the launch sits at
 * (xy[2k], xy[2k+1]) in film coordinates (x in [0, W] to the right, y in [0, H]
 * down; pixel (i, j) covers [i, i+1] x [j, j+1], DESIGN.md's camera contract) and
 * becomes the camera's ray through that point (sampling/camera_ray.h), at an
 * instant of the shutter and through a point of the lens drawn from the sampler
 * (sampling/dimensions.h). Its film key is first_key + k, its index in the
 * image's sample sequence: the per-sample film entry its light is added to
 * (docs/architecture.md); group_base + key, divided by spp, names the group of
 * samples whose strata it shares (its pixel). aov_pixel[k] is the pixel whose
 * AOVs the sample writes, or -1 (kernels/supersample.cl). distributed: the
 * camera has a lens or a shutter interval (host: Camera::isPinhole); a pinhole
 * at one instant takes camera_ray_dir, the Z-buffer pass's own arithmetic. */
#include "sampling/camera_ray.h"
#include "sampling/dimensions.h"
#include "shading/ray_io.h"

__kernel void generate(__global const CameraGpu* camera, __global const float* xy, __global const int* aov_pixel,
                       int first_key, int spp, long group_base, int strata, int count, int distributed,
                       __global RayGpu* rays) {
  int k = get_global_id(0);
  if (k >= count) return;
  int key = first_key + k;
  int sample = key % spp;
  int group = (int)((group_base + (long)key) / (long)spp);
  float3 o, d;
  float time;
  if (distributed) {
    uint seed = (uint)camera->seed;
    float u_time = ray_sample_1d(seed, strata, group, sample, DIM_TIME);
    float2 u_lens = ray_sample_2d(seed, strata, group, sample, DIM_LENS, 0, 1);
    camera_ray(camera, xy[2 * k], xy[2 * k + 1], u_time, u_lens, &o, &d, &time);
  } else {
    o = load3g(camera->origin);
    d = camera_ray_dir(camera, xy[2 * k], xy[2 * k + 1]);
    time = camera->shutter_open;
  }
  RayGpu r = ray_make(o, d, 0.0f, PRISM_INF, (float3)(1.0f, 1.0f, 1.0f), key, 0, RAY_KIND_PRIMARY, sample);
  r.aov_pixel = aov_pixel[k];
  r.time = time;
  r.dim = DIM_FIRST_HIT;
  r.strata_id = group;
  rays[k] = r;
}
