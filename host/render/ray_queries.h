// Closest-hit and any-hit queries for caller-supplied rays, through the same
// extend / occlude kernels the renderer uses, with any acceleration structure.
//   - traceClosest / traceTransmittance: one-shot queries on a scene (the
//     tests check the kernels' intersection routines through this path);
//   - RayQueryEngine: build once, query many times, with the tracing timed
//     alone (`prism trace`, prismIntersect / prismOccluded, prism-bench).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "accel/accel_buffers.h"
#include "accel/accel_structure.h"
#include "device/context.h"
#include "kernels/shared/hit_gpu.h"
#include "kernels/shared/material_gpu.h"
#include "kernels/shared/object_gpu.h"
#include "kernels/shared/ray_gpu.h"
#include "render/ray_kernel.h"
#include "scene/scene.h"

namespace prism {

// Closest hit of each ray (only origin, direction, tmin and tmax are read).
// `none` by default: the brute-force reference.
std::vector<HitGpu> traceClosest(Context& context, const Scene& scene, const std::vector<RayGpu>& rays,
                                 AccelKind accel = AccelKind::None);

// Fraction of light each ray carries from tmin to tmax (1 unblocked, 0 blocked by
// an opaque object, the product of k_trans over semitransparent ones).
std::vector<float> traceTransmittance(Context& context, const Scene& scene, const std::vector<RayGpu>& rays,
                                      AccelKind accel = AccelKind::None);

// A ray as `prism trace` reads it: 32 bytes, origin + tmin, direction + tmax.
struct QueryRay {
  float ox, oy, oz, tmin;
  float dx, dy, dz, tmax;
};
static_assert(sizeof(QueryRay) == 32, "QueryRay is the 32-byte record of prism trace");

// A structure built over a fixed set of primitives, uploaded, and its two
// kernels compiled and warmed up, ready for any number of ray batches (one
// query at a time: the batch buffers are the engine's). The
// hit record is HitGpu, the 16-byte record `prism trace` writes: t (+inf on a
// miss), prim (-1 on a miss), u and v (barycentrics of vertices 1 and 2).
class RayQueryEngine {
 public:
  // `materials` may be empty: transmittance() then treats every primitive as
  // opaque (and occluded() always does).
  RayQueryEngine(Context& context, SceneGeometry geometry, AccelKind kind, std::vector<MaterialGpu> materials = {},
                 const AccelBuildOptions& options = {}, PacketUse packets = PacketUse::WherePays);
  // Over records alone (geometryFromRecords): every triangle a record.
  RayQueryEngine(Context& context, std::vector<ObjectGpu> objects, AccelKind kind,
                 std::vector<MaterialGpu> materials = {}, const AccelBuildOptions& options = {},
                 PacketUse packets = PacketUse::WherePays);

  // Closest hits. `trace_seconds` (optional) receives the time of the kernel
  // runs alone: no upload, read-back, build or compilation. Coherent rays go
  // in packets where that pays (render/ray_kernel.h); the hits are the same.
  std::vector<HitGpu> intersect(const std::vector<QueryRay>& rays, double* trace_seconds = nullptr,
                                RayCoherence coherence = RayCoherence::Scattered);
  std::vector<HitGpu> intersect(const std::vector<RayGpu>& rays, double* trace_seconds = nullptr,
                                RayCoherence coherence = RayCoherence::Scattered);
  // Whether coherent rays go in packets here.
  bool tracesPackets() const { return m_extend.hasPackets() && m_occlude.hasPackets(); }
  // 1 where something lies strictly between tmin and tmax along the ray.
  // `view_rays`: for feelers from the hits of a view (a frame's samples, a
  // query's camera rays), that view's rays, which the density rule of packets
  // counts as the renderer does (render/ray_kernel.h); 0: these rays.
  std::vector<std::uint8_t> occluded(const std::vector<QueryRay>& rays, double* trace_seconds = nullptr,
                                     RayCoherence coherence = RayCoherence::Scattered, std::uint64_t view_rays = 0);
  std::vector<std::uint8_t> occluded(const std::vector<RayGpu>& rays, double* trace_seconds = nullptr,
                                     RayCoherence coherence = RayCoherence::Scattered, std::uint64_t view_rays = 0);
  // Light carried from tmin to tmax, as the renderer's shadow feelers see it.
  std::vector<float> transmittance(const std::vector<RayGpu>& rays, double* trace_seconds = nullptr,
                                   RayCoherence coherence = RayCoherence::Scattered, std::uint64_t view_rays = 0);

  const DeviceAccel& accel() const { return *m_accel; }
  const SceneGeometry& geometry() const { return m_geometry; }
  // Device bytes of the geometry and of the structure together.
  std::size_t deviceBytes() const { return deviceGeometryBytes(m_geometry) + m_accel->stats.bytes; }
  // Seconds spent compiling (or loading from the cache) the two kernels.
  double compileSeconds() const { return m_compile_seconds; }

  // Rays per kernel launch; bigger batches are split.
  static constexpr std::size_t kBatchRays = std::size_t(1) << 22;

 private:
  // The queries through the chosen kernel (`packets`: the `_packets` twin).
  std::vector<HitGpu> runExtend(const std::vector<RayGpu>& rays, double* trace_seconds, bool packets);
  std::vector<float> runOcclude(const std::vector<RayGpu>& rays, bool with_materials, double* trace_seconds,
                                bool packets);

  Context& m_context;
  SceneGeometry m_geometry;
  std::unique_ptr<DeviceAccel> m_accel;
  GeometryBuffers m_geometry_buffers;
  Buffer m_material_buffer;
  bool m_has_materials = false;
  AccelBuffers m_buffers;
  RayKernel m_extend, m_occlude;
  double m_compile_seconds = 0;
  // A batch's rays and answers, kept from query to query (as large as the
  // largest batch asked, until the engine goes): a buffer made for each query
  // is fresh memory for the kernel to fault in page by page (about 1.5 us a
  // page on a CPU device), which the trace time counted.
  Buffer m_ray_buffer, m_hit_buffer, m_contribution_buffer;
};

// The 80-byte queue record of a query ray (weight 1, primary, pixel = index).
std::vector<RayGpu> toRayGpu(const std::vector<QueryRay>& rays);

// One batch of rays through a structure built for it: what `prism trace` and
// prismIntersect / prismOccluded need, in one call.
struct TraceResult {
  std::vector<HitGpu> hits;            // closest hits (when occlusion was not asked)
  std::vector<std::uint8_t> occluded;  // 1 = something in (tmin, tmax) (when it was)
  double trace_seconds = 0;            // the kernel runs alone
  double compile_seconds = 0;          // kernels built or loaded, and warmed up
  AccelStats accel;                    // the structure's build, build_seconds included
};
TraceResult traceRays(Context& context, SceneGeometry geometry, AccelKind kind, const std::vector<QueryRay>& rays,
                      bool occlusion);

}  // namespace prism
