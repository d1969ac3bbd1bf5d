// Settings of one render: the scene file's film/render blocks, overridden by the
// caller (CLI flags or the C API).
#pragma once

#include <cstdint>

#include "accel/accel_structure.h"
#include "scene/scene.h"

namespace prism {

struct RenderOptions {
  int width = 640;
  int height = 480;
  int spp = 1;
  int max_depth = 5;
  double min_weight = 0.01;
  std::uint64_t seed = 0;
  AccelKind accel = AccelKind::Bvh;  // spatial index for extend / occlude

  static RenderOptions fromScene(const Scene& scene);
  // Throws std::invalid_argument naming the field when a value is out of range.
  void validate() const;
};

}  // namespace prism
