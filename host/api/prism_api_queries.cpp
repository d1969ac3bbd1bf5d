// C API: closest-hit and any-hit ray queries (prismIntersect, prismOccluded).
#include <cstring>

#include "api/api_boundary.h"
#include "api/api_enums.h"
#include "api/api_handles.h"
#include "scene/animation.h"
#include "render/gpu_scene.h"

using namespace prism;

static_assert(sizeof(PrismRay) == sizeof(QueryRay), "PrismRay and QueryRay are the same 32-byte record");
static_assert(sizeof(PrismHit) == sizeof(HitGpu), "PrismHit and HitGpu are the same 16-byte record");

namespace {

RayQueryEngine& engineFor(PrismContext context, PrismScene scene, int accel) {
  const char* name = accelNameOf(accel);
  if (!name) throw std::invalid_argument("unknown accel value " + std::to_string(accel));
  AccelKind kind = parseAccelKind(name);
  if (!context->queries || context->queries_revision != scene->revision || context->queries_accel != kind) {
    context->queries.reset();
    // An animation answers as its frame 0, as prismRender renders it.
    const Scene& whole = scene->scene;
    GpuScene gpu =
        withFirstFrame(whole, [&](const Scene& frame) { return flattenScene(frame, RenderOptions::fromScene(whole)); });
    std::vector<MaterialGpu> materials = std::move(gpu.materials);
    context->queries = std::make_unique<RayQueryEngine>(
        *context->context, std::move(static_cast<SceneGeometry&>(gpu)), kind, std::move(materials));
    context->queries_revision = scene->revision;
    context->queries_accel = kind;
  }
  return *context->queries;
}

std::vector<QueryRay> copyRays(const PrismRay* rays, size_t count) {
  std::vector<QueryRay> out(count);
  std::memcpy(out.data(), rays, count * sizeof(QueryRay));
  return out;
}

}  // namespace

extern "C" {

PRISM_API PrismStatus prismIntersect(PrismContext context, PrismScene scene, PrismAccel accel, const PrismRay* rays,
                                     PrismHit* hits, size_t count, double* trace_seconds) {
  if (!context || !scene || (count && (!rays || !hits)))
    return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismIntersect: NULL context, scene, rays or hits");
  return guarded(__func__, [&] {
    double seconds = 0;
    if (count) {
      std::vector<HitGpu> result = engineFor(context, scene, enumValue(accel)).intersect(copyRays(rays, count), &seconds);
      std::memcpy(hits, result.data(), count * sizeof(PrismHit));
    }
    if (trace_seconds) *trace_seconds = seconds;
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismOccluded(PrismContext context, PrismScene scene, PrismAccel accel, const PrismRay* rays,
                                    uint8_t* occluded, size_t count, double* trace_seconds) {
  if (!context || !scene || (count && (!rays || !occluded)))
    return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismOccluded: NULL context, scene, rays or output");
  return guarded(__func__, [&] {
    double seconds = 0;
    if (count) {
      std::vector<std::uint8_t> result = engineFor(context, scene, enumValue(accel)).occluded(copyRays(rays, count), &seconds);
      std::memcpy(occluded, result.data(), count);
    }
    if (trace_seconds) *trace_seconds = seconds;
    return PRISM_OK;
  });
}

}  // extern "C"
