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

__kernel void spawn_shadows(__global const SurfaceGpu* surfaces, long first_slot, int count, int per_surface,
                            __global const MaterialGpu* materials, __global const LightGpu* lights, int light_count,
                            uint seed, int strata, __global RayGpu* shadows,
                            __global int* tags) {
  int j = get_global_id(0);
  if (j >= count) return;
  long slot = first_slot + j;
  int k = (int)(slot / per_surface);
  int r = (int)(slot % per_surface);
  __global const SurfaceGpu* s = &surfaces[k];
  tags[j] = SLOT_TAG(RAY_KIND_NONE, 0);
  if (s->material < 0) return;
  int l = 0;
  while (l + 1 < light_count && r >= lights[l].samples) { /* point lights have none */
    r -= lights[l].samples;
    ++l;
  }
  __global const LightGpu* light = &lights[l];
  float3 p_out = load3g(s->p), nf = load3g(s->n);
#ifdef PRISM_AREA_LIGHTS /* point lights need no sample (host: kernelFeatures) */
  float2 u = ray_sample_2d(seed, strata, s->strata_id, s->sample, s->dim + DIM_FIRST_LIGHT + l, r, light->samples);
#else
  float2 u = (float2)(0.0f, 0.0f);
#endif
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
