// Flattens the host scene model into the plain arrays the kernels read
// (kernels/shared/*_gpu.h).
#pragma once

#include <vector>

#include "accel/scene_geometry.h"
#include "kernels/shared/camera_gpu.h"
#include "kernels/shared/light_gpu.h"
#include "kernels/shared/material_gpu.h"
#include "kernels/shared/object_gpu.h"
#include "render/render_options.h"
#include "scene/scene.h"

namespace prism {

// The geometry (accel/scene_geometry.h): the analytic primitives first, in
// scene order, then the meshes' triangles, mesh by mesh in scene order.
struct GpuScene : SceneGeometry {
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
