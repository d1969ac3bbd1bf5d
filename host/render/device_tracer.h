// One device's part of a frame: the scene's buffers and kernels on that device,
// the wave queues, a per-sample film and the AOVs. It traces ranges of the
// frame's sample sequence, each independent of the others by film key (a
// sample's light depends on its key alone, never on who traced the keys before
// it), which is what lets a frame be dealt out over several devices. The frame
// itself (which structure, which first-hit pass, which ranges, the resolve into
// pixels) is the Renderer's (render/renderer.h); every OpenCL call goes through
// device/context.h.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "accel/accel_buffers.h"
#include "accel/accel_structure.h"
#include "device/context.h"
#include "render/ray_kernel.h"
#include "render/firsthit.h"
#include "render/gpu_scene.h"
#include "render/light_buffer.h"
#include "render/render_options.h"
#include "render/render_stats.h"
#include "render/sampler.h"

namespace prism {

// The per-sample film does not fit the device (the message says how much it needs
// and what would fit).
class FilmTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a frame asks of every device that traces part of it: the scene as
// flattened for the kernels, and what the Renderer decided about it on the host.
struct FrameSetup {
  const GpuScene* scene = nullptr;
  const DeviceAccel* accel = nullptr;       // built once on the host
  const LightBuffer* light_buffer = nullptr;
  bool use_light_buffer = false;            // point lights' feelers through it
  const RenderOptions* options = nullptr;
  SamplingOptions sampling;
  bool zbuffer = false;                     // wave 0 from the first-hit pass
  bool distributed_camera = false;          // a lens or a shutter interval: generate samples them
};

class DeviceTracer {
 public:
  // Rays per wave slice: a fixed constant (not a device property), so chunking,
  // and with it the order of every floating-point sum, is the same on any device.
  static constexpr size_t kSliceRays = 1 << 16;
  // Shadow-feeler slots spawned, compacted and traced at once: the shaded points
  // of a slice go in runs of kShadowSlots / (feelers per point), so memory does
  // not grow with the number of light samples. A constant, like kSliceRays.
  static constexpr size_t kShadowSlots = 4 * kSliceRays;
  // Samples the first-hit pass rasterises at once (a whole number of slices),
  // and its device bytes per sample (ray direction 12, depth + id 8, a sorted
  // batch's slots 4, positions 8 where the render has no frame-wide copy of them).
  static constexpr size_t kZBufferBatch = 64 * kSliceRays;
  static constexpr size_t kZBufferBytesPerSample = 32;

  explicit DeviceTracer(Context& context);
  ~DeviceTracer();

  Context& context() { return m_context; }

  // Uploads the scene, builds (or finds) the kernels it needs and sizes the
  // queues; counts go into `stats` until the next load. mark_aovs: the AOV
  // pixels no sample of this device writes read primid kAovUnwritten (a frame
  // dealt over several devices takes each pixel from the one that wrote it).
  void load(const FrameSetup& frame, RenderStats& stats, bool mark_aovs = false);
  static constexpr std::int32_t kAovUnwritten = -2147483647 - 1;
  // Lets go of the per-sample film and the scene's reference (keeps the kernels).
  void unload();

  // The kernel-generated sampling modes (not adaptive): a film for the frame's
  // `total` samples with their positions (not zeroed: see traceSamples). It
  // holds all of them (window 0: the device that resolves the frame), or a
  // window of `window` samples that traceSamples moves to each unit it traces:
  // a device whose units leave it as they end holds one unit, not the frame.
  void beginSampleFilm(std::uint64_t total, std::uint64_t window = 0);
  // Whether the film holds a window of the frame's samples, not all of them.
  bool filmWindowed() const { return m_film_size < m_film_total; }
  // Device bytes the film takes now (entries and positions), and the most it
  // took since the last unload.
  std::uint64_t filmBytes() const { return m_film.bytes() + m_sample_xy.bytes(); }
  std::uint64_t filmPeakBytes() const { return m_film_peak_bytes; }
  // Moves the film's window over samples [first, first + n), made larger first
  // if it must be (what it held is then lost): where a run of samples is
  // written in to be resolved. [0, total) makes it hold the whole frame.
  void holdSamples(std::uint64_t first, std::uint64_t n);
  // Traces samples [first, end) of the sequence (with the Z-buffer, at most one
  // of its batches; at most the window's size): their film entries zeroed, then
  // their light added in; done(key) after each chunk, with the key that chunk ends at.
  void traceSamples(std::uint64_t first, std::uint64_t end, const std::function<void(std::uint64_t)>& done);
  // The film filtered into pixels (rgba): all of them, or pixels
  // [first_pixel, first_pixel + count) in row-major order (the film must hold
  // every sample they reach).
  std::vector<float> resolvePixels();
  std::vector<float> resolvePixels(size_t first_pixel, size_t count);
  // The film entries (rgba) and positions (x, y) of samples [first, first + n),
  // which the film must hold, read from this device or written into its film
  // (to gather a frame that several devices traced on the one that resolves it).
  void readSamples(std::uint64_t first, size_t n, float* rgba, float* xy) const;
  void writeSamples(std::uint64_t first, size_t n, const float* rgba, const float* xy);

  // Adaptive sampling: the rgba radiance of a primary sample through each
  // (x, y) of `xy`, exactly as a render computes it, and the AOVs of
  // aov_pixel[k] (-1: none) from sample k. position_base: positions traced
  // before these in the frame (their strata groups follow on). `done` (per
  // chunk) drives progress.
  std::vector<float> traceFilmPositions(const std::vector<float>& xy, const std::vector<std::int32_t>& aov_pixel,
                                        std::uint64_t position_base, const std::function<void(size_t done)>& done);

  // The AOV images every sample that owns a pixel wrote.
  void readAovs(std::vector<float>& depth, std::vector<float>& normal, std::vector<std::int32_t>& primid,
                std::vector<float>& albedo) const;

  // How many slices of adaptive sample positions the device film holds at once
  // (Renderer::setFilmBatchSlices).
  void setFilmBatchSlices(size_t slices) { m_film_batch_slices = slices > 0 ? slices : 1; }
  size_t filmBatchSlices() const { return m_film_batch_slices; }

 private:
  // Primary samples [first_key, first_key + n), n <= kSliceRays, whose positions
  // and AOV pixels are in m_chunk_xy / m_chunk_aov: wave 0 from the Z-buffer or
  // traced rays, then every wave after it, their light added into m_film.
  void traceChunk(int first_key, size_t n);
  // Sample positions [first, first + n) into m_chunk_xy, m_chunk_aov and m_sample_xy.
  void samplePositions(std::uint64_t first, size_t n);
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
  // positions when `with_positions`) fit the device beside everything else,
  // and keys up to `keys` fit the kernels' int.
  void checkFilmFits(std::uint64_t samples, bool with_positions, std::uint64_t keys) const;
  // Throws std::logic_error unless the film holds samples [first, first + n).
  void requireHeld(std::uint64_t first, std::uint64_t n, const char* what) const;
  void zeroFill(Buffer& buffer, size_t bytes, size_t offset = 0);

  Context& m_context;
  RayKernel m_extend, m_occlude;
  bool m_camera_packets = false, m_feeler_packets = false;  // this frame's (RayKernel::packets)
  cl_kernel m_generate = nullptr, m_shade = nullptr, m_spawn_shadows = nullptr, m_count = nullptr, m_scan = nullptr,
            m_scatter = nullptr, m_accumulate = nullptr, m_supersample = nullptr, m_resolve = nullptr;
  std::unique_ptr<FirstHitPass> m_firsthit;

  // Per-frame state.
  const GpuScene* m_scene = nullptr;
  const RenderOptions* m_options = nullptr;
  SamplingOptions m_sampling;
  RenderStats* m_stats = nullptr;
  bool m_zbuffer = false;  // wave 0 from the first-hit pass
  bool m_distributed_camera = false;  // a lens or a shutter interval: generate samples them
  int m_spp = 1;           // samples per pixel of the per-pixel modes (1 otherwise)
  int m_strata = 1;        // samples that share strata in the sampler (0: independent, aa random)
  long long m_group_base = 0;  // adaptive: the batch's first position, so strata groups stay distinct
  bool m_point_lights = false;  // shade traces feelers, which the last depth still counts
  int m_shadow_slots = 0;  // spawned feelers per shaded point: the area lights' samples summed
  size_t m_film_batch_slices = 256;
  GeometryBuffers m_geometry;
  AccelBuffers m_accel;
  std::uint64_t m_accel_bytes = 0;
  // render/light_buffer.h (a word or four each without it)
  Buffer m_light_buffer_cells, m_light_buffer_ids, m_light_buffer_windows;
  int m_light_buffer_resolution = 1;
  Buffer m_texels;  // image textures (GpuScene::texels)
  Buffer m_camera, m_materials, m_lights, m_aov_depth, m_aov_normal, m_aov_primid, m_aov_albedo;
  Buffer m_film;       // rgba per primary sample, indexed by the sample's key less m_film_first
  Buffer m_sample_xy;  // film positions of the same samples (for resolve)
  std::uint64_t m_film_first = 0;  // the key of the film's first entry
  std::uint64_t m_film_size = 0;   // the entries it holds (its window's size)
  std::uint64_t m_film_total = 0;  // the frame's samples (0: adaptive batches, keys from 0)
  std::uint64_t m_film_peak_bytes = 0;
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
