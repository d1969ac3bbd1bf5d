/* spawn_shadows: the area lights' shadow feelers of a run of shaded points
 * (point lights' feelers are traced by shade). Every point has `per_surface`
 * slots, area light after area light, `samples` of light l each; slot j of
 * point k is slot first_slot + j of the launch. A feeler goes to a point the light samples
 * (shading/light.h, its 2-D sample from the path's dimension for that light)
 * and carries the light it would bring: the local model's term for that
 * direction times what the light sends. Empty slots (no surface, a light behind
 * it) are only tagged, and compaction removes them before occlude. */
#include "common/math.h"
#include "sampling/dimensions.h"
#include "shading/light.h"
#include "shading/material.h"
#include "shading/ray_io.h"
#include "shared/surface_gpu.h"

#define SPAWN_LANES 8 /* slots a work-item takes (host: kSpawnLanes) */

/* The light of slot r of a point's slots (area light after area light), and
 * the slot's place among that light's samples. */
inline int spawn_light(__global const LightGpu* lights, int light_count, int* r) {
  int l = 0;
  while (l + 1 < light_count && *r >= lights[l].samples) { /* point lights have none */
    *r -= lights[l].samples;
    ++l;
  }
  return l;
}

/* Slot j's feeler from point s toward `light`, through its sample u of the light. */
inline void spawn_feeler(__global const SurfaceGpu* s, __global const MaterialGpu* materials,
                         __global const LightGpu* light, float2 u, int j, __global RayGpu* shadows,
                         __global int* tags) {
  float3 p_out = load3g(s->p), nf = load3g(s->n);
  float3 ldir, scale;
  float dist;
  if (!light_sample(light, p_out, u, &ldir, &dist, &scale)) return;
  /* Each of a hit's feelers to one light estimates the whole light. */
  if (light->samples > 1) scale = scale / (float)light->samples;
  if (sb_dot(nf, ldir) <= 0.0f) return; /* the light is behind the surface */
  __global const MaterialGpu* m = &materials[s->material];
  float3 brought = load3g(s->weight) * scale * local_light_term(m, load3g(s->kd), nf, ldir, load3g(s->v));
  /* An area light's sample sits on its shape: stop just short of it, so a
   * surface the light lies on does not shadow it. */
  float tmax = light->type == LIGHT_POINT ? dist : dist * (1.0f - 1e-4f);
  RayGpu ray = ray_make(p_out, ldir, 0.0f, tmax, brought, s->pixel, s->depth, RAY_KIND_SHADOW, s->sample);
  ray.time = s->p[3];
  ray.strata_id = s->strata_id;
  shadows[j] = ray;
  tags[j] = SLOT_TAG(RAY_KIND_SHADOW, 0);
}

/* A work-item takes SPAWN_LANES slots and draws their lights' samples in
 * vector lanes (ray_sample_2d8): one sample at a time, the sampler's chains of
 * dependent multiplies were half of this kernel's time, since PoCL runs a
 * work-group's items one after another without vectorising across them. */
__kernel void spawn_shadows(__global const SurfaceGpu* surfaces, long first_slot, int count, int per_surface,
                            __global const MaterialGpu* materials, __global const LightGpu* lights, int light_count,
                            uint seed, int strata, __global RayGpu* shadows,
                            __global int* tags) {
  int first = get_global_id(0) * SPAWN_LANES;
  if (first >= count) return;
  int lanes = min(SPAWN_LANES, count - first);
  /* Lanes past the launch's slots or at an empty point draw a sample no feeler uses. */
  int surface[SPAWN_LANES], light_of[SPAWN_LANES], strata_id[SPAWN_LANES], sample[SPAWN_LANES], dim[SPAWN_LANES],
      sub[SPAWN_LANES], subs[SPAWN_LANES];
  for (int i = 0; i < SPAWN_LANES; ++i) {
    surface[i] = -1;
    light_of[i] = strata_id[i] = sample[i] = dim[i] = sub[i] = 0;
    subs[i] = 1;
    if (i >= lanes) continue;
    long slot = first_slot + first + i;
    int k = (int)(slot / per_surface);
    int r = (int)(slot % per_surface);
    tags[first + i] = SLOT_TAG(RAY_KIND_NONE, 0);
    if (surfaces[k].material < 0) continue;
    int l = spawn_light(lights, light_count, &r);
    surface[i] = k;
    light_of[i] = l;
    strata_id[i] = surfaces[k].strata_id;
    sample[i] = surfaces[k].sample;
    dim[i] = surfaces[k].dim + DIM_FIRST_LIGHT + l;
    sub[i] = r;
    subs[i] = lights[l].samples;
  }
#ifdef PRISM_AREA_LIGHTS /* point lights need no sample (host: kernelFeatures) */
  float8 ux8, uy8;
  ray_sample_2d8(seed, strata, vload8(0, strata_id), vload8(0, sample), vload8(0, dim), vload8(0, sub),
                 vload8(0, subs), &ux8, &uy8);
  float ux[SPAWN_LANES], uy[SPAWN_LANES];
  vstore8(ux8, 0, ux);
  vstore8(uy8, 0, uy);
#endif
  for (int i = 0; i < lanes; ++i) {
    if (surface[i] < 0) continue;
#ifdef PRISM_AREA_LIGHTS
    float2 u = (float2)(ux[i], uy[i]);
#else
    float2 u = (float2)(0.0f, 0.0f);
#endif
    spawn_feeler(&surfaces[surface[i]], materials, &lights[light_of[i]], u, first + i, shadows, tags);
  }
}
