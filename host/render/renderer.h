// The wavefront Whitted renderer: sample positions → primary rays (or the
// first-hit Z-buffer) → extend → shade → occlude, wave after wave, with stable
// compaction of the ray queues in between and deterministic accumulation into a
// per-sample film, which the resolve kernel filters into pixels (kernels/*.cl,
// docs/architecture.md, docs/sampling.md).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "accel/accel_buffers.h"
#include "accel/accel_structure.h"
#include "device/context.h"
#include "device/kernel_profile.h"
#include "render/firsthit.h"
#include "render/gpu_scene.h"
#include "render/render_options.h"
#include "render/sampler.h"
#include "scene/scene.h"

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

// The per-sample film does not fit the device (the message says how much it needs
// and what would fit).
class FilmTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Fraction done in [0, 1]; returns false to cancel.
using ProgressFn = std::function<bool(double)>;

class Renderer {
 public:
  explicit Renderer(Context& context);
  ~Renderer();
  RenderResult render(const Scene& scene, const RenderOptions& options, const ProgressFn& progress = {});

  // Rays per wave slice: a fixed constant (not a device property), so chunking,
  // and with it the order of every floating-point sum, is the same on any device.
  static constexpr size_t kSliceRays = 1 << 16;
  // Shadow-feeler slots spawned, compacted and traced at once: the shaded points
  // of a slice go in runs of kShadowSlots / (feelers per point), so memory does
  // not grow with the number of light samples. A constant, like kSliceRays.
  static constexpr size_t kShadowSlots = 4 * kSliceRays;
  // Samples the first-hit pass rasterises at once (a whole number of slices),
  // and its device bytes per sample (sorted ray direction 16, depth + id 8,
  // positions 8 where the render has no frame-wide copy of them).
  static constexpr size_t kZBufferBatch = 64 * kSliceRays;
  static constexpr size_t kZBufferBytesPerSample = 32;

  // How many slices of adaptive sample positions the device film holds at once
  // (256 by default: 16M positions, 256 MiB); the colours go back to the host
  // after each batch. The image does not depend on it; tests set it low to
  // exercise batching on small images.
  void setFilmBatchSlices(size_t slices) { m_film_batch_slices = slices > 0 ? slices : 1; }
  size_t filmBatchSlices() const { return m_film_batch_slices; }

  // How the next renders build their acceleration structure (the defaults
  // unless set); the image does not depend on it.
  void setAccelBuildOptions(const AccelBuildOptions& options) { m_accel_build = options; }

 private:
  // The sampling modes whose positions come from kernels/supersample.cl, resolved
  // by kernels/resolve.cl.
  void renderSamples(const SamplingOptions& sampling, RenderResult& result, const ProgressFn& progress);
  // Adaptive sampling: adaptiveSample (render/sampler.h) driving traceFilmPositions.
  void renderAdaptive(const SamplingOptions& sampling, RenderResult& result, const ProgressFn& progress);
  // "Trace these film positions": the rgba radiance of a primary sample through
  // each (x, y) of `xy`, exactly as a render computes it, and the AOVs of
  // aov_pixel[k] (-1: none) from sample k. `done` (per chunk) drives progress.
  std::vector<float> traceFilmPositions(const std::vector<float>& xy, const std::vector<std::int32_t>& aov_pixel,
                                        const std::function<void(size_t done)>& done);
  // Primary samples [first_key, first_key + n), n <= kSliceRays, whose positions
  // and AOV pixels are in m_chunk_xy / m_chunk_aov: wave 0 from the Z-buffer or
  // traced rays, then every wave after it, their light added into m_film.
  void traceChunk(int first_key, size_t n);
  void traceLevel(int depth, size_t count);
  // One slice of m_work; `have_hits`: m_hits already holds its closest hits.
  void traceSlice(int depth, size_t count, bool have_hits = false);
  // Stable compaction of `in` (count slots, their tags in `tags`) into `out`;
  // returns the live count and adds the live rays of each kind to `kinds`.
  size_t compact(const Buffer& in, const Buffer& tags, size_t count, Buffer& out, std::array<std::uint64_t, 4>& kinds);
  // The first half of compact: adds the live rays of each kind (and the
  // point-light feelers shade traced) to `kinds`; returns the live count.
  size_t countRays(const Buffer& tags, size_t count, std::array<std::uint64_t, 4>& kinds);
  // The area lights' feelers of the slice's shaded points in m_surfaces: spawned in
  // runs, compacted, traced by occlude, their light added into m_film.
  void traceShadows(size_t surfaces);
  // Adds `count` contributions into m_film; with check_nan, the first that is
  // not finite is recorded with its ray (from `rays`) and hit (`hits`, or none).
  void accumulate(const Buffer& contributions, size_t count, const Buffer& rays, const Buffer* hits);
  // Throws FilmTooLarge unless `samples` per-sample film entries (and their
  // positions when `with_positions`) fit the device beside everything else.
  void checkFilmFits(std::uint64_t samples, bool with_positions) const;
  void zeroFill(Buffer& buffer, size_t bytes);

  Context& m_context;
  cl_kernel m_generate, m_extend, m_shade, m_spawn_shadows, m_occlude, m_count, m_scan, m_scatter, m_accumulate,
      m_supersample, m_resolve;
  std::unique_ptr<FirstHitPass> m_firsthit;

  // Per-render state.
  const GpuScene* m_scene = nullptr;
  const RenderOptions* m_options = nullptr;
  RenderStats* m_stats = nullptr;
  bool m_zbuffer = false;  // wave 0 from the first-hit pass
  bool m_distributed_camera = false;  // a lens or a shutter interval: generate samples them
  int m_spp = 1;           // samples per pixel of the per-pixel modes (1 otherwise)
  int m_strata = 1;        // samples that share strata in the sampler (0: independent, aa random)
  long long m_group_base = 0;  // adaptive: the batch's first position, so strata groups stay distinct
  bool m_point_lights = false;  // shade traces feelers, which the last depth still counts
  int m_shadow_slots = 0;  // spawned feelers per shaded point: the area lights' samples summed
  size_t m_film_batch_slices = 256;
  AccelBuildOptions m_accel_build;
  GeometryBuffers m_geometry;
  AccelBuffers m_accel;
  // render/light_buffer.h (a word or four each without it)
  Buffer m_light_buffer_cells, m_light_buffer_ids, m_light_buffer_windows;
  int m_light_buffer_resolution = 1;
  Buffer m_texels;  // image textures (GpuScene::texels)
  Buffer m_camera, m_materials, m_lights, m_aov_depth, m_aov_normal, m_aov_primid, m_aov_albedo;
  Buffer m_film;       // rgba per primary sample, indexed by the sample's key
  Buffer m_sample_xy;  // film positions of all samples (for resolve)
  Buffer m_zbuffer_xy;  // adaptive sampling: the positions of the Z-buffer's batch
  size_t m_zbuffer_first = 0;  // the chunk's first sample within the Z-buffer's batch
  Buffer m_chunk_xy, m_chunk_aov, m_tile, m_pixels;
  int m_chunk_first = 0;  // the key of m_chunk_xy's first position
  Buffer m_first_bad;     // accumulate's lowest queue index of a non-finite contribution
  std::vector<Buffer> m_levels;  // queue of each depth >= 1, up to 2 * kSliceRays rays
  // m_child_tags, m_shadow_tags: the slot tags of m_children and m_shadows
  // (kernels/shared/ray_gpu.h).
  Buffer m_work, m_hits, m_emit, m_children, m_child_tags, m_surfaces, m_shadows, m_shadow_tags, m_shadow_queue,
      m_shadow_light, m_counts, m_offsets, m_totals;
};

}  // namespace prism
