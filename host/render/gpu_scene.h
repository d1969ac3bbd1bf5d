// Flattens the host scene model into the plain arrays the kernels read
// (kernels/shared/*_gpu.h).
#pragma once

#include <vector>

#include "kernels/shared/camera_gpu.h"
#include "kernels/shared/light_gpu.h"
#include "kernels/shared/material_gpu.h"
#include "kernels/shared/object_gpu.h"
#include "render/render_options.h"
#include "scene/scene.h"

namespace prism {

struct GpuScene {
  // Every primitive (the index is its primid), then the motion records of the
  // moving ones (kernels/shared/motion_gpu.h) and the data records of kinds
  // with side data (ObjectDataGpu), which are not primitives.
  std::vector<ObjectGpu> objects;
  std::size_t primitive_count = 0;
  std::vector<MaterialGpu> materials;
  // The image textures' texels, each image once: linear RGB, float4 each
  // (MaterialGpu::image_offset counts in them); at least one texel.
  std::vector<float> texels;
  std::vector<LightGpu> lights;
  CameraGpu camera{};
  float ambient[4] = {0, 0, 0, 0};     // render.ambient, rgb
  float background[4] = {0, 0, 0, 0};  // render.background, rgb
};

GpuScene flattenScene(const Scene& scene, const RenderOptions& options);

// The camera basis in double precision, shared by flattenScene and the tests'
// reference ray generator: ray direction for film point (x, y) in [-1, 1]^2 is
// forward + x * right + y * up (not normalised).
struct CameraBasis {
  Vec3 origin, forward, right, up;
};
CameraBasis cameraBasis(const Camera& camera, int width, int height);

}  // namespace prism
