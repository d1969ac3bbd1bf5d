/* Ray-plane intersection: t = (p0 - o)·n / d·n. */
#ifndef PRISM_GEOMETRY_PLANE_H
#define PRISM_GEOMETRY_PLANE_H

#include "common/math.h"

inline bool plane_intersect(float3 o, float3 d, float tmin, float tmax, float3 p0, float3 n, float* t_out) {
  float denom = sb_dot(d, n);
  if (denom == 0.0f) return false;
  float t = sb_dot(p0 - o, n) / denom;
  if (!(t > tmin && t < tmax)) return false;
  *t_out = t;
  return true;
}

/* Coordinates in an orthonormal frame of the plane through p0, for textures. */
inline float2 plane_uv(float3 p, float3 p0, float3 n) {
  float3 helper = fabs(n.x) > 0.9f ? (float3)(0.0f, 0.0f, 1.0f) : (float3)(1.0f, 0.0f, 0.0f);
  float3 s = sb_normalize(sb_cross(helper, n));
  float3 t = sb_cross(n, s);
  float3 q = p - p0;
  return (float2)(sb_dot(q, s), sb_dot(q, t));
}

#endif
