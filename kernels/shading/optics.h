/* Directions of the mirror-reflected and the refracted ray. */
#ifndef PRISM_SHADING_OPTICS_H
#define PRISM_SHADING_OPTICS_H

#include "common/math.h"

/* R = I - 2 (N·I) N, for incident direction I and unit normal N. */
inline float3 reflect_dir(float3 i, float3 n) { return i - 2.0f * sb_dot(n, i) * n; }

/* Snell's law for unit incident direction i and unit normal n facing against i,
 * with eta = n_from / n_to. Returns false on total internal reflection. */
inline bool refract_dir(float3 i, float3 n, float eta, float3* t_out) {
  float cos_i = -sb_dot(n, i);
  float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
  if (k < 0.0f) return false;
  *t_out = eta * i + (eta * cos_i - sqrt(k)) * n;
  return true;
}

#endif
