/* Ray-sphere intersection in the form of Haines et al., "Precision Improvements
 * for Ray/Sphere Intersection" (Ray Tracing Gems, ch. 7): the discriminant is
 * taken from the distance of the centre to the ray, which avoids the cancellation
 * of b*b - 4ac for distant or large spheres. */
#ifndef PRISM_GEOMETRY_SPHERE_H
#define PRISM_GEOMETRY_SPHERE_H

#include "common/math.h"

/* Nearest t in (tmin, tmax), for rays starting outside or inside; d need not be unit. */
inline bool sphere_intersect(float3 o, float3 d, float tmin, float tmax, float3 center, float radius, float* t_out) {
  float3 f = o - center;
  float a = sb_dot(d, d);
  float b = sb_dot(f, d); /* half of the usual b */
  float3 l = f - (b / a) * d;
  float r2 = radius * radius;
  float disc = a * (r2 - sb_dot(l, l));
  if (disc < 0.0f) return false;
  float c = sb_dot(f, f) - r2;
  float q = -b - copysign(sqrt(disc), b);
  float t0 = q != 0.0f ? c / q : 0.0f;
  float t1 = q / a;
  float near_t = fmin(t0, t1), far_t = fmax(t0, t1);
  if (near_t > tmin && near_t < tmax) {
    *t_out = near_t;
    return true;
  }
  if (far_t > tmin && far_t < tmax) {
    *t_out = far_t;
    return true;
  }
  return false;
}

inline float3 sphere_normal(float3 p, float3 center) { return sb_normalize(p - center); }

/* Longitude/latitude in [0,1]^2, for textures. */
inline float2 sphere_uv(float3 n) {
  float u = 0.5f + sb_atan2(n.z, n.x) * (0.5f / M_PI_F);
  float v = 0.5f - sb_asin(clamp(n.y, -1.0f, 1.0f)) / M_PI_F;
  return (float2)(u, v);
}

#endif
