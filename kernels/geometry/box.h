/* Ray-box intersection by slabs (Kay and Kajiya): the ray's parameter interval
 * inside each pair of parallel planes, intersected over the three axes. */
#ifndef PRISM_GEOMETRY_BOX_H
#define PRISM_GEOMETRY_BOX_H

#include "common/math.h"

inline bool box_intersect(float3 o, float3 d, float tmin, float tmax, float3 lo, float3 hi, float* t_out) {
  float3 inv = 1.0f / d;
  float3 t1 = (lo - o) * inv;
  float3 t2 = (hi - o) * inv;
  /* A zero direction component with the origin on a slab plane gives 0*inf = NaN;
   * fmin/fmax drop NaN, which treats the ray as inside that slab. */
  float3 tn = fmin(t1, t2), tf = fmax(t1, t2);
  float t_near = fmax(tn.x, fmax(tn.y, tn.z));
  float t_far = fmin(tf.x, fmin(tf.y, tf.z));
  if (t_near > t_far) return false;
  if (t_near > tmin && t_near < tmax) {
    *t_out = t_near;
    return true;
  }
  if (t_far > tmin && t_far < tmax) {
    *t_out = t_far;
    return true;
  }
  return false;
}

/* Outward normal of the face nearest to p. */
inline float3 box_normal(float3 p, float3 lo, float3 hi) {
  float3 c = 0.5f * (lo + hi), h = 0.5f * (hi - lo);
  float3 q = (p - c) / h;
  float3 a = fabs(q);
  if (a.x >= a.y && a.x >= a.z) return (float3)(sign(q.x), 0.0f, 0.0f);
  if (a.y >= a.z) return (float3)(0.0f, sign(q.y), 0.0f);
  return (float3)(0.0f, 0.0f, sign(q.z));
}

/* Coordinates on the face the normal points out of, for textures. */
inline float2 box_uv(float3 p, float3 n) {
  if (n.x != 0.0f) return (float2)(p.z, p.y);
  if (n.y != 0.0f) return (float2)(p.x, p.z);
  return (float2)(p.x, p.y);
}

#endif
