// The command line of `prism render`, checked before any work starts: a wrong flag,
// number or output format fails in milliseconds, not after a long render.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "prism.h"

namespace prism_cli {

struct RenderRequest {
  bool help = false;  // --help: nothing else is checked
  std::string scene_path;
  std::string output_path;
  // Unset fields keep the scene's own value.
  std::optional<uint32_t> width, height, spp, max_depth;
  std::optional<float> min_weight;
  std::optional<uint64_t> seed;
  std::string device;  // "" for the library's default
  std::optional<PrismAov> aov;
  std::optional<PrismAccel> accel;
  std::optional<PrismAa> aa;
  std::optional<PrismFilter> filter;
  std::optional<float> aa_threshold;
  std::optional<uint32_t> aa_max_level;
  std::optional<PrismFirstHit> first_hit;
  std::optional<PrismInsideTest> inside_test;
  std::optional<PrismShadows> shadows;
  std::optional<PrismBounds> bounds;
  std::optional<std::array<float, 3>> camera_pos, camera_look, camera_up;
  std::optional<float> fov;
  std::optional<float> aperture, focus_distance;  // depth of field: lens radius, plane in focus
  bool use_kernel_cache = true;
  bool quiet = false;
  bool stats = false;  // --stats: where the render's time went
  bool check_nan = false;  // --check-nan: name the first non-finite value and its ray
  // --frames K or A-B (inclusive): the frames of an animation to render; unset: all.
  std::optional<std::pair<uint32_t, uint32_t>> frames;
};

// Throws UsageError naming the option at fault.
RenderRequest parseRenderArgs(const std::vector<std::string>& args);

// The output's extension in lower case, with its dot (".png").
std::string lowerExtension(const std::string& path);

// Where frame `frame` of an animation of `frames` frames goes: the last run of
// '#' in the file name replaced by the frame number padded to its length, else
// "_NNNN" (at least 4 digits, as many as the last frame needs) put before the
// extension. A still (frames == 1) keeps `path` as it is.
std::string frameOutputPath(const std::string& path, uint32_t frame, uint32_t frames);

}  // namespace prism_cli
