#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "kernels/shared/ray_gpu.h"
#include "render/light_buffer.h"

namespace prism {

Renderer::Renderer(Context& context) : m_context(context), m_tracer(context) {}

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
  RenderResult result;
  result.width = options.width;
  result.height = options.height;
  result.stats.aa = sampling.mode;
  result.stats.filter = sampling.effectiveFilter();
  result.stats.first_hit = first_hit;
  if (options.profile) m_context.profile().start();
  struct Reset {
    Renderer* r;
    ~Reset() {
      r->m_context.profile().discard();  // what a finished render did not take
      r->m_tracer.unload();
    }
  } reset{this};

  // Built once on the host, whichever devices trace the frame.
  AccelBuildOptions build = m_accel_build;
  build.kdop_objects = build.kdop_bvh = options.bounds == BoundsKind::Kdop;
  const std::unique_ptr<DeviceAccel> accel = buildAccel(options.accel, gpu.objects, build);
  result.stats.accel = accel->kind;  // what auto chose
  result.stats.accel_stats = accel->stats;
  // Point lights' feelers: through the light buffer or the structure.
  LightBuffer light_buffer;
  result.stats.shadows = planShadows(options.shadows, accel->kind, gpu.objects, gpu.lights, &light_buffer);
  if (result.stats.shadows == ShadowMode::LightBuffer) result.stats.light_buffer_candidates = light_buffer.mean_candidates;

  FrameSetup frame;
  frame.scene = &gpu;
  frame.accel = accel.get();
  frame.light_buffer = &light_buffer;
  frame.use_light_buffer = result.stats.shadows == ShadowMode::LightBuffer;
  frame.options = &options;
  frame.sampling = sampling;
  frame.zbuffer = first_hit == FirstHitMode::ZBuffer;
  frame.distributed_camera = !pinhole;
  m_tracer.load(frame, result.stats);

  result.stats.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (sampling.mode == AaMode::Adaptive)
    renderAdaptive(sampling, options, result, progress);
  else
    renderSamples(sampling, options, result, progress);

  const size_t pixels = static_cast<size_t>(options.width) * options.height;
  result.stats.rays_per_pixel =
      static_cast<double>(result.stats.rays_by_kind[RAY_KIND_PRIMARY]) / static_cast<double>(pixels);
  m_tracer.readAovs(result.depth, result.normal, result.primid, result.albedo);
  m_tracer.unload();
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.stats.first_launch_seconds = m_context.takeFirstLaunchSeconds();
  if (options.profile) result.stats.kernels = m_context.profile().stop();
  return result;
}

void Renderer::renderSamples(const SamplingOptions& sampling, const RenderOptions& opt, RenderResult& result,
                             const ProgressFn& progress) {
  const std::uint64_t total = sampleCount(sampling.mode, opt.width, opt.height, sampling.spp);
  m_tracer.beginSampleFilm(total);
  // The Z-buffer rasterises a batch of samples at once; tracing alone goes
  // chunk by chunk through the whole sequence.
  const std::uint64_t batch = result.stats.first_hit == FirstHitMode::ZBuffer ? DeviceTracer::kZBufferBatch : total;
  for (std::uint64_t first = 0; first < total; first += batch)
    m_tracer.traceSamples(first, std::min(total, first + batch), [&](std::uint64_t done) {
      if (progress && !progress(static_cast<double>(done) / static_cast<double>(total))) throw RenderCancelled();
    });
  result.rgba = m_tracer.resolvePixels();
}

void Renderer::renderAdaptive(const SamplingOptions& sampling, const RenderOptions& opt, RenderResult& result,
                              const ProgressFn& progress) {
  const std::int64_t w = opt.width, h = opt.height;
  // Passes: the corners, then at most one per level. Progress counts passes, each
  // in proportion to its chunks done.
  const double passes = 1.0 + sampling.adaptive_max_level;
  int pass = 0;
  std::uint64_t traced = 0;  // positions of the passes before
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
    std::vector<float> rgba = m_tracer.traceFilmPositions(xy, aov, traced, [&](size_t done) {
      if (progress && !progress(std::min(1.0, (pass + static_cast<double>(done) / n) / passes)))
        throw RenderCancelled();
    });
    ++pass;
    traced += n;
    return rgba;
  };
  AdaptiveResult adaptive =
      adaptiveSample(opt.width, opt.height, sampling.adaptive_threshold, sampling.adaptive_max_level, trace);
  result.rgba = std::move(adaptive.pixels);
  if (progress && !progress(1.0)) throw RenderCancelled();
}

}  // namespace prism
