/* shade: Whitted's local model at each ray's hit, and the rays it spawns.
 *   - emit[k]: the ray's ambient term (or the background on a miss), weighted;
 *   - shadows[k * light_count + l]: a shadow feeler towards light l carrying the
 *     diffuse + specular light it would bring, or an empty slot;
 *   - children[2k], children[2k+1]: the reflected and the refracted ray, each
 *     with weight = parent weight x coefficient, or empty slots when the branch
 *     ends (max depth reached, coefficient zero, weight under min_weight).
 * Primary rays with an AOV pixel (ray.aov_pixel >= 0, one sample per pixel
 * chosen by the sampler) also write that pixel's AOVs. */
#include "geometry/object.h"
#include "shading/local.h"
#include "shading/optics.h"
#include "shading/ray_io.h"
#include "shading/texture.h"
#include "shared/contribution_gpu.h"
#include "shared/light_gpu.h"

inline void write_aovs(int pixel, float depth, float3 n, int prim, float3 albedo, __global float* aov_depth,
                       __global float* aov_normal, __global int* aov_primid, __global float* aov_albedo) {
  aov_depth[pixel] = depth;
  aov_primid[pixel] = prim;
  vstore3(n, pixel, aov_normal);
  vstore3(albedo, pixel, aov_albedo);
}

inline ContributionGpu contribution(float3 c, float a, int pixel) {
  ContributionGpu out;
  out.r = c.x;
  out.g = c.y;
  out.b = c.z;
  out.a = a;
  out.pixel = pixel;
  out.pad[0] = out.pad[1] = out.pad[2] = 0;
  return out;
}

__kernel void shade(__global const RayGpu* rays, __global const HitGpu* hits, int count,
                    __global const ObjectGpu* objects, __global const MaterialGpu* materials,
                    __global const LightGpu* lights, int light_count, float4 ambient, float4 background,
                    int max_depth, float min_weight, __global ContributionGpu* emit, __global RayGpu* children,
                    __global RayGpu* shadows, __global float* aov_depth, __global float* aov_normal,
                    __global int* aov_primid, __global float* aov_albedo) {
  int k = get_global_id(0);
  if (k >= count) return;
  RayGpu ray = rays[k];
  HitGpu hit = hits[k];
  float3 weight = ray_weight(ray);
  bool primary = ray.kind == RAY_KIND_PRIMARY;
  bool writes_aovs = primary && ray.aov_pixel >= 0;

  for (int l = 0; l < light_count; ++l) shadows[k * light_count + l] = ray_empty();
  children[2 * k] = ray_empty();
  children[2 * k + 1] = ray_empty();

  if (hit.prim < 0) {
    emit[k] = contribution(weight * background.xyz, 0.0f, ray.pixel);
    if (writes_aovs)
      write_aovs(ray.aov_pixel, PRISM_INF, (float3)(0.0f), -1, (float3)(0.0f), aov_depth, aov_normal, aov_primid,
                 aov_albedo);
    return;
  }

  __global const ObjectGpu* object = &objects[hit.prim];
  __global const MaterialGpu* m = &materials[object->material];
  float3 o = ray_origin(ray), d = ray_dir(ray);
  float3 n;
  float2 uv;
  object_surface(object, o, d, hit, &n, &uv);
  float3 p = o + hit.t * d;
  float3 i_dir = normalize(d);
  bool inside = dot(n, i_dir) > 0.0f;
  float3 nf = inside ? -n : n; /* normal on the side the ray came from */
  float3 v = -i_dir;
  float3 tex = texture_color(m, uv);
  float3 kd = load3g(m->diffuse) * tex;
  float eps = surface_epsilon(p);
  float3 p_out = p + eps * nf; /* just off the surface, on the viewer's side */

  emit[k] = contribution(weight * load3g(m->ambient) * tex * ambient.xyz, primary ? 1.0f : 0.0f, ray.pixel);
  if (writes_aovs) write_aovs(ray.aov_pixel, hit.t, nf, hit.prim, kd, aov_depth, aov_normal, aov_primid, aov_albedo);

  for (int l = 0; l < light_count; ++l) {
    float3 to_light = load3g(lights[l].position) - p_out;
    float dist = length(to_light);
    float3 ldir = to_light / dist;
    if (dot(nf, ldir) <= 0.0f) continue; /* the light is behind the surface */
    float3 brought = weight * load3g(lights[l].color) * local_light_term(m, kd, nf, ldir, v);
    shadows[k * light_count + l] =
        ray_make(p_out, ldir, 0.0f, dist, brought, ray.pixel, ray.depth, RAY_KIND_SHADOW, ray.sample);
  }

  if (ray.depth >= max_depth) return;
  float k_reflect = m->reflect;
  if (m->transmit > 0.0f) {
    float eta = inside ? m->ior : 1.0f / m->ior;
    float3 t_dir;
    if (refract_dir(i_dir, nf, eta, &t_dir)) {
      float3 w = weight * m->transmit;
      if (max3(w) >= min_weight)
        children[2 * k + 1] = ray_make(p - eps * nf, t_dir, 0.0f, PRISM_INF, w, ray.pixel, ray.depth + 1,
                                       RAY_KIND_REFRACTED, ray.sample);
    } else {
      k_reflect += m->transmit; /* total internal reflection: what would pass is reflected */
    }
  }
  if (k_reflect > 0.0f) {
    float3 w = weight * k_reflect;
    if (max3(w) >= min_weight)
      children[2 * k] = ray_make(p_out, reflect_dir(i_dir, nf), 0.0f, PRISM_INF, w, ray.pixel, ray.depth + 1,
                                 RAY_KIND_REFLECTED, ray.sample);
  }
}
