#include "render/render_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace prism {

FirstHitMode parseFirstHitMode(const std::string& name) {
  FirstHitMode mode;
  if (!tryParseFirstHitMode(name, &mode))
    throw std::invalid_argument("unknown first-hit mode '" + name + "' (valid: " + kFirstHitModeNames + ")");
  return mode;
}

ShadowMode parseShadowMode(const std::string& name) {
  ShadowMode mode;
  if (!tryParseShadowMode(name, &mode))
    throw std::invalid_argument("unknown shadow mode '" + name + "' (valid: " + kShadowModeNames + ")");
  return mode;
}

RenderOptions RenderOptions::fromScene(const Scene& scene) {
  RenderOptions o;
  o.width = scene.film.width;
  o.height = scene.film.height;
  o.spp = scene.film.spp;
  o.max_depth = scene.render.max_depth;
  o.min_weight = scene.render.min_weight;
  o.seed = scene.render.seed;
  o.accel = parseAccelKind(scene.render.accel);
  if (!scene.film.aa.empty() && scene.film.aa != "auto") o.aa = parseAaMode(scene.film.aa);
  o.filter = parseFilterKind(scene.film.filter);
  o.aa_threshold = scene.film.aa_threshold;
  o.aa_max_level = scene.film.aa_max_level;
  o.first_hit = parseFirstHitMode(scene.render.first_hit);
  o.shadows = parseShadowMode(scene.render.shadows);
  if (!tryParseBoundsKind(scene.render.bounds, &o.bounds))
    throw std::invalid_argument("unknown bounds '" + scene.render.bounds + "' (expected " + kBoundsKindNames + ")");
  if (!tryParseInsideTest(scene.render.inside_test, &o.inside_test))
    throw std::invalid_argument("unknown inside test '" + scene.render.inside_test + "' (expected " +
                                kInsideTestNames + ")");
  return o;
}

SamplingOptions RenderOptions::sampling() const {
  SamplingOptions s;
  s.mode = aaMode();
  s.filter = filter;
  s.spp = spp;
  s.adaptive_threshold = aa_threshold;
  s.adaptive_max_level = aa_max_level;
  return s;
}

void validateCounts(long long width, long long height, long long spp, long long max_depth, long long aa_max_level) {
  auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
  if (width < 1 || width > 32768) fail("width must be in 1..32768, got " + std::to_string(width));
  if (height < 1 || height > 32768) fail("height must be in 1..32768, got " + std::to_string(height));
  if (width * height > (1ll << 28)) fail("width x height must be at most 2^28 pixels");
  if (spp < 1 || spp > 65536) fail("spp must be in 1..65536, got " + std::to_string(spp));
  if (max_depth < 0 || max_depth > 31) fail("max_depth must be in 0..31, got " + std::to_string(max_depth));
  if (aa_max_level < 0 || aa_max_level > kMaxAdaptiveLevel)
    fail("the adaptive maximum level must be in 0.." + std::to_string(kMaxAdaptiveLevel) + ", got " +
         std::to_string(aa_max_level));
}

void RenderOptions::validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
  validateCounts(width, height, spp, max_depth, aa_max_level);
  if (!(min_weight >= 0 && min_weight <= 1)) fail("min_weight must be in [0, 1], got " + std::to_string(min_weight));
  if (static_cast<int>(filter) < 0 || static_cast<int>(filter) > static_cast<int>(FilterKind::Mitchell))
    fail("unknown filter value " + std::to_string(static_cast<int>(filter)));
  // SamplingOptions checks its adaptive settings only for adaptive sampling;
  // a bad value is a mistake whatever the mode.
  if (!(aa_threshold >= 0) || !std::isfinite(aa_threshold))
    fail("the adaptive threshold must be a finite number >= 0, got " + std::to_string(aa_threshold));
  sampling().validate();
}

}  // namespace prism
