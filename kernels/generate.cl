/* generate: one primary ray per sample, for the samples of pixels
 * [first_pixel, first_pixel + count / spp). Camera conventions (DESIGN.md): pixel
 * (i, j) with i to the right and j down from the top row; with one sample the
 * ray passes through the pixel centre (i + 0.5, j + 0.5). */
#include "common/math.h"
#include "common/rng.h"
#include "shading/ray_io.h"
#include "shared/camera_gpu.h"

__kernel void generate(__global const CameraGpu* camera, int first_pixel, int count, __global RayGpu* rays) {
  int k = get_global_id(0);
  if (k >= count) return;
  int spp = camera->spp;
  int pixel = first_pixel + k / spp;
  int sample = k % spp;
  int i = pixel % camera->width;
  int j = pixel / camera->width;

  float sx = 0.5f, sy = 0.5f;
  if (spp > 1) {
    sx = rng_uniform((uint)camera->seed, (uint)pixel, (uint)sample, 0u);
    sy = rng_uniform((uint)camera->seed, (uint)pixel, (uint)sample, 1u);
  }
  float x = 2.0f * ((float)i + sx) / (float)camera->width - 1.0f;
  float y = 1.0f - 2.0f * ((float)j + sy) / (float)camera->height;
  float3 d = normalize(load3g(camera->forward) + x * load3g(camera->right) + y * load3g(camera->up));
  rays[k] = ray_make(load3g(camera->origin), d, 0.0f, PRISM_INF, (float3)(1.0f, 1.0f, 1.0f), pixel, 0,
                     RAY_KIND_PRIMARY, sample);
}
