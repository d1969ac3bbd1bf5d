/* The local illumination models: diffuse (Lambert) plus the specular highlight of
 * Phong (R·V)^n, Blinn (N·H)^n or Cook-Torrance (shading/microfacet.h), for one
 * light. */
#ifndef PRISM_SHADING_LOCAL_H
#define PRISM_SHADING_LOCAL_H

#include "common/math.h"
#include "shading/microfacet.h"
#include "shading/optics.h"
#include "shared/material_gpu.h"

/* n: unit normal facing the viewer, l: unit direction to the light, v: unit
 * direction to the viewer; n·l > 0 is the caller's precondition. */
inline float3 local_light_term(__global const MaterialGpu* m, float3 kd, float3 n, float3 l, float3 v) {
  float n_dot_l = sb_dot(n, l);
  if (m->model == SHADING_COOK_TORRANCE)
    return kd * n_dot_l + load3g(m->specular) * cook_torrance(n, l, v, m->roughness, m->distribution, m->ior);
  float3 ks = load3g(m->specular);
  /* Without a highlight, the power (most of this function's time) is not
   * needed: ks * spec is then a zero of ks's sign, as ks * 0 is, spec being
   * finite and not negative (spec_base is a cosine of unit vectors, at most 1
   * and a few ulps, and the scene loader keeps shininess within 0..1e6). */
  if (ks.x == 0.0f && ks.y == 0.0f && ks.z == 0.0f) return kd * n_dot_l + ks * 0.0f;
  float spec_base;
  if (m->model == SHADING_BLINN) {
    spec_base = sb_dot(n, sb_normalize(l + v));
  } else {
    spec_base = sb_dot(reflect_dir(-l, n), v);
  }
  float spec = spec_base > 0.0f ? pow_positive(spec_base, m->shininess) : 0.0f;
  return kd * n_dot_l + ks * spec;
}

#endif
