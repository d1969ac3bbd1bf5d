#include "render/ray_queries.h"

#include "kernels/shared/contribution_gpu.h"
#include "render/gpu_scene.h"

namespace prism {
namespace {

struct UploadedScene {
  Buffer objects, materials;
  int object_count;
  UploadedScene(Context& context, const Scene& scene) {
    RenderOptions options = RenderOptions::fromScene(scene);
    GpuScene gpu = flattenScene(scene, options);
    objects = Buffer(context, gpu.objects.size() * sizeof(ObjectGpu));
    objects.writeVector(gpu.objects);
    materials = Buffer(context, gpu.materials.size() * sizeof(MaterialGpu));
    materials.writeVector(gpu.materials);
    object_count = static_cast<int>(gpu.objects.size());
  }
};

}  // namespace

std::vector<HitGpu> traceClosest(Context& context, const Scene& scene, const std::vector<RayGpu>& rays) {
  UploadedScene s(context, scene);
  Buffer ray_buffer(context, rays.size() * sizeof(RayGpu));
  ray_buffer.writeVector(rays);
  Buffer hits(context, rays.size() * sizeof(HitGpu));
  int count = static_cast<int>(rays.size());
  context.launch(context.kernel("extend.cl", "extend")).arg(ray_buffer).arg(count).arg(s.objects).arg(s.object_count).arg(hits).run(rays.size());
  return hits.readVector<HitGpu>(rays.size());
}

std::vector<float> traceTransmittance(Context& context, const Scene& scene, const std::vector<RayGpu>& rays) {
  UploadedScene s(context, scene);
  std::vector<RayGpu> unit = rays;
  for (RayGpu& r : unit) r.wr = r.wg = r.wb = 1.0f;  // the contribution then equals the transmittance
  Buffer ray_buffer(context, unit.size() * sizeof(RayGpu));
  ray_buffer.writeVector(unit);
  Buffer out(context, unit.size() * sizeof(ContributionGpu));
  int count = static_cast<int>(unit.size());
  context.launch(context.kernel("occlude.cl", "occlude"))
      .arg(ray_buffer).arg(count).arg(s.objects).arg(s.object_count).arg(s.materials).arg(out)
      .run(unit.size());
  std::vector<ContributionGpu> c = out.readVector<ContributionGpu>(unit.size());
  std::vector<float> result(c.size());
  for (size_t i = 0; i < c.size(); ++i) result[i] = c[i].r;
  return result;
}

}  // namespace prism
