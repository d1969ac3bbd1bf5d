// Settings of one render: the scene file's film/render blocks, overridden by the
// caller (CLI flags or the C API).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "accel/accel_structure.h"
#include "render/sampler.h"
#include "scene/primitives/bounds_kind.h"
#include "scene/primitives/inside_test.h"
#include "scene/render_modes.h"
#include "scene/scene.h"

namespace prism {

// FirstHitMode (scene/render_modes.h): the first-hit (Z-buffer) pass
// (render/firsthit.h), traced rays (extend), or the Z-buffer whenever the camera
// allows it (a pinhole: no depth of field, no motion blur) and zbufferPays.
// An unknown name throws std::invalid_argument listing them.
FirstHitMode parseFirstHitMode(const std::string& name);

// ShadowMode (scene/render_modes.h): the acceleration structure, the light
// buffer (render/light_buffer.h), or whichever the renderer's cost model
// expects to be faster (auto). An unknown name throws std::invalid_argument
// listing them.
ShadowMode parseShadowMode(const std::string& name);

struct RenderOptions {
  int width = 640;
  int height = 480;
  int spp = 1;
  int max_depth = 5;
  double min_weight = 0.01;
  std::uint64_t seed = 0;
  AccelKind accel = AccelKind::Auto;  // spatial index for extend / occlude (and shade's feelers)
  // Anti-aliasing (docs/sampling.md). No mode: none at spp 1, jitter above.
  std::optional<AaMode> aa;
  FilterKind filter = FilterKind::Box;  // quincunx always resolves with its tent, adaptive by area
  double aa_threshold = 0.1;            // adaptive: corner contrast that splits a square
  int aa_max_level = 2;                 // adaptive: most splits of a pixel's side
  FirstHitMode first_hit = FirstHitMode::Auto;
  InsideTest inside_test = InsideTest::Crossing;  // for polygons that name none
  ShadowMode shadows = ShadowMode::Auto;          // point lights' feelers
  BoundsKind bounds = BoundsKind::Aabb;           // the BVH children's bounds
  // Time every kernel launch on the device (RenderStats::kernels); each launch
  // then keeps an event until the render ends.
  bool profile = false;
  // Watch every contribution to the film for NaN and infinity, and report the
  // first with its ray (RenderStats::nan). Costs a read-back per launch.
  bool check_nan = false;

  static RenderOptions fromScene(const Scene& scene);
  // The anti-aliasing mode in effect: `aa`, or by default none at one sample per
  // pixel and jitter above.
  AaMode aaMode() const { return aa ? *aa : (spp > 1 ? AaMode::Jitter : AaMode::None); }
  SamplingOptions sampling() const;
  // Throws std::invalid_argument naming the field when a value is out of range
  // or the sampling settings do not fit together (SamplingOptions::validate).
  void validate() const;
};

// The ranges of RenderOptions' counts (width, height, spp, max_depth,
// aa_max_level), checked on values as wide as their source holds them (the C
// API's are uint32, wider than int), so that a refusal shows the number given.
// RenderOptions::validate checks its own through it.
void validateCounts(long long width, long long height, long long spp, long long max_depth, long long aa_max_level);

}  // namespace prism
