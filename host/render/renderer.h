// The wavefront Whitted renderer: generate → extend → shade → occlude, wave
// after wave, with stable compaction of the ray queues in between and
// deterministic accumulation into the film (see kernels/*.cl).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <vector>

#include "accel/accel_buffers.h"
#include "accel/accel_structure.h"
#include "device/context.h"
#include "render/gpu_scene.h"
#include "render/render_options.h"
#include "scene/scene.h"

namespace prism {

struct RenderStats {
  double seconds = 0;
  double kernel_build_seconds = 0;
  std::array<std::uint64_t, 4> rays_by_kind{};  // indexed by RAY_KIND_*
  std::array<std::uint64_t, 32> rays_per_depth{};
  int waves = 0;
  AccelKind accel = AccelKind::Bvh;  // the structure used; accelName() names it
  AccelStats accel_stats;            // its build (host) statistics

  std::uint64_t totalRays() const { return rays_by_kind[0] + rays_by_kind[1] + rays_by_kind[2] + rays_by_kind[3]; }
};

struct RenderResult {
  int width = 0, height = 0;
  std::vector<float> rgba;          // width*height*4, linear, rows top to bottom
  std::vector<float> depth;         // width*height
  std::vector<float> normal;        // width*height*3
  std::vector<std::int32_t> primid; // width*height
  std::vector<float> albedo;        // width*height*3
  RenderStats stats;
};

class RenderCancelled : public std::runtime_error {
 public:
  RenderCancelled() : std::runtime_error("render cancelled by the progress callback") {}
};

// Fraction done in [0, 1]; returns false to cancel.
using ProgressFn = std::function<bool(double)>;

class Renderer {
 public:
  explicit Renderer(Context& context);
  RenderResult render(const Scene& scene, const RenderOptions& options, const ProgressFn& progress = {});

  // Rays per wave slice: a fixed constant (not a device property), so chunking,
  // and with it the order of every floating-point sum, is the same on any device.
  static constexpr size_t kSliceRays = 1 << 16;

 private:
  void traceLevel(int depth, size_t count);
  void traceSlice(int depth, size_t count);
  // Stable compaction of `in` (count slots) into `out`; returns the live count
  // and adds the live rays of each kind to `kinds`.
  size_t compact(const Buffer& in, size_t count, Buffer& out, std::array<std::uint64_t, 4>& kinds);
  void accumulate(const Buffer& contributions, size_t count);

  Context& m_context;
  cl_kernel m_generate, m_extend, m_shade, m_occlude, m_count, m_scatter, m_accumulate;

  // Per-render state.
  const GpuScene* m_scene = nullptr;
  const RenderOptions* m_options = nullptr;
  RenderStats* m_stats = nullptr;
  AccelBuffers m_accel;
  Buffer m_camera, m_objects, m_materials, m_lights, m_film, m_aov_depth, m_aov_normal, m_aov_primid, m_aov_albedo;
  std::vector<Buffer> m_levels;  // queue of each depth, up to 2 * kSliceRays rays
  Buffer m_work, m_hits, m_emit, m_children, m_shadows, m_shadow_queue, m_shadow_light, m_counts, m_offsets;
};

}  // namespace prism
