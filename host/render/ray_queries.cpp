#include "render/ray_queries.h"

#include <algorithm>
#include <chrono>

#include "accel/prim_ref.h"
#include "kernels/shared/contribution_gpu.h"
#include "render/gpu_scene.h"

namespace prism {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

RayGpu unitRay(const RayGpu& in) {
  RayGpu r = in;
  r.wr = r.wg = r.wb = 1.0f;  // the contribution then equals the transmittance
  return r;
}

}  // namespace

std::vector<RayGpu> toRayGpu(const std::vector<QueryRay>& rays) {
  std::vector<RayGpu> out(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const QueryRay& q = rays[i];
    RayGpu& r = out[i];
    r = RayGpu{};
    r.ox = q.ox;
    r.oy = q.oy;
    r.oz = q.oz;
    r.tmin = q.tmin;
    r.dx = q.dx;
    r.dy = q.dy;
    r.dz = q.dz;
    r.tmax = q.tmax;
    r.wr = r.wg = r.wb = 1.0f;
    r.pixel = static_cast<int>(i);
    r.kind = RAY_KIND_PRIMARY;
  }
  return out;
}

RayQueryEngine::RayQueryEngine(Context& context, std::vector<ObjectGpu> objects, AccelKind kind,
                               std::vector<MaterialGpu> materials, const AccelBuildOptions& options,
                               PacketUse packets)
    : RayQueryEngine(context, geometryFromRecords(std::move(objects)), kind, std::move(materials), options,
                     packets) {}

RayQueryEngine::RayQueryEngine(Context& context, SceneGeometry geometry, AccelKind kind,
                               std::vector<MaterialGpu> materials, const AccelBuildOptions& options,
                               PacketUse packets)
    : m_context(context), m_geometry(std::move(geometry)) {
  m_accel = buildAccel(kind, m_geometry.objects, options);
  m_geometry_buffers.upload(context, m_geometry);
  m_has_materials = !materials.empty();
  if (m_has_materials) {
    m_material_buffer = Buffer(context, materials.size() * sizeof(MaterialGpu));
    m_material_buffer.writeVector(materials);
  }
  m_buffers.upload(context, *m_accel);
  auto start = Clock::now();
  m_extend = RayKernel(context, *m_accel, RayQuery::ClosestHits, packets);
  m_occlude = RayKernel(context, *m_accel, RayQuery::Transmittance, packets);
  // PoCL finishes compiling a kernel at its first launch with a new work-group
  // size (PERF-NOTES); one tiny launch of each keeps that out of the timings.
  // The packet kernels are launched directly: one ray is too few for the
  // density rule to send it there.
  RayGpu probe{};
  probe.dz = 1.0f;
  probe.tmax = 1.0f;
  const std::vector<RayGpu> probes{probe};
  for (bool packets : {false, true}) {
    if (packets && !tracesPackets()) break;
    runExtend(probes, nullptr, packets);
    runOcclude(probes, m_has_materials, nullptr, packets);
  }
  m_compile_seconds = secondsSince(start);
}

std::vector<HitGpu> RayQueryEngine::intersect(const std::vector<QueryRay>& rays, double* trace_seconds,
                                              RayCoherence coherence) {
  return intersect(toRayGpu(rays), trace_seconds, coherence);
}

std::vector<HitGpu> RayQueryEngine::intersect(const std::vector<RayGpu>& rays, double* trace_seconds,
                                              RayCoherence coherence) {
  return runExtend(rays, trace_seconds, m_extend.packets(coherence, rays.size()));
}

std::vector<HitGpu> RayQueryEngine::runExtend(const std::vector<RayGpu>& rays, double* trace_seconds, bool packets) {
  std::vector<HitGpu> hits(rays.size());
  double seconds = 0;
  const std::size_t batch = std::min(kBatchRays, std::max<std::size_t>(rays.size(), 1));
  m_ray_buffer.reserve(m_context, batch * sizeof(RayGpu));
  m_hit_buffer.reserve(m_context, batch * sizeof(HitGpu));
  for (std::size_t first = 0; first < rays.size(); first += batch) {
    const std::size_t n = std::min(batch, rays.size() - first);
    m_ray_buffer.write(rays.data() + first, n * sizeof(RayGpu));
    auto start = Clock::now();
    KernelLaunch launch = m_extend.launch(packets);
    launch.arg(m_ray_buffer).arg(static_cast<int>(n));
    m_buffers.bind(launch, m_geometry_buffers).arg(m_hit_buffer).run(m_extend.workItems(n, packets));
    m_context.finish();
    seconds += secondsSince(start);
    m_hit_buffer.read(hits.data() + first, n * sizeof(HitGpu));
  }
  if (trace_seconds) *trace_seconds = seconds;
  return hits;
}

std::vector<float> RayQueryEngine::runOcclude(const std::vector<RayGpu>& rays, bool with_materials,
                                              double* trace_seconds, bool packets) {
  std::vector<float> carried(rays.size());
  double seconds = 0;
  const std::size_t batch = std::min(kBatchRays, std::max<std::size_t>(rays.size(), 1));
  m_ray_buffer.reserve(m_context, batch * sizeof(RayGpu));
  m_contribution_buffer.reserve(m_context, batch * sizeof(ContributionGpu));
  const Buffer no_materials;  // NULL in the kernel: every primitive opaque
  std::vector<RayGpu> unit(batch);
  std::vector<ContributionGpu> c(batch);
  for (std::size_t first = 0; first < rays.size(); first += batch) {
    const std::size_t n = std::min(batch, rays.size() - first);
    for (std::size_t i = 0; i < n; ++i) unit[i] = unitRay(rays[first + i]);
    m_ray_buffer.write(unit.data(), n * sizeof(RayGpu));
    auto start = Clock::now();
    KernelLaunch launch = m_occlude.launch(packets);
    launch.arg(m_ray_buffer).arg(static_cast<int>(n));
    m_buffers.bind(launch, m_geometry_buffers)
        .arg(with_materials ? m_material_buffer : no_materials)
        .arg(m_contribution_buffer)
        .run(m_occlude.workItems(n, packets));
    m_context.finish();
    seconds += secondsSince(start);
    m_contribution_buffer.read(c.data(), n * sizeof(ContributionGpu));
    for (std::size_t i = 0; i < n; ++i) carried[first + i] = c[i].r;
  }
  if (trace_seconds) *trace_seconds = seconds;
  return carried;
}

std::vector<std::uint8_t> RayQueryEngine::occluded(const std::vector<QueryRay>& rays, double* trace_seconds,
                                                   RayCoherence coherence, std::uint64_t view_rays) {
  return occluded(toRayGpu(rays), trace_seconds, coherence, view_rays);
}

std::vector<std::uint8_t> RayQueryEngine::occluded(const std::vector<RayGpu>& rays, double* trace_seconds,
                                                   RayCoherence coherence, std::uint64_t view_rays) {
  const bool packets = m_occlude.packets(coherence, view_rays ? view_rays : rays.size());
  std::vector<float> carried = runOcclude(rays, false, trace_seconds, packets);
  std::vector<std::uint8_t> result(carried.size());
  for (std::size_t i = 0; i < carried.size(); ++i) result[i] = carried[i] == 0.0f ? 1 : 0;
  return result;
}

std::vector<float> RayQueryEngine::transmittance(const std::vector<RayGpu>& rays, double* trace_seconds,
                                                 RayCoherence coherence, std::uint64_t view_rays) {
  const bool packets = m_occlude.packets(coherence, view_rays ? view_rays : rays.size());
  return runOcclude(rays, m_has_materials, trace_seconds, packets);
}

TraceResult traceRays(Context& context, SceneGeometry geometry, AccelKind kind, const std::vector<QueryRay>& rays,
                      bool occlusion) {
  RayQueryEngine engine(context, std::move(geometry), kind);
  TraceResult result;
  if (occlusion)
    result.occluded = engine.occluded(rays, &result.trace_seconds);
  else
    result.hits = engine.intersect(rays, &result.trace_seconds);
  result.compile_seconds = engine.compileSeconds();
  result.accel = engine.accel().stats;
  return result;
}

std::vector<HitGpu> traceClosest(Context& context, const Scene& scene, const std::vector<RayGpu>& rays,
                                 AccelKind accel) {
  GpuScene gpu = flattenScene(scene, RenderOptions::fromScene(scene));
  std::vector<MaterialGpu> materials = std::move(gpu.materials);
  RayQueryEngine engine(context, std::move(static_cast<SceneGeometry&>(gpu)), accel, std::move(materials));
  return engine.intersect(rays);
}

std::vector<float> traceTransmittance(Context& context, const Scene& scene, const std::vector<RayGpu>& rays,
                                      AccelKind accel) {
  GpuScene gpu = flattenScene(scene, RenderOptions::fromScene(scene));
  std::vector<MaterialGpu> materials = std::move(gpu.materials);
  RayQueryEngine engine(context, std::move(static_cast<SceneGeometry&>(gpu)), accel, std::move(materials));
  return engine.transmittance(rays);
}

}  // namespace prism
