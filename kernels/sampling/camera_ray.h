/* The primary ray direction through a film position (x in [0, W], y in [0, H],
 * pixel (i, j) covering [i, i+1] x [j, j+1], y down): the same arithmetic as
 * kernels/generate.cl, so a sample traced either way meets the same hit. */
#ifndef PRISM_SAMPLING_CAMERA_RAY_H
#define PRISM_SAMPLING_CAMERA_RAY_H

#include "common/math.h"
#include "shared/camera_gpu.h"

inline float3 camera_ray_dir(__global const CameraGpu* camera, float fx, float fy) {
  float x = 2.0f * fx / (float)camera->width - 1.0f;
  float y = 1.0f - 2.0f * fy / (float)camera->height;
  return normalize(load3g(camera->forward) + x * load3g(camera->right) + y * load3g(camera->up));
}

#endif
