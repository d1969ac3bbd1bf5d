/* Cook and Torrance's microfacet highlight (1982): a surface of tiny mirrors
 * whose normals h are spread by a distribution D, each reflecting by the
 * Fresnel factor F, shadowed and masked by the geometric term G. The BRDF is
 *   f = F(v.h) D(h) G / (4 (n.l) (n.v))
 * with D normalised so that the integral of D(h) (n.h) over the hemisphere is 1
 * (Walter et al. 2007 fixed the 1982 paper's pi in place of 4). Beckmann's D
 * goes with Cook and Torrance's own V-cavity G; GGX (Trowbridge-Reitz) with
 * Smith's G for it. tests/kernels/microfacet_test.cpp checks D's normalisation,
 * F against the Fresnel equations, and the directional albedo against a
 * double-precision quadrature. */
#ifndef PRISM_SHADING_MICROFACET_H
#define PRISM_SHADING_MICROFACET_H

#include "common/math.h"
#include "shared/material_gpu.h"

/* D(h) for cos_h = n.h > 0 and roughness alpha > 0. */
inline float microfacet_d(float cos_h, float alpha, int distribution) {
  float c2 = cos_h * cos_h, a2 = alpha * alpha;
  if (distribution == MICROFACET_GGX) {
    float k = c2 * (a2 - 1.0f) + 1.0f;
    return a2 / (PRISM_PI * k * k);
  }
  /* Beckmann: exp(-tan^2 / m^2) / (pi m^2 cos^4). Towards the horizon both the
   * exponential and cos^4 underflow (0 / 0); the quotient's limit is 0. */
  float x = (1.0f - c2) / (c2 * a2);
  if (!(x < 80.0f)) return 0.0f;
  return sb_exp(-x) / (PRISM_PI * a2 * c2 * c2);
}

/* Smith's one-sided masking for GGX at a direction with cosine c to n. */
inline float microfacet_smith_ggx(float c, float alpha) {
  float a2 = alpha * alpha;
  return 2.0f * c / (c + sqrt(a2 + (1.0f - a2) * c * c));
}

/* G: the fraction of microfacets both lit and seen. */
inline float microfacet_g(float n_l, float n_v, float n_h, float v_h, float alpha, int distribution) {
  if (distribution == MICROFACET_GGX) return microfacet_smith_ggx(n_l, alpha) * microfacet_smith_ggx(n_v, alpha);
  return fmin(1.0f, fmin(2.0f * n_h * n_v / v_h, 2.0f * n_h * n_l / v_h)); /* V-cavities */
}

/* The Fresnel reflectance of unpolarised light meeting a dielectric of relative
 * index eta (inside over outside) at cos_i; 1 under total internal reflection. */
inline float fresnel_dielectric(float cos_i, float eta) {
  float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return 1.0f;
  float cos_t = sqrt(1.0f - sin2_t);
  float rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  float rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5f * (rs * rs + rp * rp);
}

/* pi f (n.l): the highlight in the units of the local model's Lambert term
 * kd (n.l), for unit n, l (to the light) and v (to the viewer) with n.l > 0.
 * fresnel_eta <= 0 stands for F = 1 (the tests' perfect reflector). */
inline float cook_torrance(float3 n, float3 l, float3 v, float alpha, int distribution, float fresnel_eta) {
  float n_l = sb_dot(n, l), n_v = sb_dot(n, v);
  if (n_l <= 0.0f || n_v <= 0.0f) return 0.0f;
  float3 h = sb_normalize(l + v);
  float n_h = sb_dot(n, h), v_h = sb_dot(v, h);
  if (n_h <= 0.0f || v_h <= 0.0f) return 0.0f;
  float f = fresnel_eta > 0.0f ? fresnel_dielectric(v_h, fresnel_eta) : 1.0f;
  float d = microfacet_d(n_h, alpha, distribution);
  float g = microfacet_g(n_l, n_v, n_h, v_h, alpha, distribution);
  return PRISM_PI * f * d * g / (4.0f * n_v);
}

#endif
