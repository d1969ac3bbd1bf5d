#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "kernels/shared/contribution_gpu.h"
#include "kernels/shared/hit_gpu.h"
#include "kernels/shared/ray_gpu.h"
#include "kernels/shared/surface_gpu.h"
#include "render/light_buffer.h"

namespace prism {
namespace {

constexpr int kCompactBlock = 256;  // slots counted by one work-item of count_rays

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

Renderer::Renderer(Context& context) : m_context(context) {
  m_count = context.kernel(kRenderLoopProgram, "count_rays");
  m_scan = context.kernel(kRenderLoopProgram, "scan_blocks");
  m_scatter = context.kernel(kRenderLoopProgram, "scatter_rays");
  m_accumulate = context.kernel(kRenderLoopProgram, "accumulate");
  m_supersample = context.kernel(kRenderLoopProgram, "supersample");
  m_resolve = context.kernel(kRenderLoopProgram, "resolve");
  m_generate = context.kernel(kRenderLoopProgram, "generate");
}

Renderer::~Renderer() = default;

RenderResult Renderer::render(const Scene& scene, const RenderOptions& options, const ProgressFn& progress) {
  options.validate();
  m_context.takeFirstLaunchSeconds();  // launches before this render are not its start-up
  auto start = std::chrono::steady_clock::now();
  const SamplingOptions sampling = options.sampling();
  // The first-hit pass serves rays that leave one point at one instant.
  const bool pinhole = scene.camera.isPinhole();
  FirstHitMode first_hit = options.first_hit;
  if (first_hit == FirstHitMode::ZBuffer && !pinhole)
    throw std::invalid_argument(std::string("first hit zbuffer needs a pinhole camera, but this one has ") +
                                (scene.camera.aperture > 0 ? "an aperture (depth of field)"
                                                           : "a shutter interval (motion blur)") +
                                ": its primary rays do not share one origin and instant; use first hit trace or auto");

  GpuScene gpu = flattenScene(scene, options);
  if (first_hit == FirstHitMode::Auto) {
    const std::uint64_t samples = sampling.mode == AaMode::Adaptive
                                      ? static_cast<std::uint64_t>(options.width + 1) * (options.height + 1)
                                      : sampleCount(sampling.mode, options.width, options.height, sampling.spp);
    first_hit = pinhole && zbufferPays(gpu, samples) ? FirstHitMode::ZBuffer : FirstHitMode::Trace;
  }
  // Each distributed effect's code is compiled only into the programs of scenes
  // that use it, so a Whitted scene builds what it did before (PoCL compiles slowly).
  const KernelFeatures features = kernelFeatures(gpu);
  RenderResult result;
  result.width = options.width;
  result.height = options.height;
  result.stats.aa = sampling.mode;
  result.stats.filter = sampling.effectiveFilter();
  result.stats.first_hit = first_hit;
  m_scene = &gpu;
  m_options = &options;
  m_stats = &result.stats;
  m_zbuffer = first_hit == FirstHitMode::ZBuffer;
  m_distributed_camera = !pinhole;
  m_spp = sampling.spp;
  m_strata = sampling.mode == AaMode::Random ? 0 : sampling.spp;
  m_group_base = 0;
  m_shadow_slots = 0;
  m_point_lights = false;
  for (const LightGpu& l : gpu.lights) {
    m_shadow_slots += l.samples;  // 0 for point lights
    m_point_lights = m_point_lights || l.type == LIGHT_POINT;
  }
  if (options.profile) m_context.profile().start();
  struct Reset {
    Renderer* r;
    ~Reset() {
      r->m_context.profile().discard();  // what a finished render did not take
      r->m_scene = nullptr;
      r->m_options = nullptr;
      r->m_stats = nullptr;
    }
  } reset{this};

  const size_t pixels = static_cast<size_t>(options.width) * options.height;
  m_camera = Buffer(m_context, sizeof(CameraGpu));
  m_camera.write(&gpu.camera, sizeof(CameraGpu));
  const std::int32_t none_bad = std::numeric_limits<std::int32_t>::max();
  m_first_bad = Buffer(m_context, sizeof none_bad);
  m_first_bad.write(&none_bad, sizeof none_bad);
  m_geometry.upload(m_context, gpu);
  {
    AccelBuildOptions build = m_accel_build;
    build.kdop_objects = build.kdop_bvh = options.bounds == BoundsKind::Kdop;
    std::unique_ptr<DeviceAccel> accel = buildAccel(options.accel, gpu.objects, build);
    m_accel.upload(m_context, *accel);
    result.stats.accel = accel->kind;  // what auto chose
    result.stats.accel_stats = accel->stats;
    m_extend = m_context.kernel("extend.cl", "extend", accel->kernel_options);
    // Point lights' feelers: through the light buffer or the structure.
    LightBuffer light_buffer;
    result.stats.shadows = planShadows(options.shadows, accel->kind, gpu.objects, gpu.lights, &light_buffer);
    const bool use_light_buffer = result.stats.shadows == ShadowMode::LightBuffer;
    if (use_light_buffer) result.stats.light_buffer_candidates = light_buffer.mean_candidates;
    if (light_buffer.cells.empty()) light_buffer.cells.assign(2, 0);  // (bound, never read)
    if (light_buffer.ids.empty()) light_buffer.ids.push_back(0);
    if (light_buffer.windows.empty()) light_buffer.windows.assign(4, 0.0f);
    m_light_buffer_cells = Buffer(m_context, light_buffer.cells.size() * sizeof(std::int32_t));
    m_light_buffer_cells.writeVector(light_buffer.cells);
    m_light_buffer_ids = Buffer(m_context, light_buffer.ids.size() * sizeof(std::int32_t));
    m_light_buffer_ids.writeVector(light_buffer.ids);
    m_light_buffer_windows = Buffer(m_context, light_buffer.windows.size() * sizeof(float));
    m_light_buffer_windows.writeVector(light_buffer.windows);
    m_light_buffer_resolution = light_buffer.resolution;
    m_shade = m_context.kernel("shade.cl", "shade",
                               accel->kernel_options + features.shading + (use_light_buffer ? " -DPRISM_LIGHT_BUFFER" : ""));
    if (m_shadow_slots > 0) {
      m_spawn_shadows = m_context.kernel("spawn_shadows.cl", "spawn_shadows", features.shadows);
      m_occlude = m_context.kernel("occlude.cl", "occlude", accel->kernel_options);
    }
  }
  if (m_zbuffer) {
    if (!m_firsthit) m_firsthit = std::make_unique<FirstHitPass>(m_context);
    m_firsthit->prepare(gpu);
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

  result.stats.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (sampling.mode == AaMode::Adaptive)
    renderAdaptive(sampling, result, progress);
  else
    renderSamples(sampling, result, progress);

  result.stats.rays_per_pixel =
      static_cast<double>(result.stats.rays_by_kind[RAY_KIND_PRIMARY]) / static_cast<double>(pixels);
  result.depth = m_aov_depth.readVector<float>(pixels);
  result.normal = m_aov_normal.readVector<float>(pixels * 3);
  result.primid = m_aov_primid.readVector<std::int32_t>(pixels);
  result.albedo = m_aov_albedo.readVector<float>(pixels * 3);
  // The per-sample film can be large: give it back now rather than at the next render.
  m_film = Buffer();
  m_sample_xy = Buffer();
  m_zbuffer_xy = Buffer();
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.stats.first_launch_seconds = m_context.takeFirstLaunchSeconds();
  if (options.profile) result.stats.kernels = m_context.profile().stop();
  return result;
}

void Renderer::renderSamples(const SamplingOptions& sampling, RenderResult& result, const ProgressFn& progress) {
  const RenderOptions& opt = *m_options;
  const size_t pixels = static_cast<size_t>(opt.width) * opt.height;
  const std::uint64_t total = sampleCount(sampling.mode, opt.width, opt.height, sampling.spp);
  checkFilmFits(total, true);

  std::vector<float> tile_xy(2, 0.0f);  // a buffer may not be empty
  if (sampling.mode == AaMode::Poisson) tile_xy = poissonTile(sampling.spp, opt.seed).xy;
  m_tile = Buffer(m_context, tile_xy.size() * sizeof(float));
  m_tile.writeVector(tile_xy);
  m_film = Buffer();  // free the last render's film before asking for this one
  m_sample_xy = Buffer();
  m_film = Buffer(m_context, total * kFilmBytesPerSample);
  zeroFill(m_film, total * kFilmBytesPerSample);
  m_sample_xy = Buffer(m_context, total * kPositionBytesPerSample);

  // Chunks of kSliceRays samples in sequence order: keys ascend within each.
  auto positions = [&](std::uint64_t first, size_t n) {
    m_context.launch(m_supersample)
        .arg(static_cast<cl_int>(sampling.mode))
        .arg(static_cast<cl_int>(opt.width))
        .arg(static_cast<cl_int>(opt.height))
        .arg(static_cast<cl_int>(sampling.spp))
        .arg(static_cast<cl_uint>(kernelSeed(opt.seed)))
        .arg(m_tile)
        .arg(static_cast<cl_long>(first))
        .arg(static_cast<cl_int>(n))
        .arg(m_chunk_xy)
        .arg(m_chunk_aov)
        .run(n);
    m_chunk_xy.copyTo(m_sample_xy, n * kPositionBytesPerSample, 0, first * kPositionBytesPerSample);
  };
  // The Z-buffer takes kZBufferBatch samples at once: their positions first,
  // rasterised together, then resolved chunk by chunk.
  const std::uint64_t batch = m_zbuffer ? kZBufferBatch : total;
  for (std::uint64_t batch_first = 0; batch_first < total; batch_first += batch) {
    const std::uint64_t batch_end = std::min(total, batch_first + batch);
    if (m_zbuffer) {
      for (std::uint64_t first = batch_first; first < batch_end; first += kSliceRays)
        positions(first, static_cast<size_t>(std::min<std::uint64_t>(kSliceRays, batch_end - first)));
      // Per-pixel modes number their samples pixel by pixel: no sort needed.
      m_firsthit->rasterize(m_geometry, m_sample_xy, static_cast<size_t>(batch_first),
                            static_cast<size_t>(batch_end - batch_first),
                            sampling.mode == AaMode::Quincunx ? 0 : sampling.spp);
    }
    for (std::uint64_t first = batch_first; first < batch_end; first += kSliceRays) {
      const size_t n = static_cast<size_t>(std::min<std::uint64_t>(kSliceRays, batch_end - first));
      positions(first, n);
      m_zbuffer_first = static_cast<size_t>(first - batch_first);
      traceChunk(static_cast<int>(first), n);
      if (progress && !progress(static_cast<double>(first + n) / static_cast<double>(total))) throw RenderCancelled();
    }
  }

  m_pixels.reserve(m_context, pixels * 4 * sizeof(float));
  m_context.launch(m_resolve)
      .arg(static_cast<cl_int>(sampling.mode))
      .arg(static_cast<cl_int>(sampling.effectiveFilter()))
      .arg(static_cast<cl_int>(opt.width))
      .arg(static_cast<cl_int>(opt.height))
      .arg(static_cast<cl_int>(sampling.spp))
      .arg(m_sample_xy)
      .arg(m_film)
      .arg(static_cast<cl_int>(0))
      .arg(static_cast<cl_int>(pixels))
      .arg(m_pixels)
      .run(pixels);
  result.rgba = m_pixels.readVector<float>(pixels * 4);
}

void Renderer::renderAdaptive(const SamplingOptions& sampling, RenderResult& result, const ProgressFn& progress) {
  const RenderOptions& opt = *m_options;
  const std::int64_t w = opt.width, h = opt.height;
  // Passes: the corners, then at most one per level. Progress counts passes, each
  // in proportion to its chunks done.
  const double passes = 1.0 + sampling.adaptive_max_level;
  int pass = 0;
  TraceFn trace = [&](const std::vector<float>& xy) {
    const size_t n = xy.size() / 2;
    // The corner (i, j) of pixel (i, j) is its first sample and writes its AOVs
    // (every corner comes in the first pass; later points are never corners).
    std::vector<std::int32_t> aov(n, -1);
    for (size_t k = 0; k < n; ++k) {
      const float x = xy[2 * k], y = xy[2 * k + 1];
      if (x == std::floor(x) && y == std::floor(y) && x < w && y < h)
        aov[k] = static_cast<std::int32_t>(static_cast<std::int64_t>(y) * w + static_cast<std::int64_t>(x));
    }
    std::vector<float> rgba = traceFilmPositions(xy, aov, [&](size_t done) {
      if (progress && !progress(std::min(1.0, (pass + static_cast<double>(done) / n) / passes)))
        throw RenderCancelled();
    });
    ++pass;
    return rgba;
  };
  AdaptiveResult adaptive =
      adaptiveSample(opt.width, opt.height, sampling.adaptive_threshold, sampling.adaptive_max_level, trace);
  result.rgba = std::move(adaptive.pixels);
  if (progress && !progress(1.0)) throw RenderCancelled();
}

std::vector<float> Renderer::traceFilmPositions(const std::vector<float>& xy,
                                                const std::vector<std::int32_t>& aov_pixel,
                                                const std::function<void(size_t done)>& done) {
  const size_t n = xy.size() / 2;
  if (aov_pixel.size() != n) throw std::logic_error("traceFilmPositions: one AOV pixel per position");
  if (n == 0) return {};
  // The colours come back to the host, so the device film need only hold one batch
  // (a whole number of slices; the key is the position's index in its batch).
  const size_t batch = std::min(n, m_film_batch_slices * kSliceRays);
  checkFilmFits(batch, false);
  m_film = Buffer();
  m_film = Buffer(m_context, batch * kFilmBytesPerSample);
  std::vector<float> rgba(4 * n);
  for (size_t begin = 0; begin < n; begin += batch) {
    const size_t count = std::min(batch, n - begin);
    zeroFill(m_film, count * kFilmBytesPerSample);
    for (size_t first = 0; first < count; first += kSliceRays) {
      const size_t m = std::min(kSliceRays, count - first);
      if (m_zbuffer && first % kZBufferBatch == 0) {
        // The next Z-buffer batch of positions, rasterised together.
        const size_t z = std::min<size_t>(kZBufferBatch, count - first);
        m_zbuffer_xy.reserve(m_context, z * kPositionBytesPerSample);
        m_zbuffer_xy.write(xy.data() + 2 * (begin + first), z * kPositionBytesPerSample);
        m_firsthit->rasterize(m_geometry, m_zbuffer_xy, 0, z);
      }
      m_zbuffer_first = first % kZBufferBatch;
      m_chunk_xy.write(xy.data() + 2 * (begin + first), m * kPositionBytesPerSample);
      m_chunk_aov.write(aov_pixel.data() + begin + first, m * sizeof(std::int32_t));
      m_group_base = static_cast<long long>(m_stats->rays_by_kind[RAY_KIND_PRIMARY]) - static_cast<long long>(first);
      traceChunk(static_cast<int>(first), m);
      if (done) done(begin + first + m);
    }
    m_film.read(rgba.data() + 4 * begin, count * kFilmBytesPerSample);
    ++m_stats->film_batches;
  }
  return rgba;
}

void Renderer::traceChunk(int first_key, size_t n) {
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
      .run(n);
  m_stats->rays_by_kind[RAY_KIND_PRIMARY] += n;
  m_stats->waves = std::max(m_stats->waves, 1);
  if (m_zbuffer) m_firsthit->resolve(m_geometry, m_zbuffer_first, n, m_hits);
  traceSlice(0, n, m_zbuffer);
}

void Renderer::traceLevel(int depth, size_t count) {
  m_stats->waves = std::max(m_stats->waves, depth + 1);
  for (size_t start = 0; start < count; start += kSliceRays) {
    size_t n = std::min(kSliceRays, count - start);
    m_levels[depth].copyTo(m_work, n * sizeof(RayGpu), start * sizeof(RayGpu), 0);
    traceSlice(depth, n);
  }
}

void Renderer::traceSlice(int depth, size_t n, bool have_hits) {
  const int light_count = static_cast<int>(m_scene->lights.size());
  const RenderOptions& opt = *m_options;
  m_stats->rays_per_depth[depth] += n;

  if (!have_hits) {
    KernelLaunch extend = m_context.launch(m_extend);
    extend.arg(m_work).arg(static_cast<int>(n));
    m_accel.bind(extend, m_geometry).arg(m_hits).run(n);
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

void Renderer::traceShadows(size_t surfaces) {
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
        .run(slots);
    const size_t live = compact(m_shadows, m_shadow_tags, slots, m_shadow_queue, m_stats->rays_by_kind);
    if (live == 0) continue;
    KernelLaunch occlude = m_context.launch(m_occlude);
    occlude.arg(m_shadow_queue).arg(static_cast<int>(live));
    m_accel.bind(occlude, m_geometry).arg(m_materials).arg(m_shadow_light).run(live);
    accumulate(m_shadow_light, live, m_shadow_queue, nullptr);
  }
}

size_t Renderer::countRays(const Buffer& tags, size_t count, std::array<std::uint64_t, 4>& kinds) {
  const int blocks = compactBlocks(count);
  m_context.launch(m_count).arg(tags).arg(static_cast<int>(count)).arg(kCompactBlock).arg(m_counts).run(blocks);
  m_context.launch(m_scan).arg(m_counts).arg(blocks).arg(m_offsets).arg(m_totals).run(1);
  std::int32_t totals[RAY_TOTALS];
  m_totals.read(totals, sizeof totals);
  for (int k = 0; k < RAY_KIND_COUNT; ++k) kinds[k] += static_cast<std::uint64_t>(totals[k]);
  kinds[RAY_KIND_SHADOW] += static_cast<std::uint64_t>(totals[RAY_TOTAL_FEELERS]);
  return static_cast<size_t>(totals[RAY_TOTAL_LIVE]);
}

size_t Renderer::compact(const Buffer& in, const Buffer& tags, size_t count, Buffer& out,
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

void Renderer::accumulate(const Buffer& contributions, size_t count, const Buffer& rays, const Buffer* hits) {
  m_context.launch(m_accumulate)
      .arg(contributions)
      .arg(static_cast<int>(count))
      .arg(m_film)
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
  f.sample = static_cast<std::uint64_t>(ray.pixel);
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

void Renderer::zeroFill(Buffer& buffer, size_t bytes) {
  if (bytes == 0) return;
  const cl_float zero = 0.0f;
  buffer.fill(&zero, sizeof zero, bytes);
}

void Renderer::checkFilmFits(std::uint64_t samples, bool with_positions) const {
  const RenderOptions& opt = *m_options;
  const std::uint64_t pixels = static_cast<std::uint64_t>(opt.width) * opt.height;
  const DeviceDescription& device = m_context.device();
  const std::uint64_t max_alloc = device.max_alloc_bytes;
  const std::uint64_t global = device.global_memory_bytes;
  // Everything else this render keeps on the device: queues, scene, structure, AOVs.
  std::uint64_t other = pixels * kBytesPerPixel + deviceGeometryBytes(*m_scene) +
                        m_stats->accel_stats.bytes + m_tile.bytes();
  for (const Buffer* b : {&m_work, &m_hits, &m_emit, &m_children, &m_child_tags, &m_surfaces, &m_shadows,
                          &m_shadow_tags, &m_shadow_queue, &m_shadow_light, &m_counts, &m_offsets, &m_chunk_xy,
                          &m_chunk_aov})
    other += b->bytes();
  for (const Buffer& b : m_levels) other += b.bytes();
  if (m_firsthit && m_zbuffer)  // its per-sample buffers at their largest (a batch, or all samples if fewer)
    other += m_firsthit->deviceBytes() + std::min<std::uint64_t>(kZBufferBatch, samples) * kZBufferBytesPerSample;

  const std::uint64_t per_sample = kFilmBytesPerSample + (with_positions ? kPositionBytesPerSample : 0);
  const std::uint64_t max_key = static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max());
  std::uint64_t fit = std::min<std::uint64_t>(max_key, max_alloc / kFilmBytesPerSample);
  fit = std::min<std::uint64_t>(fit, global > other ? (global - other) / per_sample : 0);
  if (samples <= fit) return;
  std::string advice;
  const std::uint64_t per_pixel = fit / std::max<std::uint64_t>(1, pixels);
  if (with_positions && m_options->spp > 1 && per_pixel >= 1)
    advice = "use fewer samples per pixel (at most " + std::to_string(per_pixel) + " at " + std::to_string(opt.width) +
             "x" + std::to_string(opt.height) + ") or a smaller image";
  else
    advice = "use a smaller image, fewer samples per pixel, or a lower adaptive level";
  throw FilmTooLarge("the film needs " + std::to_string(samples) + " samples at " + std::to_string(per_sample) +
                     " bytes each (" + gib(static_cast<double>(samples) * per_sample) + ") but device '" +
                     device.name + "' takes at most " + gib(static_cast<double>(max_alloc)) + " in one buffer, " +
                     gib(static_cast<double>(global)) + " in all (" + gib(static_cast<double>(other)) +
                     " already used by this render), and a film index must stay under 2^31; " + advice);
}

}  // namespace prism
