/* The general quadric
 *   Q(x) = A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0
 * clipped to a box, open (the surface inside the box) or capped (the boundary
 * of the solid {Q <= 0} cut by the box, so the box's faces close it). Host
 * half: host/scene/primitives/quadric.cpp.
 *
 * Along a ray Q is the quadratic a t^2 + 2 h t + c. Its roots come from the
 * cancellation-free pair q = -(h + sign(h) sqrt(h^2 - a c)), t = q / a and
 * t = c / q, which stays right as a -> 0: there c / q tends to the root of the
 * linear equation 2 h t + c = 0 (a ray along a cylinder's axis or a cone's
 * generator) and q / a runs off to infinity. The solid's parameter intervals
 * along the ray are where the quadratic is <= 0, by the sign of a; cut by the
 * box's slab interval, their ends are the hits, each tagged with the surface it
 * lies on (QUADRIC_SURFACE, or a box face for a cap), so the normal is the
 * gradient's or the face's without guessing from the point. */
#ifndef PRISM_GEOMETRY_QUADRIC_H
#define PRISM_GEOMETRY_QUADRIC_H

#include "common/math.h"

/* Hit tags: the quadric itself, or face 1 + 2 axis + (1 at the box's max). */
#define QUADRIC_SURFACE 0

/* A x, for the symmetric matrix of the quadratic part. */
inline float3 quadric_times(__global const float* q, float3 x) {
  return (float3)(q[0] * x.x + 0.5f * (q[3] * x.y + q[4] * x.z), q[1] * x.y + 0.5f * (q[3] * x.x + q[5] * x.z),
                  q[2] * x.z + 0.5f * (q[4] * x.x + q[5] * x.y));
}

/* Outward (towards Q > 0) gradient of Q at p. */
inline float3 quadric_gradient(__global const float* q, float3 p) {
  return 2.0f * quadric_times(q, p) + (float3)(q[6], q[7], q[8]);
}

/* The ray's interval inside the clip box, with the faces it enters and leaves by. */
inline bool quadric_clip_interval(float3 o, float3 d, __global const float* clip, float* t0, float* t1, int* f0,
                                  int* f1) {
  float lo_t = -PRISM_INF, hi_t = PRISM_INF;
  int lo_f = 0, hi_f = 0;
  float oa[3] = {o.x, o.y, o.z}, da[3] = {d.x, d.y, d.z};
  for (int axis = 0; axis < 3; ++axis) {
    float lo = clip[axis], hi = clip[3 + axis];
    if (da[axis] == 0.0f) {
      if (oa[axis] < lo || oa[axis] > hi) return false;
      continue;
    }
    float ta = (lo - oa[axis]) / da[axis], tb = (hi - oa[axis]) / da[axis];
    int fa = 1 + 2 * axis, fb = 2 + 2 * axis;
    if (ta > tb) {
      float s = ta;
      ta = tb;
      tb = s;
      int g = fa;
      fa = fb;
      fb = g;
    }
    if (ta > lo_t) lo_t = ta, lo_f = fa;
    if (tb < hi_t) hi_t = tb, hi_f = fb;
  }
  *t0 = lo_t;
  *t1 = hi_t;
  *f0 = lo_f;
  *f1 = hi_f;
  return lo_t <= hi_t;
}

/* Offers boundary point t (on surface `face`) as the hit: the first offered
 * inside (tmin, tmax), in increasing order, wins. */
inline bool quadric_offer(float t, int face, float tmin, float tmax, float* t_out, int* face_out) {
  if (t > tmin && t < tmax) {
    *t_out = t;
    *face_out = face;
    return true;
  }
  return false;
}

/* Nearest t in (tmin, tmax); *face_out tells the surface it lies on. */
inline bool quadric_intersect(float3 o, float3 d, float tmin, float tmax, __global const float* q,
                              __global const float* clip, bool capped, float* t_out, int* face_out) {
  float b0, b1;
  int f0, f1;
  if (!quadric_clip_interval(o, d, clip, &b0, &b1, &f0, &f1)) return false;
  float3 ad = quadric_times(q, d);
  float3 lin = (float3)(q[6], q[7], q[8]);
  float a = sb_dot(d, ad);
  float h = sb_dot(o, ad) + 0.5f * sb_dot(lin, d);
  float c = sb_dot(o, quadric_times(q, o)) + sb_dot(lin, o) + q[9];
  float disc = h * h - a * c;
  /* The roots r0 <= r1, one of them infinite when a = 0 (the equation is
   * linear; the infinite one stands on the side where it stays <= 0, so the
   * rule for a >= 0 below holds). No roots when disc < 0, or when a = h = 0. */
  bool roots = false;
  float r0 = 0.0f, r1 = 0.0f;
  if (disc >= 0.0f) {
    float qq = -(h + copysign(sqrt(disc), h));
    if (qq != 0.0f) {
      float x = c / qq, y = a != 0.0f ? qq / a : (h > 0.0f ? -PRISM_INF : PRISM_INF);
      r0 = fmin(x, y);
      r1 = fmax(x, y);
      roots = true;
    } else if (a != 0.0f) { /* h = 0 and disc = 0: a double root at 0 */
      roots = true;
    }
  }
  if (!capped) {
    /* The roots inside the box, nearer first (an infinite one never is). */
    if (roots && r0 >= b0 && r0 <= b1 && quadric_offer(r0, QUADRIC_SURFACE, tmin, tmax, t_out, face_out)) return true;
    return roots && r1 >= b0 && r1 <= b1 && quadric_offer(r1, QUADRIC_SURFACE, tmin, tmax, t_out, face_out);
  }
  /* Capped: up to two intervals where the quadratic is <= 0 (between the
   * roots when a >= 0, outside them when a < 0), cut by [b0, b1]; each
   * interval's ends are offered in order. */
  float lo[2], hi[2];
  int count = 0;
  if (roots && a >= 0.0f) {
    lo[0] = r0;
    hi[0] = r1;
    count = 1;
  } else if (roots) {
    lo[0] = -PRISM_INF;
    hi[0] = r0;
    lo[1] = r1;
    hi[1] = PRISM_INF;
    count = 2;
  } else if (c <= 0.0f && a <= 0.0f) { /* never positive along the ray: the whole line */
    lo[0] = -PRISM_INF;
    hi[0] = PRISM_INF;
    count = 1;
  }
  for (int k = 0; k < count; ++k) {
    float s = lo[k], e = hi[k];
    int sf = QUADRIC_SURFACE, ef = QUADRIC_SURFACE;
    if (b0 >= s) s = b0, sf = f0;
    if (b1 <= e) e = b1, ef = f1;
    if (s > e) continue;
    if (quadric_offer(s, sf, tmin, tmax, t_out, face_out)) return true;
    if (quadric_offer(e, ef, tmin, tmax, t_out, face_out)) return true;
  }
  return false;
}

/* Outward unit normal at p on the surface `face` names. */
inline float3 quadric_normal(__global const float* q, float3 p, int face) {
  if (face == QUADRIC_SURFACE) {
    float3 g = quadric_gradient(q, p);
    float len = sb_length(g);
    return len > 0.0f ? g / len : (float3)(0.0f, 1.0f, 0.0f);
  }
  int axis = (face - 1) / 2;
  float s = (face - 1) % 2 ? 1.0f : -1.0f;
  return (float3)(axis == 0 ? s : 0.0f, axis == 1 ? s : 0.0f, axis == 2 ? s : 0.0f);
}

/* Texture coordinates: around the y axis and up the clip box on the surface,
 * planar on a cap. */
inline float2 quadric_uv(float3 p, __global const float* clip, int face) {
  float3 lo = (float3)(clip[0], clip[1], clip[2]), hi = (float3)(clip[3], clip[4], clip[5]);
  float3 s = (p - lo) / (hi - lo);
  if (face == QUADRIC_SURFACE) {
    float3 c = 0.5f * (lo + hi);
    return (float2)(0.5f + sb_atan2(p.z - c.z, p.x - c.x) * (0.5f / M_PI_F), s.y);
  }
  int axis = (face - 1) / 2;
  return axis == 0 ? (float2)(s.z, s.y) : axis == 1 ? (float2)(s.x, s.z) : (float2)(s.x, s.y);
}

#endif
