#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "kernels/shared/contribution_gpu.h"
#include "kernels/shared/hit_gpu.h"
#include "kernels/shared/ray_gpu.h"

namespace prism {
namespace {

constexpr int kCompactBlock = 256;  // slots counted by one work-item of count_rays

template <typename T>
void fillZero(Buffer& b, size_t count) {
  std::vector<T> zeros(count, T{});
  b.writeVector(zeros);
}

}  // namespace

Renderer::Renderer(Context& context) : m_context(context) {
  m_generate = context.kernel("generate.cl", "generate");
  m_shade = context.kernel("shade.cl", "shade");
  m_count = context.kernel("count_rays.cl", "count_rays");
  m_scatter = context.kernel("scatter_rays.cl", "scatter_rays");
  m_accumulate = context.kernel("accumulate.cl", "accumulate");
}

RenderResult Renderer::render(const Scene& scene, const RenderOptions& options, const ProgressFn& progress) {
  options.validate();
  auto start = std::chrono::steady_clock::now();
  GpuScene gpu = flattenScene(scene, options);
  RenderResult result;
  result.width = options.width;
  result.height = options.height;
  m_scene = &gpu;
  m_options = &options;
  m_stats = &result.stats;

  const size_t pixels = static_cast<size_t>(options.width) * options.height;
  m_camera = Buffer(m_context, sizeof(CameraGpu));
  m_camera.write(&gpu.camera, sizeof(CameraGpu));
  m_objects = Buffer(m_context, gpu.objects.size() * sizeof(ObjectGpu));
  m_objects.writeVector(gpu.objects);
  {
    std::unique_ptr<DeviceAccel> accel = buildAccel(options.accel, gpu.objects);
    m_accel.upload(m_context, *accel);
    result.stats.accel = options.accel;
    result.stats.accel_stats = accel->stats;
    m_extend = m_context.kernel("extend.cl", "extend", accel->kernel_options);
    m_occlude = m_context.kernel("occlude.cl", "occlude", accel->kernel_options);
  }
  m_materials = Buffer(m_context, gpu.materials.size() * sizeof(MaterialGpu));
  m_materials.writeVector(gpu.materials);
  m_lights = Buffer(m_context, gpu.lights.size() * sizeof(LightGpu));
  m_lights.writeVector(gpu.lights);
  m_film = Buffer(m_context, pixels * 4 * sizeof(float));
  fillZero<float>(m_film, pixels * 4);
  m_aov_depth = Buffer(m_context, pixels * sizeof(float));
  m_aov_normal = Buffer(m_context, pixels * 3 * sizeof(float));
  m_aov_primid = Buffer(m_context, pixels * sizeof(std::int32_t));
  m_aov_albedo = Buffer(m_context, pixels * 3 * sizeof(float));

  const size_t light_count = gpu.lights.size();
  m_levels.clear();
  for (int d = 0; d <= options.max_depth; ++d) m_levels.emplace_back(m_context, 2 * kSliceRays * sizeof(RayGpu));
  m_work.reserve(m_context, kSliceRays * sizeof(RayGpu));
  m_hits.reserve(m_context, kSliceRays * sizeof(HitGpu));
  m_emit.reserve(m_context, kSliceRays * sizeof(ContributionGpu));
  m_children.reserve(m_context, 2 * kSliceRays * sizeof(RayGpu));
  m_shadows.reserve(m_context, kSliceRays * light_count * sizeof(RayGpu));
  m_shadow_queue.reserve(m_context, kSliceRays * light_count * sizeof(RayGpu));
  m_shadow_light.reserve(m_context, kSliceRays * light_count * sizeof(ContributionGpu));
  size_t max_blocks = (2 * kSliceRays * std::max<size_t>(light_count, 1) + kCompactBlock - 1) / kCompactBlock;
  m_counts.reserve(m_context, max_blocks * RAY_KIND_COUNT * sizeof(std::int32_t));
  m_offsets.reserve(m_context, max_blocks * sizeof(std::int32_t));

  // Whole pixels per chunk, so all samples of a pixel share one primary slice.
  const size_t chunk_pixels = std::max<size_t>(1, kSliceRays / options.spp);
  for (size_t first = 0; first < pixels; first += chunk_pixels) {
    size_t n_pixels = std::min(chunk_pixels, pixels - first);
    size_t n = n_pixels * options.spp;
    m_context.launch(m_generate).arg(m_camera).arg(static_cast<int>(first)).arg(static_cast<int>(n)).arg(m_levels[0]).run(n);
    m_stats->rays_by_kind[RAY_KIND_PRIMARY] += n;
    traceLevel(0, n);
    if (progress && !progress(static_cast<double>(first + n_pixels) / pixels)) throw RenderCancelled();
  }

  std::vector<float> film = m_film.readVector<float>(pixels * 4);
  const float inv_spp = 1.0f / static_cast<float>(options.spp);
  for (float& v : film) v *= inv_spp;
  result.rgba = std::move(film);
  result.depth = m_aov_depth.readVector<float>(pixels);
  result.normal = m_aov_normal.readVector<float>(pixels * 3);
  result.primid = m_aov_primid.readVector<std::int32_t>(pixels);
  result.albedo = m_aov_albedo.readVector<float>(pixels * 3);
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m_scene = nullptr;
  m_options = nullptr;
  m_stats = nullptr;
  return result;
}

void Renderer::traceLevel(int depth, size_t count) {
  m_stats->waves = std::max(m_stats->waves, depth + 1);
  for (size_t start = 0; start < count; start += kSliceRays) {
    size_t n = std::min(kSliceRays, count - start);
    PRISM_CL_CHECK(clEnqueueCopyBuffer(m_context.queue(), m_levels[depth].handle(), m_work.handle(),
                                       start * sizeof(RayGpu), 0, n * sizeof(RayGpu), 0, nullptr, nullptr));
    traceSlice(depth, n);
  }
}

void Renderer::traceSlice(int depth, size_t n) {
  const int object_count = static_cast<int>(m_scene->objects.size());
  const int light_count = static_cast<int>(m_scene->lights.size());
  const RenderOptions& opt = *m_options;
  m_stats->rays_per_depth[depth] += n;

  {
    KernelLaunch extend = m_context.launch(m_extend);
    extend.arg(m_work).arg(static_cast<int>(n));
    m_accel.bind(extend, m_objects, object_count).arg(m_hits).run(n);
  }

  cl_float4 ambient, background;
  for (int i = 0; i < 4; ++i) {
    ambient.s[i] = m_scene->ambient[i];
    background.s[i] = m_scene->background[i];
  }
  m_context.launch(m_shade)
      .arg(m_work)
      .arg(m_hits)
      .arg(static_cast<int>(n))
      .arg(m_objects)
      .arg(m_materials)
      .arg(m_lights)
      .arg(light_count)
      .arg(ambient)
      .arg(background)
      .arg(opt.max_depth)
      .arg(static_cast<float>(opt.min_weight))
      .arg(m_emit)
      .arg(m_children)
      .arg(m_shadows)
      .arg(m_aov_depth)
      .arg(m_aov_normal)
      .arg(m_aov_primid)
      .arg(m_aov_albedo)
      .run(n);
  accumulate(m_emit, n);

  if (light_count > 0) {
    size_t shadow_count = compact(m_shadows, n * light_count, m_shadow_queue, m_stats->rays_by_kind);
    if (shadow_count > 0) {
      KernelLaunch occlude = m_context.launch(m_occlude);
      occlude.arg(m_shadow_queue).arg(static_cast<int>(shadow_count));
      m_accel.bind(occlude, m_objects, object_count).arg(m_materials).arg(m_shadow_light).run(shadow_count);
      accumulate(m_shadow_light, shadow_count);
    }
  }

  if (depth >= opt.max_depth) return;
  size_t child_count = compact(m_children, 2 * n, m_levels[depth + 1], m_stats->rays_by_kind);
  if (child_count > 0) traceLevel(depth + 1, child_count);
}

size_t Renderer::compact(const Buffer& in, size_t count, Buffer& out, std::array<std::uint64_t, 4>& kinds) {
  const int blocks = static_cast<int>((count + kCompactBlock - 1) / kCompactBlock);
  m_context.launch(m_count).arg(in).arg(static_cast<int>(count)).arg(kCompactBlock).arg(m_counts).run(blocks);
  std::vector<std::int32_t> counts(static_cast<size_t>(blocks) * RAY_KIND_COUNT);
  m_counts.read(counts.data(), counts.size() * sizeof(std::int32_t));
  std::vector<std::int32_t> offsets(blocks);
  std::int64_t total = 0;
  for (int b = 0; b < blocks; ++b) {
    offsets[b] = static_cast<std::int32_t>(total);
    for (int k = 0; k < RAY_KIND_COUNT; ++k) {
      total += counts[b * RAY_KIND_COUNT + k];
      kinds[k] += counts[b * RAY_KIND_COUNT + k];
    }
  }
  if (total == 0) return 0;
  m_offsets.write(offsets.data(), offsets.size() * sizeof(std::int32_t));
  m_context.launch(m_scatter).arg(in).arg(static_cast<int>(count)).arg(kCompactBlock).arg(m_offsets).arg(out).run(blocks);
  return static_cast<size_t>(total);
}

void Renderer::accumulate(const Buffer& contributions, size_t count) {
  m_context.launch(m_accumulate).arg(contributions).arg(static_cast<int>(count)).arg(m_film).run(count);
}

}  // namespace prism
