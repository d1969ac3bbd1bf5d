/* A material's two halves as the wave loop uses them: it evaluates its local
 * model for light arriving from a direction (shading/local.h), and it samples
 * the directions of its reflected and refracted rays. A glossy or translucent
 * material spreads them over a Phong lobe cos^n around the ideal direction
 * (Cook, Porter and Carpenter 1984); the ray's weight stays k_refl or k_trans,
 * because the lobe is sampled in proportion to itself. */
#ifndef PRISM_SHADING_MATERIAL_H
#define PRISM_SHADING_MATERIAL_H

#include "common/math.h"
#include "shading/frame.h"
#include "shading/local.h"
#include "shading/optics.h"

/* A unit direction from the density (n + 1) / (2 pi) cos^n(theta) around unit
 * `axis` (theta measured from it), for u in [0, 1)^2. */
inline float3 sample_phong_lobe(float3 axis, float exponent, float2 u) {
  float cos_t = pow_positive(1.0f - u.x, 1.0f / (exponent + 1.0f)) /* 1 - u.x > 0 */;
  float sin_t = sqrt(fmax(0.0f, 1.0f - cos_t * cos_t));
  float phi = 2.0f * PRISM_PI * u.y;
  float3 t, b;
  orthonormal_basis(axis, &t, &b);
  return sb_normalize(sin_t * sb_cos(phi) * t + sin_t * sb_sin(phi) * b + cos_t * axis);
}

/* A sampled direction that left the side of the surface it belongs to is
 * mirrored back across the tangent plane: its energy stays on its own side
 * instead of being lost or leaking through. side = +1: the viewer's side of
 * unit normal nf; -1: the other. */
inline float3 fold_to_side(float3 d, float3 nf, float side) {
  float dn = sb_dot(d, nf) * side;
  return dn > 0.0f ? d : d - 2.0f * sb_dot(d, nf) * nf;
}

/* The reflected ray's direction for incident i_dir at unit normal nf (facing
 * the viewer). */
inline float3 material_reflect_dir(__global const MaterialGpu* m, float3 i_dir, float3 nf, float2 u) {
  float3 mirror = reflect_dir(i_dir, nf);
#ifdef PRISM_LOBES /* built for scenes with a glossy or translucent material (host: kernelFeatures) */
  if (m->gloss > 0.0f) return fold_to_side(sample_phong_lobe(mirror, m->gloss, u), nf, 1.0f);
#endif
  return mirror;
}

/* The refracted ray's direction around Snell's direction t_dir. */
inline float3 material_transmit_dir(__global const MaterialGpu* m, float3 t_dir, float3 nf, float2 u) {
#ifdef PRISM_LOBES
  if (m->translucency > 0.0f) return fold_to_side(sample_phong_lobe(t_dir, m->translucency, u), nf, -1.0f);
#endif
  return t_dir;
}

#endif
