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

#define GENERATE_LANES 8 /* samples a work-item takes (host: kGenerateLanes, render/sampler.h) */

/* A work-item takes GENERATE_LANES samples and, for a distributed camera,
 * draws their instants and lens points in vector lanes (ray_sample_1d8,
 * ray_sample_2d8): one sample at a time, the sampler's chains of dependent
 * multiplies were most of this kernel's time (PoCL runs a work-group's items
 * one after another without vectorising across them). */
__kernel void generate(__global const CameraGpu* camera, __global const float* xy, __global const int* aov_pixel,
                       int first_key, int spp, long group_base, int strata, int count, int distributed,
                       __global RayGpu* rays) {
  int first = get_global_id(0) * GENERATE_LANES;
  if (first >= count) return;
  int lanes = min(GENERATE_LANES, count - first);
  int sample[GENERATE_LANES], group[GENERATE_LANES];
  for (int l = 0; l < GENERATE_LANES; ++l) { /* lanes past the launch repeat its last sample */
    int key = first_key + first + min(l, lanes - 1);
    sample[l] = key % spp;
    group[l] = (int)((group_base + (long)key) / (long)spp);
  }
  float u_time[GENERATE_LANES], lens_x[GENERATE_LANES], lens_y[GENERATE_LANES];
  if (distributed) {
    uint seed = (uint)camera->seed;
    int8 group8 = vload8(0, group), sample8 = vload8(0, sample);
    float8 lx, ly;
    ray_sample_2d8(seed, strata, group8, sample8, (int8)(DIM_LENS), (int8)(0), (int8)(1), &lx, &ly);
    vstore8(ray_sample_1d8(seed, strata, group8, sample8, DIM_TIME), 0, u_time);
    vstore8(lx, 0, lens_x);
    vstore8(ly, 0, lens_y);
  }
  for (int l = 0; l < lanes; ++l) {
    int k = first + l;
    float3 o, d;
    float time;
    if (distributed) {
      camera_ray(camera, xy[2 * k], xy[2 * k + 1], u_time[l], (float2)(lens_x[l], lens_y[l]), &o, &d, &time);
    } else {
      o = load3g(camera->origin);
      d = camera_ray_dir(camera, xy[2 * k], xy[2 * k + 1]);
      time = camera->shutter_open;
    }
    RayGpu r = ray_make(o, d, 0.0f, PRISM_INF, (float3)(1.0f, 1.0f, 1.0f), first_key + k, 0, RAY_KIND_PRIMARY,
                        sample[l]);
    r.aov_pixel = aov_pixel[k];
    r.time = time;
    r.dim = DIM_FIRST_HIT;
    r.strata_id = group[l];
    rays[k] = r;
  }
}
