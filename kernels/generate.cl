/* generate: one primary ray per film position. Sample k of the launch sits at
 * (xy[2k], xy[2k+1]) in film coordinates (x in [0, W] to the right, y in [0, H]
 * down; pixel (i, j) covers [i, i+1] x [j, j+1], DESIGN.md's camera contract) and
 * becomes a ray through that point (sampling/camera_ray.h, the arithmetic the
 * first-hit pass uses too, so both passes see the same rays). Its film key is
 * first_key + k, its index in the image's sample sequence: the per-sample film
 * entry its light is added to (docs/architecture.md). aov_pixel[k] is the pixel
 * whose AOVs the sample writes, or -1 (kernels/supersample.cl). */
#include "sampling/camera_ray.h"
#include "shading/ray_io.h"

__kernel void generate(__global const CameraGpu* camera, __global const float* xy, __global const int* aov_pixel,
                       int first_key, int spp, int count, __global RayGpu* rays) {
  int k = get_global_id(0);
  if (k >= count) return;
  int key = first_key + k;
  float3 d = camera_ray_dir(camera, xy[2 * k], xy[2 * k + 1]);
  RayGpu r = ray_make(load3g(camera->origin), d, 0.0f, PRISM_INF, (float3)(1.0f, 1.0f, 1.0f), key, 0,
                      RAY_KIND_PRIMARY, key % spp);
  r.aov_pixel = aov_pixel[k];
  rays[k] = r;
}
