/* The convex polyhedron {x : n_i . x + w_i <= 0 for every plane i}, unit n_i:
 * the slab test generalised (Kay and Kajiya; Haines, "Fast ray-convex polyhedron
 * intersection", Graphics Gems II). Each plane the ray goes into (n . d < 0)
 * raises t_near to where it crosses it, each it leaves by lowers t_far; a ray
 * parallel to a plane and outside it misses. The hit is t_near, or t_far from
 * inside, tagged with its plane for the normal. Host half:
 * host/scene/primitives/polyhedron.cpp. */
#ifndef PRISM_GEOMETRY_POLYHEDRON_H
#define PRISM_GEOMETRY_POLYHEDRON_H

#include "common/math.h"

inline bool polyhedron_intersect(float3 o, float3 d, float tmin, float tmax, int count, __global const float* planes,
                                 float* t_out, int* face_out) {
  float t_near = -PRISM_INF, t_far = PRISM_INF;
  int f_near = 0, f_far = 0;
  for (int i = 0; i < count; ++i) {
    float3 n = load3g(planes + 4 * i);
    float dn = sb_dot(n, d), value = sb_dot(n, o) + planes[4 * i + 3]; /* value: <= 0 on the inner side */
    if (dn == 0.0f) {
      if (value > 0.0f) return false;
      continue;
    }
    float t = -value / dn;
    if (dn < 0.0f) {
      if (t > t_near) t_near = t, f_near = i;
    } else if (t < t_far) {
      t_far = t, f_far = i;
    }
    if (t_near > t_far) return false;
  }
  if (t_near > tmin && t_near < tmax) {
    *t_out = t_near;
    *face_out = f_near;
    return true;
  }
  if (t_far > tmin && t_far < tmax) {
    *t_out = t_far;
    *face_out = f_far;
    return true;
  }
  return false;
}

/* Coordinates on the face, for textures: the hit projected along the normal's
 * largest axis. */
inline float2 polyhedron_uv(float3 p, float3 n) {
  float3 a = fabs(n);
  if (a.x >= a.y && a.x >= a.z) return (float2)(p.z, p.y);
  if (a.y >= a.z) return (float2)(p.x, p.z);
  return (float2)(p.x, p.y);
}

#endif
