/* A piece of a bicubic Bezier patch, intersected by Newton iteration from
 * subdivision starts. The ray is the meeting line of two planes through it
 * (Kajiya, "Ray tracing parametric patches", 1982): projected onto their
 * normals the piece becomes F(u, v) in the plane, and a hit is a root F = 0,
 * where the surface point lies on the ray. Newton's Jacobian there is
 * det(d, S_u, S_v), which keeps one sign over the piece when the ray is far
 * enough from every tangent plane: the host stores an axis and the sine of
 * the angle within which every product of a u and a v difference of the
 * control net lies (so every normal does), and a ray steeper than that
 * crosses the piece at most once: one Newton run from where the ray crosses
 * the piece's corner triangles finds it. A ray nearer grazing is handled by
 * cutting the piece, in the projection, into parts whose control points' box
 * holds the ray and whose u and v differences keep det one sign (then a part
 * holds at most one crossing), each starting Newton in turn; the nearest
 * root wins. The host cut the patch into pieces that bend little
 * (host/scene/patches/patch_subdivision.h). Host half:
 * host/scene/primitives/patch.cpp. */
#ifndef PRISM_GEOMETRY_PATCH_H
#define PRISM_GEOMETRY_PATCH_H

#include "common/math.h"
#include "geometry/box.h"

#define PATCH_NEWTON_STEPS 10
/* A root this far outside the piece still counts, so that neighbouring pieces
 * overlap a little at their common edge instead of letting a ray through. */
#define PATCH_EDGE_SLACK 1e-4f
/* Cuts of a piece, at most, for a ray near grazing. */
#define PATCH_MAX_CUTS 8
/* The side data: control points, then the normal cone (axis xyz, sine). */
#define PATCH_CONE 48

inline void patch_bernstein(float t, float* b, float* db) {
  float s = 1.0f - t;
  b[0] = s * s * s;
  b[1] = 3.0f * t * s * s;
  b[2] = 3.0f * t * t * s;
  b[3] = t * t * t;
  db[0] = -3.0f * s * s;
  db[1] = 3.0f * s * s - 6.0f * t * s;
  db[2] = 6.0f * t * s - 3.0f * t * t;
  db[3] = 3.0f * t * t;
}

/* F(u, v) and its partial derivatives, for control points q projected to the
 * ray's planes (x, y; the third float of each is its t). */
inline float2 patch_project(const float* q, float u, float v, float2* fu, float2* fv) {
  float bu[4], dbu[4], bv[4], dbv[4];
  patch_bernstein(u, bu, dbu);
  patch_bernstein(v, bv, dbv);
  float2 f = (float2)(0.0f), a = (float2)(0.0f), b = (float2)(0.0f);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      float2 c = (float2)(q[12 * i + 3 * j], q[12 * i + 3 * j + 1]);
      f += (bu[i] * bv[j]) * c;
      a += (dbu[i] * bv[j]) * c;
      b += (bu[i] * dbv[j]) * c;
    }
  *fu = a;
  *fv = b;
  return f;
}

/* S(u, v) and, when du/dv are not null, its partial derivatives. */
inline float3 patch_point(__global const float* cp, float u, float v, float3* du, float3* dv) {
  float bu[4], dbu[4], bv[4], dbv[4];
  patch_bernstein(u, bu, dbu);
  patch_bernstein(v, bv, dbv);
  float3 s = (float3)(0.0f), a = (float3)(0.0f), b = (float3)(0.0f);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      float3 c = load3g(cp + 12 * i + 3 * j);
      s += (bu[i] * bv[j]) * c;
      a += (dbu[i] * bv[j]) * c;
      b += (bu[i] * dbv[j]) * c;
    }
  if (du) *du = a;
  if (dv) *dv = b;
  return s;
}

/* Barycentric coordinates (of b and c) of the origin in the 2D triangle abc;
 * false when it has no area. */
inline bool patch_origin_in_triangle(float2 a, float2 b, float2 c, float* wb, float* wc) {
  float2 e1 = b - a, e2 = c - a;
  float det = e1.x * e2.y - e1.y * e2.x;
  if (det == 0.0f) return false;
  *wb = (-a.x * e2.y + a.y * e2.x) / det;
  *wc = (-e1.x * a.y + e1.y * a.x) / det;
  return true;
}

/* Where Newton starts in a part (control points c, projected): the ray's
 * crossing of the corner triangles (c00, c30, c33) and (c00, c33, c03), in the
 * part's (u, v), from whichever triangle the crossing lies deeper in; the
 * centre when neither has area. */
inline float2 patch_start(const float* c) {
  float2 p00 = (float2)(c[0], c[1]), p03 = (float2)(c[9], c[10]), p30 = (float2)(c[36], c[37]),
         p33 = (float2)(c[45], c[46]);
  float2 start = (float2)(0.5f, 0.5f);
  float depth = -PRISM_INF, wb, wc;
  if (patch_origin_in_triangle(p00, p30, p33, &wb, &wc)) { /* (0,0) (1,0) (1,1) */
    depth = fmin(1.0f - wb - wc, fmin(wb, wc));
    start = (float2)(wb + wc, wc);
  }
  if (patch_origin_in_triangle(p00, p33, p03, &wb, &wc) && fmin(1.0f - wb - wc, fmin(wb, wc)) > depth)
    start = (float2)(wb, wb + wc); /* (0,0) (1,1) (0,1) */
  return clamp(start, 0.0f, 1.0f);
}

/* The cubic c[0..3] (3 floats each, `stride` floats apart) restricted to
 * [a, b], in place (de Casteljau at b, then at a / b of what is left). */
inline void patch_cut_curve(float* c, int stride, float a, float b) {
  for (int k = 0; k < 3; ++k) {
    float p0 = c[k], p1 = c[stride + k], p2 = c[2 * stride + k], p3 = c[3 * stride + k];
    if (b < 1.0f) {
      float p01 = sb_mix(p0, p1, b), p12 = sb_mix(p1, p2, b), p23 = sb_mix(p2, p3, b), p012 = sb_mix(p01, p12, b);
      p3 = sb_mix(p012, sb_mix(p12, p23, b), b);
      p2 = p012;
      p1 = p01;
    }
    if (a > 0.0f) {
      float s = a / b;
      float p01 = sb_mix(p0, p1, s), p12 = sb_mix(p1, p2, s), p23 = sb_mix(p2, p3, s), p123 = sb_mix(p12, p23, s);
      p0 = sb_mix(sb_mix(p01, p12, s), p123, s);
      p1 = p123;
      p2 = p23;
    }
    c[k] = p0, c[stride + k] = p1, c[2 * stride + k] = p2, c[3 * stride + k] = p3;
  }
}

/* The part [u0, u1] x [v0, v1] of the projected piece q, into c. */
inline void patch_part(const float* q, float u0, float u1, float v0, float v1, float* c) {
  for (int k = 0; k < 48; ++k) c[k] = q[k];
  for (int j = 0; j < 4; ++j) patch_cut_curve(c + 3 * j, 12, u0, u1);
  for (int i = 0; i < 4; ++i) patch_cut_curve(c + 12 * i, 3, v0, v1);
}

/* Whether the part c can hold a crossing in (tmin, tmax): its control points'
 * box (convex hull property) holds the ray, within tol, and reaches that t. */
inline bool patch_part_meets(const float* c, float tol, float tmin, float tmax) {
  float3 lo = (float3)(PRISM_INF), hi = (float3)(-PRISM_INF);
  for (int k = 0; k < 16; ++k) {
    float3 p = (float3)(c[3 * k], c[3 * k + 1], c[3 * k + 2]);
    lo = fmin(lo, p);
    hi = fmax(hi, p);
  }
  return lo.x <= tol && hi.x >= -tol && lo.y <= tol && hi.y >= -tol && hi.z > tmin && lo.z < tmax;
}

/* Whether det(F_u, F_v) keeps one sign over the part c (projected): every
 * u difference of its net crossed with every v difference has that sign. */
inline bool patch_part_one_sign(const float* c) {
  int positive = 0, negative = 0;
  for (int a = 0; a < 12; ++a) {
    int i = a / 4, j = a % 4; /* u difference (i, j) -> (i + 1, j) */
    float2 du = (float2)(c[12 * (i + 1) + 3 * j] - c[12 * i + 3 * j], c[12 * (i + 1) + 3 * j + 1] - c[12 * i + 3 * j + 1]);
    for (int b = 0; b < 12; ++b) {
      int k = b / 3, l = b % 3; /* v difference (k, l) -> (k, l + 1) */
      float2 dv = (float2)(c[12 * k + 3 * (l + 1)] - c[12 * k + 3 * l], c[12 * k + 3 * (l + 1) + 1] - c[12 * k + 3 * l + 1]);
      float x = du.x * dv.y - du.y * dv.x;
      positive |= x > 0.0f;
      negative |= x < 0.0f;
    }
  }
  return !(positive && negative);
}

/* Newton on the piece q from (u, v); true with the root in (u, v) when it
 * converges to within tol of the ray inside the piece. */
inline bool patch_newton(const float* q, float tol, float* u_io, float* v_io) {
  float u = *u_io, v = *v_io;
  for (int step = 0; step < PATCH_NEWTON_STEPS; ++step) {
    float2 fu, fv;
    float2 f = patch_project(q, u, v, &fu, &fv);
    if (fmax(fabs(f.x), fabs(f.y)) <= tol) {
      if (u < -PATCH_EDGE_SLACK || u > 1.0f + PATCH_EDGE_SLACK || v < -PATCH_EDGE_SLACK || v > 1.0f + PATCH_EDGE_SLACK)
        return false;
      *u_io = clamp(u, 0.0f, 1.0f);
      *v_io = clamp(v, 0.0f, 1.0f);
      return true;
    }
    float det = fu.x * fv.y - fu.y * fv.x;
    if (det == 0.0f) return false;
    u -= (f.x * fv.y - f.y * fv.x) / det;
    v -= (fu.x * f.y - fu.y * f.x) / det;
    if (!(u > -0.5f && u < 1.5f && v > -0.5f && v < 1.5f)) return false; /* left the piece (or NaN) */
  }
  return false;
}

/* p: the record's words (u0 u1 v0 v1, box, tolerance); cp: 16 control points.
 * On a hit, *u and *v are the root's coordinates in the piece. */
inline bool patch_intersect(float3 o, float3 d, float tmin, float tmax, __global const float* p,
                            __global const float* cp, float* t_out, float* u_out, float* v_out) {
  float box_t;
  float3 lo = load3g(p + 4), hi = load3g(p + 7);
  if (!box_intersect(o, d, tmin, tmax, lo, hi, &box_t)) return false;
  /* Two unit normals perpendicular to the ray and to each other. */
  float3 ad = fabs(d);
  float3 axis = ad.x <= ad.y && ad.x <= ad.z ? (float3)(1.0f, 0.0f, 0.0f)
                : ad.y <= ad.z               ? (float3)(0.0f, 1.0f, 0.0f)
                                             : (float3)(0.0f, 0.0f, 1.0f);
  float3 n1 = sb_normalize(sb_cross(d, axis));
  float3 n2 = sb_normalize(sb_cross(d, n1));
  float dd = sb_dot(d, d);
  float q[48];
  for (int k = 0; k < 16; ++k) {
    float3 c = load3g(cp + 3 * k) - o;
    q[3 * k] = sb_dot(n1, c);
    q[3 * k + 1] = sb_dot(n2, c);
    q[3 * k + 2] = sb_dot(d, c) / dd;
  }
  /* Newton cannot get closer than float's spacing of the coordinates. */
  float tol = fmax(p[10], 4e-6f * (max3(fabs(hi - lo)) + max3(fabs(o - 0.5f * (lo + hi)))));
  float best = tmax, best_u = 0.0f, best_v = 0.0f;
  /* Steeper than the normal cone allows for a tangent: one crossing at most. */
  bool steep = fabs(sb_dot(d, load3g(cp + PATCH_CONE))) > cp[PATCH_CONE + 3] * sqrt(dd);
  /* Parts still to look at: (u0, u1, v0, v1, cuts so far), depth first. */
  float stack[5 * (PATCH_MAX_CUTS + 1)];
  stack[0] = 0.0f, stack[1] = 1.0f, stack[2] = 0.0f, stack[3] = 1.0f, stack[4] = 0.0f;
  int top = 1;
  float c[48];
  while (top > 0) {
    --top;
    float u0 = stack[5 * top], u1 = stack[5 * top + 1], v0 = stack[5 * top + 2], v1 = stack[5 * top + 3];
    int cuts = (int)stack[5 * top + 4];
    if (cuts > 0) patch_part(q, u0, u1, v0, v1, c);
    const float* part = cuts > 0 ? c : q; /* the whole piece is q itself */
    if (!patch_part_meets(part, tol, tmin, best)) continue;
    if (!steep && cuts < PATCH_MAX_CUTS && !patch_part_one_sign(part)) {
      /* Cut across the longer side (in the projection); both halves go on the stack. */
      float lu = sb_length2((float2)(part[36] - part[0], part[37] - part[1])) + sb_length2((float2)(part[45] - part[9], part[46] - part[10]));
      float lv = sb_length2((float2)(part[9] - part[0], part[10] - part[1])) + sb_length2((float2)(part[45] - part[36], part[46] - part[37]));
      bool along_u = lu >= lv;
      float mu = 0.5f * (u0 + u1), mv = 0.5f * (v0 + v1);
      for (int second = 0; second < 2; ++second) {
        float* s = stack + 5 * top;
        s[0] = along_u && second ? mu : u0;
        s[1] = along_u && !second ? mu : u1;
        s[2] = !along_u && second ? mv : v0;
        s[3] = !along_u && !second ? mv : v1;
        s[4] = (float)(cuts + 1);
        ++top;
      }
      continue;
    }
    float2 start = patch_start(part);
    float u = sb_mix(u0, u1, start.x), v = sb_mix(v0, v1, start.y);
    if (!patch_newton(q, tol, &u, &v)) {
      u = 0.5f * (u0 + u1), v = 0.5f * (v0 + v1); /* a second start: the part's centre */
      if (!patch_newton(q, tol, &u, &v)) continue;
    }
    float t = sb_dot(patch_point(cp, u, v, 0, 0) - o, d) / dd;
    if (t > tmin && t < best) {
      best = t;
      best_u = u;
      best_v = v;
    }
  }
  if (!(best < tmax)) return false;
  *t_out = best;
  *u_out = best_u;
  *v_out = best_v;
  return true;
}

/* The unit normal du x dv at (u, v); at a collapsed edge (the teapot lid's
 * apex), where it vanishes, the normal a little way towards the centre. */
inline float3 patch_normal(__global const float* cp, float u, float v) {
  float3 du, dv, n = (float3)(0.0f, 0.0f, 1.0f);
  for (int k = 0; k < 3; ++k) {
    float step = k == 0 ? 0.0f : (k == 1 ? 1e-3f : 1e-2f);
    patch_point(cp, u + (0.5f - u) * step, v + (0.5f - v) * step, &du, &dv);
    float3 c = sb_cross(du, dv);
    float len = sb_length(c);
    if (len > 0.0f) return c / len;
  }
  return n;
}

/* Texture coordinates: (u, v) in the patch the piece was cut from. */
inline float2 patch_uv(__global const float* p, float u, float v) {
  return (float2)(sb_mix(p[0], p[1], u), sb_mix(p[2], p[3], v));
}

#endif
