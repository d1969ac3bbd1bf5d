// What a render reports besides its images: ray counts, the choices it made
// (structure, first-hit pass, shadows), time spent where, and with check_nan the
// first non-finite contribution (render/renderer.h fills it; render/device_tracer.h
// counts into it).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "accel/accel_structure.h"
#include "device/kernel_profile.h"
#include "render/render_options.h"
#include "render/work_dealer.h"
#include "scene/sampling_options.h"

namespace prism {

// With RenderOptions::check_nan: the first contribution to the film that was not
// finite (NaN or infinite), in render order (chunk by chunk of the sample
// sequence, and in a chunk depth by depth, lowest sample first), with the ray
// that brought it.
struct NanFinding {
  std::uint64_t sample = 0;     // the film key: the primary sample's index in the image
  float film_x = 0, film_y = 0; // its film position (pixel floor(x), floor(y))
  int ray_kind = 0;             // RAY_KIND_*
  int depth = 0;
  std::array<float, 3> origin{}, direction{};
  int prim = -1;                // what the ray hit (-1: nothing, or a shadow ray)
  float t = 0;
  std::array<float, 4> value{}; // the contribution: rgb and coverage
};

struct RenderStats {
  double seconds = 0;
  double kernel_build_seconds = 0;
  std::array<std::uint64_t, 4> rays_by_kind{};  // indexed by RAY_KIND_*; primary = primary samples
  std::array<std::uint64_t, 32> rays_per_depth{};
  int waves = 0;
  AccelKind accel = AccelKind::Bvh;  // the structure used (never Auto: what it chose); accelName() names it
  AccelStats accel_stats;            // its build (host) statistics
  AaMode aa = AaMode::None;          // the anti-aliasing mode used (the default resolved)
  FilterKind filter = FilterKind::Box;  // the filter applied (tent for quincunx; unused by adaptive)
  FirstHitMode first_hit = FirstHitMode::Trace;  // how wave 0 found its hits: ZBuffer or Trace
  ShadowMode shadows = ShadowMode::Accel;  // how point lights' feelers were traced (never Auto)
  double light_buffer_candidates = 0;  // with the light buffer: the mean length of a cell's list
  double rays_per_pixel = 0;         // primary samples / pixels
  int film_batches = 0;              // adaptive: trips of sample colours from the device film to the host
  // Set-up before the first sample: flattening the scene, building the structure,
  // building (or loading) kernels, uploads. The rest of `seconds` is tracing.
  double setup_seconds = 0;
  // Of the tracing time: kernels waiting between submission and start on their
  // first launch, which is where a driver compiles them for it (PoCL specialises
  // each for the work-group size): start-up cost, not tracing.
  double first_launch_seconds = 0;
  std::vector<KernelTime> kernels;   // with RenderOptions::profile: device time per kernel, longest first
  std::optional<NanFinding> nan;     // with RenderOptions::check_nan, where one was found
  std::vector<DeviceShare> devices;  // each device's part of the frame, in the order they were given
  std::vector<std::string> warnings; // a device that failed mid-frame, and the like

  std::uint64_t totalRays() const { return rays_by_kind[0] + rays_by_kind[1] + rays_by_kind[2] + rays_by_kind[3]; }
};

}  // namespace prism
