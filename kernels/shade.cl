/* shade: the local model at each ray's hit, and what the hit spawns.
 *   - emit[k]: the ray's ambient term plus the light its point lights bring
 *     through their shadow feelers (Whitted's feelers: one per point light in
 *     front of the surface, traced here, attenuated by semitransparent objects),
 *     the background on a miss, or the radiance of an area light it meets before
 *     any object; weighted;
 *   - surfaces[k] (scenes with area lights): the shaded point, from which
 *     spawn_shadows sends the area lights' sampled feelers, or no surface;
 *   - children[2k], children[2k+1]: the reflected and the refracted ray, their
 *     directions sampled from the material's lobes (shading/material.h), each
 *     with weight = parent weight x coefficient, or empty slots when the branch
 *     ends (max depth reached, coefficient zero, weight under min_weight); only
 *     filled slots are written;
 *   - child_tags[2k], child_tags[2k+1]: the slots' tags (shared/ray_gpu.h);
 *     the first also counts the point-light feelers traced, for the statistics.
 * Point-light feelers are traced in place rather than queued: each is one
 * deterministic ray per light, and a queue would move 80 bytes per feeler
 * through four more kernels (on PoCL that was a third of a Whitted render).
 * Primary rays with an AOV pixel (ray.aov_pixel >= 0, one sample per pixel
 * chosen by the sampler) also write that pixel's AOVs. The program is built
 * with the acceleration structure's options (kernels/accel/accel.h). */
#include "common/math.h"
#include "accel/accel.h"
#include "sampling/dimensions.h"
#include "shading/light.h"
#include "shading/light_buffer.h"
#include "shading/material.h"
#include "shading/ray_io.h"
#include "shading/texture.h"
#include "shared/contribution_gpu.h"
#include "shared/surface_gpu.h"

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

inline void put4(__global float* dst, float3 v, float w) { vstore4((float4)(v, w), 0, dst); }

/* The slots of ray k's children: each ray written only where it exists. */
inline void write_children(__global RayGpu* children, __global int* tags, int k, const RayGpu* reflected,
                           const RayGpu* refracted, int feelers) {
  tags[2 * k] = SLOT_TAG(reflected->kind, feelers);
  tags[2 * k + 1] = SLOT_TAG(refracted->kind, 0);
  if (reflected->kind >= 0) children[2 * k] = *reflected;
  if (refracted->kind >= 0) children[2 * k + 1] = *refracted;
}

inline void write_no_children(__global int* tags, int k) {
  tags[2 * k] = SLOT_TAG(RAY_KIND_NONE, 0);
  tags[2 * k + 1] = SLOT_TAG(RAY_KIND_NONE, 0);
}

/* The 2-D sample of one lobe of the ray's hit; nothing to draw without lobes. */
inline float2 lobe_sample(uint seed, int strata, RayGpu ray, int lobe) {
#ifdef PRISM_LOBES
  return ray_sample_2d(seed, strata, ray.strata_id, ray.sample, ray.dim + lobe, 0, 1);
#else
  return (float2)(0.0f, 0.0f);
#endif
}

__kernel void shade(__global const RayGpu* rays, __global const HitGpu* hits, int count, ACCEL_KERNEL_PARAMS,
                    __global const MaterialGpu* materials, __global const float4* texels,
                    __global const LightGpu* lights, int light_count, LIGHT_BUFFER_PARAMS, float4 ambient,
                    float4 background, int max_depth, float min_weight, uint seed, int strata,
                    __global ContributionGpu* emit, __global RayGpu* children, __global int* child_tags,
                    __global SurfaceGpu* surfaces,
                    __global float* aov_depth, __global float* aov_normal, __global int* aov_primid,
                    __global float* aov_albedo) {
  ACCEL_GEOMETRY;
  int k = get_global_id(0);
  if (k >= count) return;
  RayGpu ray = rays[k];
  HitGpu hit = hits[k];
  float3 weight = ray_weight(ray);
  bool primary = ray.kind == RAY_KIND_PRIMARY;
  bool writes_aovs = primary && ray.aov_pixel >= 0;
  float3 o = ray_origin(ray), d = ray_dir(ray);

  /* An area light in front of the hit (or of nothing) is what the ray sees. */
#ifdef PRISM_AREA_LIGHTS /* built for scenes with area lights (host: kernelFeatures) */
  surfaces[k].material = -1;
  {
    float t_light = hit.prim < 0 ? PRISM_INF : hit.t;
    int seen = -1;
    for (int l = 0; l < light_count; ++l) {
      float t = light_hit(&lights[l], o, d, t_light);
      if (t < t_light) {
        t_light = t;
        seen = l;
      }
    }
    if (seen >= 0) {
      write_no_children(child_tags, k);
      emit[k] = contribution(weight * load3g(lights[seen].color), primary ? 1.0f : 0.0f, ray.pixel);
      if (writes_aovs)
        write_aovs(ray.aov_pixel, t_light, (float3)(0.0f), -1, (float3)(0.0f), aov_depth, aov_normal, aov_primid,
                   aov_albedo);
      return;
    }
  }
#endif

  if (hit.prim < 0) {
    write_no_children(child_tags, k);
    emit[k] = contribution(weight * background.xyz, 0.0f, ray.pixel);
    if (writes_aovs)
      write_aovs(ray.aov_pixel, PRISM_INF, (float3)(0.0f), -1, (float3)(0.0f), aov_depth, aov_normal, aov_primid,
                 aov_albedo);
    return;
  }

  __global const MeshGpu* mesh = prim_mesh_or_null(geom, hit.prim); /* one search for both questions */
  const int material = prim_material_in(geom, hit.prim, mesh);
  __global const MaterialGpu* m = &materials[material];
  float3 n;
  float2 uv = (float2)(0.0f, 0.0f);
  prim_surface(geom, hit.prim, mesh, ray.time, hit, m->texture != TEXTURE_NONE, o, d, &n, &uv);
  float3 p = o + hit.t * d;
  float3 i_dir = sb_normalize(d);
  bool inside = sb_dot(n, i_dir) > 0.0f;
  float3 nf = inside ? -n : n; /* normal on the side the ray came from */
  float3 v = -i_dir;
  float3 tex = texture_color(m, texels, uv);
  float3 kd = load3g(m->diffuse) * tex;
  float eps = surface_epsilon(p);
  float3 p_out = p + eps * nf; /* just off the surface, on the viewer's side */

  if (writes_aovs) write_aovs(ray.aov_pixel, hit.t, nf, hit.prim, kd, aov_depth, aov_normal, aov_primid, aov_albedo);

  float3 light = load3g(m->ambient) * tex * ambient.xyz;
  int feelers = 0;
  for (int l = 0; l < light_count; ++l) {
    __global const LightGpu* source = &lights[l];
    if (source->type != LIGHT_POINT) continue; /* sampled by spawn_shadows */
    float3 ldir, scale;
    float dist;
    light_sample(source, p_out, (float2)(0.0f, 0.0f), &ldir, &dist, &scale);
    if (sb_dot(nf, ldir) <= 0.0f) continue; /* the light is behind the surface */
    ++feelers;
    float3 brought = scale * local_light_term(m, kd, nf, ldir, v);
    light += brought * point_light_transmittance(ACCEL_ARGS, LIGHT_BUFFER_ARGS, materials, l, load3g(source->position),
                                                 p_out, ldir, ray.time, dist);
  }
  emit[k] = contribution(weight * light, primary ? 1.0f : 0.0f, ray.pixel);

#ifdef PRISM_AREA_LIGHTS
  __global SurfaceGpu* s = &surfaces[k];
  put4(s->p, p_out, ray.time);
  put4(s->n, nf, 0.0f);
  put4(s->v, v, 0.0f);
  put4(s->kd, kd, 0.0f);
  put4(s->weight, weight, 0.0f);
  s->material = material;
  s->pixel = ray.pixel;
  s->sample = ray.sample;
  s->strata_id = ray.strata_id;
  s->dim = ray.dim;
  s->depth = ray.depth;
#endif

  RayGpu reflected, refracted;
  reflected.kind = refracted.kind = RAY_KIND_NONE;
  if (ray.depth < max_depth) {
    int child_dim = dim_children(ray.dim, light_count);
    float k_reflect = m->reflect;
    if (m->transmit > 0.0f) {
      float eta = inside ? m->ior : 1.0f / m->ior;
      float3 t_dir;
      if (refract_dir(i_dir, nf, eta, &t_dir)) {
        float3 w = weight * m->transmit;
        if (max3(w) >= min_weight) {
          float2 u = lobe_sample(seed, strata, ray, DIM_TRANSMIT_LOBE);
          refracted = ray_child(ray, p - eps * nf, material_transmit_dir(m, t_dir, nf, u), PRISM_INF, w,
                                ray.depth + 1, RAY_KIND_REFRACTED, child_dim);
        }
      } else {
        k_reflect += m->transmit; /* total internal reflection: what would pass is reflected */
      }
    }
    if (k_reflect > 0.0f) {
      float3 w = weight * k_reflect;
      if (max3(w) >= min_weight) {
        float2 u = lobe_sample(seed, strata, ray, DIM_REFLECT_LOBE);
        reflected = ray_child(ray, p_out, material_reflect_dir(m, i_dir, nf, u), PRISM_INF, w, ray.depth + 1,
                              RAY_KIND_REFLECTED, child_dim);
      }
    }
  }
  write_children(children, child_tags, k, &reflected, &refracted, feelers);
}
