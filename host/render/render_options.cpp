#include "render/render_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace prism {

RenderOptions RenderOptions::fromScene(const Scene& scene) {
  RenderOptions o;
  o.width = scene.film.width;
  o.height = scene.film.height;
  o.spp = scene.film.spp;
  o.max_depth = scene.render.max_depth;
  o.min_weight = scene.render.min_weight;
  o.seed = scene.render.seed;
  o.accel = parseAccelKind(scene.render.accel);
  return o;
}

void RenderOptions::validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
  if (width < 1 || width > 32768) fail("width must be in 1..32768, got " + std::to_string(width));
  if (height < 1 || height > 32768) fail("height must be in 1..32768, got " + std::to_string(height));
  if (static_cast<long long>(width) * height > (1ll << 28)) fail("width x height must be at most 2^28 pixels");
  if (spp < 1 || spp > 65536) fail("spp must be in 1..65536, got " + std::to_string(spp));
  if (max_depth < 0 || max_depth > 31) fail("max_depth must be in 0..31, got " + std::to_string(max_depth));
  if (!(min_weight >= 0 && min_weight <= 1)) fail("min_weight must be in [0, 1], got " + std::to_string(min_weight));
}

}  // namespace prism
