/* Ray-triangle intersection (Moller and Trumbore 1997): solves o + t d =
 * v0 + u (v1 - v0) + v (v2 - v0) by Cramer's rule. */
#ifndef PRISM_GEOMETRY_TRIANGLE_H
#define PRISM_GEOMETRY_TRIANGLE_H

#include "common/math.h"

inline bool triangle_intersect(float3 o, float3 d, float tmin, float tmax, float3 v0, float3 v1, float3 v2,
                               float* t_out, float* u_out, float* v_out) {
  float3 e1 = v1 - v0, e2 = v2 - v0;
  float3 pv = cross(d, e2);
  float det = dot(e1, pv);
  if (det == 0.0f) return false; /* ray parallel to the triangle's plane */
  float inv_det = 1.0f / det;
  float3 tv = o - v0;
  float u = dot(tv, pv) * inv_det;
  if (u < 0.0f || u > 1.0f) return false;
  float3 qv = cross(tv, e1);
  float v = dot(d, qv) * inv_det;
  if (v < 0.0f || u + v > 1.0f) return false;
  float t = dot(e2, qv) * inv_det;
  if (!(t > tmin && t < tmax)) return false;
  *t_out = t;
  *u_out = u;
  *v_out = v;
  return true;
}

inline float3 triangle_normal(float3 v0, float3 v1, float3 v2) { return normalize(cross(v1 - v0, v2 - v0)); }

#endif
