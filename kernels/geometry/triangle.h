/* Ray-triangle intersection (Moller and Trumbore 1997): solves o + t d =
 * v0 + u (v1 - v0) + v (v2 - v0) by Cramer's rule. Dot and cross products are
 * written out, left to right, rather than taken from the builtins, whose
 * rounding a driver may choose (one fused multiply-add, another order): the
 * 4-wide forms of this test (accel/leaf_packets.h, firsthit.cl) then give the
 * same bits as this one on every device. */
#ifndef PRISM_GEOMETRY_TRIANGLE_H
#define PRISM_GEOMETRY_TRIANGLE_H

#include "common/math.h"

inline float tri_dot(float3 a, float3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline float3 tri_cross(float3 a, float3 b) {
  return (float3)(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* The terms of the solve that depend on the ray's origin alone: rays from one
 * point (a pinhole camera's primary rays) share them, and the first-hit pass
 * computes them once per triangle. triangle_intersect is this split, so the two
 * give the same t, u and v bit for bit. */
typedef struct {
  float3 e1, e2, tv, qv;
} TriangleFromOrigin;

inline TriangleFromOrigin triangle_from_origin(float3 o, float3 v0, float3 v1, float3 v2) {
  TriangleFromOrigin s;
  s.e1 = v1 - v0;
  s.e2 = v2 - v0;
  s.tv = o - v0;
  s.qv = tri_cross(s.tv, s.e1);
  return s;
}

inline bool triangle_intersect_from(const TriangleFromOrigin* s, float3 d, float tmin, float tmax, float* t_out,
                                    float* u_out, float* v_out) {
  float3 pv = tri_cross(d, s->e2);
  float det = tri_dot(s->e1, pv);
  if (det == 0.0f) return false; /* ray parallel to the triangle's plane */
  float inv_det = 1.0f / det;
  float u = tri_dot(s->tv, pv) * inv_det;
  if (u < 0.0f || u > 1.0f) return false;
  float v = tri_dot(d, s->qv) * inv_det;
  if (v < 0.0f || u + v > 1.0f) return false;
  float t = tri_dot(s->e2, s->qv) * inv_det;
  if (!(t > tmin && t < tmax)) return false;
  *t_out = t;
  *u_out = u;
  *v_out = v;
  return true;
}

inline bool triangle_intersect(float3 o, float3 d, float tmin, float tmax, float3 v0, float3 v1, float3 v2,
                               float* t_out, float* u_out, float* v_out) {
  TriangleFromOrigin s = triangle_from_origin(o, v0, v1, v2);
  return triangle_intersect_from(&s, d, tmin, tmax, t_out, u_out, v_out);
}

inline float3 triangle_normal(float3 v0, float3 v1, float3 v2) { return sb_normalize(sb_cross(v1 - v0, v2 - v0)); }

#endif
