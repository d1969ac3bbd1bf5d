#include "render/device_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "kernels/shared/contribution_gpu.h"
#include "kernels/shared/hit_gpu.h"
#include "kernels/shared/ray_gpu.h"
#include "kernels/shared/surface_gpu.h"

namespace prism {
namespace {

constexpr int kCompactBlock = 256;  // slots counted by one work-item of count_rays
constexpr size_t kSpawnLanes = 8;     // slots a work-item of spawn_shadows takes (SPAWN_LANES)

int compactBlocks(size_t slots) { return static_cast<int>((slots + kCompactBlock - 1) / kCompactBlock); }

// Device bytes a sample takes: its rgba film entry and its (x, y) position.
constexpr std::uint64_t kFilmBytesPerSample = 4 * sizeof(float);
constexpr std::uint64_t kPositionBytesPerSample = 2 * sizeof(float);
// Per pixel: resolved rgba, depth, normal, primid, albedo.
constexpr std::uint64_t kBytesPerPixel = (4 + 1 + 3 + 1 + 3) * 4;

std::string gib(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return text;
}

// Build options naming the distributed features a scene uses (kernels/*.cl test
// them with #ifdef).
// (shade also takes the acceleration structure's options, which name moving
// objects when there are some: it traces the point lights' feelers.)
struct KernelFeatures {
  std::string shading;  // shade: area lights, lobes
  std::string shadows;  // spawn_shadows: area lights
};

KernelFeatures kernelFeatures(const GpuScene& gpu) {
  KernelFeatures f;
  bool area = false, lobes = false;
  for (const LightGpu& l : gpu.lights) area = area || l.type != LIGHT_POINT;
  for (const MaterialGpu& m : gpu.materials) lobes = lobes || m.gloss > 0 || m.translucency > 0;
  if (area) f.shading += " -DPRISM_AREA_LIGHTS";
  if (lobes) f.shading += " -DPRISM_LOBES";
  if (area) f.shadows = "-DPRISM_AREA_LIGHTS";
  return f;
}

}  // namespace

DeviceTracer::DeviceTracer(Context& context) : m_context(context) {
  m_count = context.kernel(kRenderLoopProgram, "count_rays");
  m_scan = context.kernel(kRenderLoopProgram, "scan_blocks");
  m_scatter = context.kernel(kRenderLoopProgram, "scatter_rays");
  m_accumulate = context.kernel(kRenderLoopProgram, "accumulate");
  m_supersample = context.kernel(kRenderLoopProgram, "supersample");
  m_resolve = context.kernel(kRenderLoopProgram, "resolve");
  m_generate = context.kernel(kRenderLoopProgram, "generate");
}

DeviceTracer::~DeviceTracer() = default;

void DeviceTracer::load(const FrameSetup& frame, RenderStats& stats, bool mark_aovs) {
  const GpuScene& gpu = *frame.scene;
  const RenderOptions& options = *frame.options;
  const DeviceAccel& accel = *frame.accel;
  m_scene = &gpu;
  m_options = &options;
  m_sampling = frame.sampling;
  m_film_peak_bytes = 0;  // this frame's
  m_stats = &stats;
  m_zbuffer = frame.zbuffer;
  m_distributed_camera = frame.distributed_camera;
  m_spp = frame.sampling.spp;
  m_strata = frame.sampling.mode == AaMode::Random ? 0 : frame.sampling.spp;
  m_group_base = 0;
  m_shadow_slots = 0;
  m_point_lights = false;
  for (const LightGpu& l : gpu.lights) {
    m_shadow_slots += l.samples;  // 0 for point lights
    m_point_lights = m_point_lights || l.type == LIGHT_POINT;
  }
  // Each distributed effect's code is compiled only into the programs of scenes
  // that use it, so a Whitted scene builds what it did before (PoCL compiles slowly).
  const KernelFeatures features = kernelFeatures(gpu);

  const size_t pixels = static_cast<size_t>(options.width) * options.height;
  m_camera = Buffer(m_context, sizeof(CameraGpu));
  m_camera.write(&gpu.camera, sizeof(CameraGpu));
  const std::int32_t none_bad = std::numeric_limits<std::int32_t>::max();
  m_first_bad = Buffer(m_context, sizeof none_bad);
  m_first_bad.write(&none_bad, sizeof none_bad);
  m_geometry.upload(m_context, gpu);
  m_accel.upload(m_context, accel);
  m_accel_bytes = accel.stats.bytes;
  m_extend = RayKernel(m_context, accel, RayQuery::ClosestHits);
  // The frame's samples share the view: they say how dense the geometry is
  // beside the camera rays and a point's feelers (render/ray_kernel.h).
  const std::uint64_t view_rays = static_cast<std::uint64_t>(pixels) * std::max(1, frame.sampling.spp);
  m_camera_packets = m_extend.packets(RayCoherence::Coherent, view_rays);
  const LightBuffer& light_buffer = *frame.light_buffer;
  // (bound, never read, without a light buffer: a buffer may not be empty)
  const std::vector<std::int32_t> cells = light_buffer.cells.empty() ? std::vector<std::int32_t>(2, 0) : light_buffer.cells;
  const std::vector<std::int32_t> ids = light_buffer.ids.empty() ? std::vector<std::int32_t>(1, 0) : light_buffer.ids;
  const std::vector<float> windows = light_buffer.windows.empty() ? std::vector<float>(4, 0.0f) : light_buffer.windows;
  m_light_buffer_cells = Buffer(m_context, cells.size() * sizeof(std::int32_t));
  m_light_buffer_cells.writeVector(cells);
  m_light_buffer_ids = Buffer(m_context, ids.size() * sizeof(std::int32_t));
  m_light_buffer_ids.writeVector(ids);
  m_light_buffer_windows = Buffer(m_context, windows.size() * sizeof(float));
  m_light_buffer_windows.writeVector(windows);
  m_light_buffer_resolution = light_buffer.resolution;
  m_shade = m_context.kernel("shade.cl", "shade",
                             accel.kernel_options + features.shading +
                                 (frame.use_light_buffer ? " -DPRISM_LIGHT_BUFFER" : ""));
  m_feeler_packets = false;
  if (m_shadow_slots > 0) {
    m_spawn_shadows = m_context.kernel("spawn_shadows.cl", "spawn_shadows", features.shadows);
    m_occlude = RayKernel(m_context, accel, RayQuery::Transmittance);
    m_feeler_packets = m_occlude.packets(RayCoherence::Coherent, view_rays);
  }
  if (m_zbuffer) {
    if (!m_firsthit) m_firsthit = std::make_unique<FirstHitPass>(m_context);
    m_firsthit->prepare(gpu, accel.primitive_options);
  }
  m_materials = Buffer(m_context, gpu.materials.size() * sizeof(MaterialGpu));
  m_materials.writeVector(gpu.materials);
  m_texels = Buffer(m_context, gpu.texels.size() * sizeof(float));
  m_texels.writeVector(gpu.texels);
  m_lights = Buffer(m_context, gpu.lights.size() * sizeof(LightGpu));
  m_lights.writeVector(gpu.lights);
  m_aov_depth = Buffer(m_context, pixels * sizeof(float));
  m_aov_normal = Buffer(m_context, pixels * 3 * sizeof(float));
  m_aov_primid = Buffer(m_context, pixels * sizeof(std::int32_t));
  m_aov_albedo = Buffer(m_context, pixels * 3 * sizeof(float));
  if (mark_aovs) {
    const std::int32_t unwritten = kAovUnwritten;
    m_aov_primid.fill(&unwritten, sizeof unwritten, pixels * sizeof unwritten);
  }

  m_levels.clear();
  m_levels.emplace_back();  // depth 0 is generated chunk by chunk straight into m_work
  for (int d = 1; d <= options.max_depth; ++d) m_levels.emplace_back(m_context, 2 * kSliceRays * sizeof(RayGpu));
  m_work.reserve(m_context, kSliceRays * sizeof(RayGpu));
  m_hits.reserve(m_context, kSliceRays * sizeof(HitGpu));
  m_emit.reserve(m_context, kSliceRays * sizeof(ContributionGpu));
  m_children.reserve(m_context, 2 * kSliceRays * sizeof(RayGpu));
  m_child_tags.reserve(m_context, 2 * kSliceRays * sizeof(std::int32_t));
  // Shaded points are kept only for area lights' feelers (a buffer cannot be empty).
  m_surfaces.reserve(m_context, (m_shadow_slots > 0 ? kSliceRays : 1) * sizeof(SurfaceGpu));
  if (m_shadow_slots > 0) {
    const size_t slots = std::min(kShadowSlots, kSliceRays * m_shadow_slots);
    m_shadows.reserve(m_context, slots * sizeof(RayGpu));
    m_shadow_tags.reserve(m_context, slots * sizeof(std::int32_t));
    m_shadow_queue.reserve(m_context, slots * sizeof(RayGpu));
    m_shadow_light.reserve(m_context, slots * sizeof(ContributionGpu));
  }
  const size_t max_blocks = (std::max(2 * kSliceRays, kShadowSlots) + kCompactBlock - 1) / kCompactBlock;
  m_counts.reserve(m_context, max_blocks * RAY_COUNT_COLUMNS * sizeof(std::int32_t));
  m_offsets.reserve(m_context, max_blocks * sizeof(std::int32_t));
  m_totals.reserve(m_context, RAY_TOTALS * sizeof(std::int32_t));
  m_chunk_xy.reserve(m_context, kSliceRays * 2 * sizeof(float));
  m_chunk_aov.reserve(m_context, kSliceRays * sizeof(std::int32_t));
}

void DeviceTracer::unload() {
  // The per-sample film can be large: give it back now rather than at the next render.
  m_film = Buffer();
  m_sample_xy = Buffer();
  m_film_first = m_film_size = m_film_total = 0;
  m_film_peak_bytes = 0;
  m_zbuffer_xy = Buffer();
  m_scene = nullptr;
  m_options = nullptr;
  m_stats = nullptr;
}

void DeviceTracer::beginSampleFilm(std::uint64_t total, std::uint64_t window) {
  const RenderOptions& opt = *m_options;
  const std::uint64_t size = window > 0 ? std::min(window, total) : total;
  checkFilmFits(size, true, total);
  std::vector<float> tile_xy(2, 0.0f);  // a buffer may not be empty
  if (m_sampling.mode == AaMode::Poisson) tile_xy = poissonTile(m_sampling.spp, opt.seed).xy;
  m_tile = Buffer(m_context, tile_xy.size() * sizeof(float));
  m_tile.writeVector(tile_xy);
  m_film = Buffer();  // free the last render's film before asking for this one
  m_sample_xy = Buffer();
  // Not zeroed here: each unit zeroes its own samples (traceSamples), so a device
  // sharing the frame touches only the part it traces. Zeroing a whole 16 spp
  // frame's film cost a PoCL CPU beside a GPU 30 ms in its first unit.
  m_film = Buffer(m_context, size * kFilmBytesPerSample);
  m_sample_xy = Buffer(m_context, size * kPositionBytesPerSample);
  m_film_first = 0;
  m_film_size = size;
  m_film_total = total;
  m_film_peak_bytes = std::max(m_film_peak_bytes, filmBytes());
}

void DeviceTracer::holdSamples(std::uint64_t first, std::uint64_t n) {
  if (first > m_film_total || n > m_film_total - first) throw std::logic_error("holdSamples: past the frame's samples");
  if (n > m_film_size) {
    checkFilmFits(n, true, m_film_total);
    m_film = Buffer();
    m_sample_xy = Buffer();
    m_film_size = 0;  // until both are made
    m_film = Buffer(m_context, n * kFilmBytesPerSample);
    m_sample_xy = Buffer(m_context, n * kPositionBytesPerSample);
    m_film_size = n;
    m_film_peak_bytes = std::max(m_film_peak_bytes, filmBytes());
  }
  m_film_first = first;
}

void DeviceTracer::requireHeld(std::uint64_t first, std::uint64_t n, const char* what) const {
  if (first < m_film_first || n > m_film_size || first - m_film_first > m_film_size - n)
    throw std::logic_error(std::string(what) + ": samples the film does not hold");
}

void DeviceTracer::samplePositions(std::uint64_t first, size_t n) {
  const RenderOptions& opt = *m_options;
  m_context.launch(m_supersample)
      .arg(static_cast<cl_int>(m_sampling.mode))
      .arg(static_cast<cl_int>(opt.width))
      .arg(static_cast<cl_int>(opt.height))
      .arg(static_cast<cl_int>(m_sampling.spp))
      .arg(static_cast<cl_uint>(kernelSeed(opt.seed)))
      .arg(m_tile)
      .arg(static_cast<cl_long>(first))
      .arg(static_cast<cl_int>(n))
      .arg(m_chunk_xy)
      .arg(m_chunk_aov)
      .run(n);
  m_chunk_xy.copyTo(m_sample_xy, n * kPositionBytesPerSample, 0, (first - m_film_first) * kPositionBytesPerSample);
}

void DeviceTracer::traceSamples(std::uint64_t first_sample, std::uint64_t end,
                                const std::function<void(std::uint64_t)>& done) {
  if (end < first_sample || end - first_sample > m_film_size)
    throw std::logic_error("traceSamples: more samples than the film's window holds");
  // A window moves to the unit; a film of the whole frame holds it already.
  if (first_sample < m_film_first || end - m_film_first > m_film_size) holdSamples(first_sample, end - first_sample);
  zeroFill(m_film, static_cast<size_t>(end - first_sample) * kFilmBytesPerSample,
           static_cast<size_t>(first_sample - m_film_first) * kFilmBytesPerSample);
  // The Z-buffer takes its batch of samples at once: their positions first,
  // rasterised together, then resolved chunk by chunk.
  if (m_zbuffer) {
    for (std::uint64_t first = first_sample; first < end; first += kSliceRays)
      samplePositions(first, static_cast<size_t>(std::min<std::uint64_t>(kSliceRays, end - first)));
    // Per-pixel modes number their samples pixel by pixel: no sort needed.
    m_firsthit->rasterize(m_geometry, m_sample_xy, static_cast<size_t>(m_film_first), static_cast<size_t>(first_sample),
                          static_cast<size_t>(end - first_sample),
                          m_sampling.mode == AaMode::Quincunx ? 0 : m_sampling.spp);
  }
  // Chunks of kSliceRays samples in sequence order: keys ascend within each.
  for (std::uint64_t first = first_sample; first < end; first += kSliceRays) {
    const size_t n = static_cast<size_t>(std::min<std::uint64_t>(kSliceRays, end - first));
    samplePositions(first, n);
    m_zbuffer_first = static_cast<size_t>(first - first_sample);
    traceChunk(static_cast<int>(first), n);
    if (done) done(first + n);
  }
}

std::vector<float> DeviceTracer::resolvePixels() {
  const RenderOptions& opt = *m_options;
  return resolvePixels(0, static_cast<size_t>(opt.width) * opt.height);
}

std::vector<float> DeviceTracer::resolvePixels(size_t first_pixel, size_t count) {
  const RenderOptions& opt = *m_options;
  const size_t pixels = static_cast<size_t>(opt.width) * opt.height;
  if (first_pixel > pixels || count > pixels - first_pixel) throw std::logic_error("resolvePixels: past the frame");
  if (count == 0) return {};
  // The samples those pixels reach: every one in quincunx mode (its corners are
  // numbered row by row before the centres); else those of the pixels within the
  // filter's reach rows and columns, all within reach * (width + 1) pixels.
  const std::uint64_t spp = static_cast<std::uint64_t>(m_sampling.spp);
  if (m_sampling.mode == AaMode::Quincunx) {
    requireHeld(0, m_film_total, "resolvePixels");
  } else {
    const std::uint64_t reach = static_cast<std::uint64_t>(filterReach(m_sampling.effectiveFilter())) *
                                (static_cast<std::uint64_t>(opt.width) + 1);
    const std::uint64_t lo = first_pixel > reach ? first_pixel - reach : 0;
    const std::uint64_t hi = std::min<std::uint64_t>(pixels, first_pixel + count + reach);
    requireHeld(lo * spp, (hi - lo) * spp, "resolvePixels");
  }
  m_pixels.reserve(m_context, pixels * 4 * sizeof(float));
  m_context.launch(m_resolve)
      .arg(static_cast<cl_int>(m_sampling.mode))
      .arg(static_cast<cl_int>(m_sampling.effectiveFilter()))
      .arg(static_cast<cl_int>(opt.width))
      .arg(static_cast<cl_int>(opt.height))
      .arg(static_cast<cl_int>(m_sampling.spp))
      .arg(m_sample_xy)
      .arg(m_film)
      .arg(static_cast<cl_int>(m_film_first))
      .arg(static_cast<cl_int>(first_pixel))
      .arg(static_cast<cl_int>(count))
      .arg(m_pixels)
      .run(count);
  std::vector<float> rgba(4 * count);
  m_pixels.read(rgba.data(), rgba.size() * sizeof(float), 4 * first_pixel * sizeof(float));
  return rgba;
}

void DeviceTracer::readSamples(std::uint64_t first, size_t n, float* rgba, float* xy) const {
  requireHeld(first, n, "readSamples");
  m_film.read(rgba, n * kFilmBytesPerSample, (first - m_film_first) * kFilmBytesPerSample);
  m_sample_xy.read(xy, n * kPositionBytesPerSample, (first - m_film_first) * kPositionBytesPerSample);
}

void DeviceTracer::writeSamples(std::uint64_t first, size_t n, const float* rgba, const float* xy) {
  requireHeld(first, n, "writeSamples");
  m_film.write(rgba, n * kFilmBytesPerSample, (first - m_film_first) * kFilmBytesPerSample);
  m_sample_xy.write(xy, n * kPositionBytesPerSample, (first - m_film_first) * kPositionBytesPerSample);
}

std::vector<float> DeviceTracer::traceFilmPositions(const std::vector<float>& xy,
                                                    const std::vector<std::int32_t>& aov_pixel,
                                                    std::uint64_t position_base,
                                                    const std::function<void(size_t done)>& done) {
  const size_t n = xy.size() / 2;
  if (aov_pixel.size() != n) throw std::logic_error("traceFilmPositions: one AOV pixel per position");
  if (n == 0) return {};
  // The colours come back to the host, so the device film need only hold one batch
  // (a whole number of slices; the key is the position's index in its batch).
  const size_t batch = std::min(n, m_film_batch_slices * kSliceRays);
  checkFilmFits(batch, false, batch);
  m_film = Buffer();
  m_film = Buffer(m_context, batch * kFilmBytesPerSample);
  m_film_first = 0;  // keys count from the batch's first position
  m_film_size = batch;
  m_film_total = 0;
  m_film_peak_bytes = std::max(m_film_peak_bytes, filmBytes());
  std::vector<float> rgba(4 * n);
  for (size_t begin = 0; begin < n; begin += batch) {
    const size_t count = std::min(batch, n - begin);
    zeroFill(m_film, count * kFilmBytesPerSample);
    // A key is the position's index in its batch; its strata group follows on
    // from every position traced before it in the frame.
    m_group_base = static_cast<long long>(position_base + begin);
    for (size_t first = 0; first < count; first += kSliceRays) {
      const size_t m = std::min(kSliceRays, count - first);
      if (m_zbuffer && first % kZBufferBatch == 0) {
        // The next Z-buffer batch of positions, rasterised together.
        const size_t z = std::min<size_t>(kZBufferBatch, count - first);
        m_zbuffer_xy.reserve(m_context, z * kPositionBytesPerSample);
        m_zbuffer_xy.write(xy.data() + 2 * (begin + first), z * kPositionBytesPerSample);
        m_firsthit->rasterize(m_geometry, m_zbuffer_xy, 0, 0, z);
      }
      m_zbuffer_first = first % kZBufferBatch;
      m_chunk_xy.write(xy.data() + 2 * (begin + first), m * kPositionBytesPerSample);
      m_chunk_aov.write(aov_pixel.data() + begin + first, m * sizeof(std::int32_t));
      traceChunk(static_cast<int>(first), m);
      if (done) done(begin + first + m);
    }
    m_film.read(rgba.data() + 4 * begin, count * kFilmBytesPerSample);
    ++m_stats->film_batches;
  }
  return rgba;
}

void DeviceTracer::readAovs(std::vector<float>& depth, std::vector<float>& normal, std::vector<std::int32_t>& primid,
                            std::vector<float>& albedo) const {
  const size_t pixels = static_cast<size_t>(m_options->width) * m_options->height;
  depth = m_aov_depth.readVector<float>(pixels);
  normal = m_aov_normal.readVector<float>(pixels * 3);
  primid = m_aov_primid.readVector<std::int32_t>(pixels);
  albedo = m_aov_albedo.readVector<float>(pixels * 3);
}

void DeviceTracer::traceChunk(int first_key, size_t n) {
  m_chunk_first = first_key;
  m_context.launch(m_generate)
      .arg(m_camera)
      .arg(m_chunk_xy)
      .arg(m_chunk_aov)
      .arg(static_cast<cl_int>(first_key))
      .arg(static_cast<cl_int>(m_spp))
      .arg(static_cast<cl_long>(m_group_base))
      .arg(static_cast<cl_int>(m_strata))
      .arg(static_cast<cl_int>(n))
      .arg(static_cast<cl_int>(m_distributed_camera ? 1 : 0))
      .arg(m_work)
      .run((n + kGenerateLanes - 1) / kGenerateLanes);
  m_stats->rays_by_kind[RAY_KIND_PRIMARY] += n;
  m_stats->waves = std::max(m_stats->waves, 1);
  if (m_zbuffer) m_firsthit->resolve(m_geometry, m_zbuffer_first, n, m_hits);
  traceSlice(0, n, m_zbuffer);
}

void DeviceTracer::traceLevel(int depth, size_t count) {
  m_stats->waves = std::max(m_stats->waves, depth + 1);
  for (size_t start = 0; start < count; start += kSliceRays) {
    size_t n = std::min(kSliceRays, count - start);
    m_levels[depth].copyTo(m_work, n * sizeof(RayGpu), start * sizeof(RayGpu), 0);
    traceSlice(depth, n);
  }
}

void DeviceTracer::traceSlice(int depth, size_t n, bool have_hits) {
  const int light_count = static_cast<int>(m_scene->lights.size());
  const RenderOptions& opt = *m_options;
  m_stats->rays_per_depth[depth] += n;

  if (!have_hits) {
    // Camera rays come in sample order, neighbours alike; later waves do not.
    const bool packets = depth == 0 && m_camera_packets;
    KernelLaunch extend = m_extend.launch(packets);
    extend.arg(m_work).arg(static_cast<int>(n));
    m_accel.bind(extend, m_geometry).arg(m_hits).run(m_extend.workItems(n, packets));
  }

  cl_float4 ambient, background;
  for (int i = 0; i < 4; ++i) {
    ambient.s[i] = m_scene->ambient[i];
    background.s[i] = m_scene->background[i];
  }
  KernelLaunch shade = m_context.launch(m_shade);
  shade.arg(m_work).arg(m_hits).arg(static_cast<int>(n));
  m_accel.bind(shade, m_geometry)
      .arg(m_materials)
      .arg(m_texels)
      .arg(m_lights)
      .arg(light_count)
      .arg(m_light_buffer_cells)
      .arg(m_light_buffer_ids)
      .arg(m_light_buffer_windows)
      .arg(static_cast<cl_int>(m_light_buffer_resolution))
      .arg(ambient)
      .arg(background)
      .arg(opt.max_depth)
      .arg(static_cast<float>(opt.min_weight))
      .arg(static_cast<cl_uint>(m_scene->camera.seed))
      .arg(static_cast<cl_int>(m_strata))
      .arg(m_emit)
      .arg(m_children)
      .arg(m_child_tags)
      .arg(m_surfaces)
      .arg(m_aov_depth)
      .arg(m_aov_normal)
      .arg(m_aov_primid)
      .arg(m_aov_albedo)
      .run(n);
  accumulate(m_emit, n, m_work, &m_hits);

  if (m_shadow_slots > 0) traceShadows(n);

  // At the last depth the children's slots are all empty, but they still hold
  // the count of point-light feelers.
  if (depth >= opt.max_depth) {
    if (m_point_lights) countRays(m_child_tags, 2 * n, m_stats->rays_by_kind);
    return;
  }
  size_t child_count = compact(m_children, m_child_tags, 2 * n, m_levels[depth + 1], m_stats->rays_by_kind);
  if (child_count > 0) traceLevel(depth + 1, child_count);
}

void DeviceTracer::traceShadows(size_t surfaces) {
  const int light_count = static_cast<int>(m_scene->lights.size());
  const size_t per_run = std::max<size_t>(1, kShadowSlots / m_shadow_slots);  // shaded points per run
  for (size_t first = 0; first < surfaces; first += per_run) {
    const size_t slots = std::min(per_run, surfaces - first) * m_shadow_slots;
    m_context.launch(m_spawn_shadows)
        .arg(m_surfaces)
        .arg(static_cast<cl_long>(first * m_shadow_slots))
        .arg(static_cast<cl_int>(slots))
        .arg(static_cast<cl_int>(m_shadow_slots))
        .arg(m_materials)
        .arg(m_lights)
        .arg(light_count)
        .arg(static_cast<cl_uint>(m_scene->camera.seed))
        .arg(static_cast<cl_int>(m_strata))
        .arg(m_shadows)
        .arg(m_shadow_tags)
        .run((slots + kSpawnLanes - 1) / kSpawnLanes);
    const size_t live = compact(m_shadows, m_shadow_tags, slots, m_shadow_queue, m_stats->rays_by_kind);
    if (live == 0) continue;
    // A shaded point's feelers are neighbours in the queue, and alike.
    KernelLaunch occlude = m_occlude.launch(m_feeler_packets);
    occlude.arg(m_shadow_queue).arg(static_cast<int>(live));
    m_accel.bind(occlude, m_geometry)
        .arg(m_materials)
        .arg(m_shadow_light)
        .run(m_occlude.workItems(live, m_feeler_packets));
    accumulate(m_shadow_light, live, m_shadow_queue, nullptr);
  }
}

size_t DeviceTracer::countRays(const Buffer& tags, size_t count, std::array<std::uint64_t, 4>& kinds) {
  const int blocks = compactBlocks(count);
  m_context.launch(m_count).arg(tags).arg(static_cast<int>(count)).arg(kCompactBlock).arg(m_counts).run(blocks);
  m_context.launch(m_scan).arg(m_counts).arg(blocks).arg(m_offsets).arg(m_totals).run(1);
  std::int32_t totals[RAY_TOTALS];
  m_totals.read(totals, sizeof totals);
  for (int k = 0; k < RAY_KIND_COUNT; ++k) kinds[k] += static_cast<std::uint64_t>(totals[k]);
  kinds[RAY_KIND_SHADOW] += static_cast<std::uint64_t>(totals[RAY_TOTAL_FEELERS]);
  return static_cast<size_t>(totals[RAY_TOTAL_LIVE]);
}

size_t DeviceTracer::compact(const Buffer& in, const Buffer& tags, size_t count, Buffer& out,
                         std::array<std::uint64_t, 4>& kinds) {
  const size_t total = countRays(tags, count, kinds);
  if (total == 0) return 0;
  m_context.launch(m_scatter)
      .arg(in)
      .arg(tags)
      .arg(static_cast<int>(count))
      .arg(kCompactBlock)
      .arg(m_offsets)
      .arg(out)
      .run(compactBlocks(count));
  return static_cast<size_t>(total);
}

void DeviceTracer::accumulate(const Buffer& contributions, size_t count, const Buffer& rays, const Buffer* hits) {
  m_context.launch(m_accumulate)
      .arg(contributions)
      .arg(static_cast<int>(count))
      .arg(m_film)
      .arg(static_cast<cl_int>(m_film_first))
      .arg(m_first_bad)
      .run(count);
  if (!m_options->check_nan || m_stats->nan) return;
  std::int32_t k = 0;
  m_first_bad.read(&k, sizeof k);
  if (k == std::numeric_limits<std::int32_t>::max()) return;
  ContributionGpu c;
  contributions.read(&c, sizeof c, static_cast<size_t>(k) * sizeof c);
  RayGpu ray;
  rays.read(&ray, sizeof ray, static_cast<size_t>(k) * sizeof ray);
  NanFinding f;
  // Adaptive keys count from their batch: the finding names the position's
  // index in the frame (m_group_base is 0 for the other modes).
  f.sample = static_cast<std::uint64_t>(m_group_base + ray.pixel);
  f.ray_kind = ray.kind;
  f.depth = ray.depth;
  f.origin = {ray.ox, ray.oy, ray.oz};
  f.direction = {ray.dx, ray.dy, ray.dz};
  f.value = {c.r, c.g, c.b, c.a};
  if (hits) {
    HitGpu hit;
    hits->read(&hit, sizeof hit, static_cast<size_t>(k) * sizeof hit);
    f.prim = hit.prim;
    f.t = hit.t;
  }
  float xy[2] = {0, 0};
  m_chunk_xy.read(xy, sizeof xy, static_cast<size_t>(ray.pixel - m_chunk_first) * sizeof xy);
  f.film_x = xy[0];
  f.film_y = xy[1];
  m_stats->nan = f;
}

void DeviceTracer::zeroFill(Buffer& buffer, size_t bytes, size_t offset) {
  if (bytes == 0) return;
  const cl_float zero = 0.0f;
  buffer.fill(&zero, sizeof zero, bytes, offset);
}

void DeviceTracer::checkFilmFits(std::uint64_t samples, bool with_positions, std::uint64_t keys) const {
  const RenderOptions& opt = *m_options;
  const std::uint64_t pixels = static_cast<std::uint64_t>(opt.width) * opt.height;
  const DeviceDescription& device = m_context.device();
  const std::uint64_t max_alloc = device.max_alloc_bytes;
  const std::uint64_t global = device.global_memory_bytes;
  // Everything else this render keeps on the device: queues, scene, structure, AOVs.
  std::uint64_t other = pixels * kBytesPerPixel + deviceGeometryBytes(*m_scene) +
                        m_accel_bytes + m_tile.bytes();
  for (const Buffer* b : {&m_work, &m_hits, &m_emit, &m_children, &m_child_tags, &m_surfaces, &m_shadows,
                          &m_shadow_tags, &m_shadow_queue, &m_shadow_light, &m_counts, &m_offsets, &m_chunk_xy,
                          &m_chunk_aov})
    other += b->bytes();
  for (const Buffer& b : m_levels) other += b.bytes();
  if (m_firsthit && m_zbuffer)  // its per-sample buffers at their largest (a batch, or all samples if fewer)
    other += m_firsthit->deviceBytes() - m_firsthit->batchBytes() +
             std::max<std::uint64_t>(m_firsthit->batchBytes(),
                                     std::min<std::uint64_t>(kZBufferBatch, samples) * kZBufferBytesPerSample);
  else if (m_firsthit)  // what an earlier render's pass still holds (FirstHitPass keeps its buffers)
    other += m_firsthit->deviceBytes();

  const std::uint64_t per_sample = kFilmBytesPerSample + (with_positions ? kPositionBytesPerSample : 0);
  const std::uint64_t max_keys = static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max());
  std::uint64_t fit = max_alloc / kFilmBytesPerSample;
  fit = std::min<std::uint64_t>(fit, global > other ? (global - other) / per_sample : 0);
  if (samples <= fit && keys <= max_keys) return;
  if (samples <= fit)
    throw FilmTooLarge("the frame has " + std::to_string(keys) +
                       " samples, but a film key must stay under 2^31; use fewer samples per pixel (at most " +
                       std::to_string(max_keys / std::max<std::uint64_t>(1, pixels)) + " at " +
                       std::to_string(opt.width) + "x" + std::to_string(opt.height) + ") or a smaller image");
  std::string advice;
  const std::uint64_t per_pixel = std::min(fit, max_keys) / std::max<std::uint64_t>(1, pixels);
  if (samples < keys)  // a window of one unit: fewer samples per pixel would not shrink it
    advice = "the device holds one unit of the frame at a time, so only a smaller scene or leaving it out helps";
  else if (with_positions && m_options->spp > 1 && per_pixel >= 1)
    advice = "use fewer samples per pixel (at most " + std::to_string(per_pixel) + " at " + std::to_string(opt.width) +
             "x" + std::to_string(opt.height) + ") or a smaller image";
  else
    advice = "use a smaller image, fewer samples per pixel, or a lower adaptive level";
  throw FilmTooLarge("the film needs " + std::to_string(samples) + " samples at " + std::to_string(per_sample) +
                     " bytes each (" + gib(static_cast<double>(samples) * per_sample) + ") but device '" +
                     device.name + "' takes at most " + gib(static_cast<double>(max_alloc)) + " in one buffer, " +
                     gib(static_cast<double>(global)) + " in all (" + gib(static_cast<double>(other)) +
                     " already used by this render)" +
                     (keys > max_keys ? ", and a film key must stay under 2^31" : "") + "; " + advice);
}

}  // namespace prism
