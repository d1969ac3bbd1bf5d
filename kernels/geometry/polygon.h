/* The planar polygon: the ray meets its plane, and the hit's projection onto
 * the two axes the normal is least along is tested against the projected
 * vertices by one of the three classic point-in-polygon tests (the record
 * says which, POLYGON_*):
 *   crossing    the Jordan curve test: a ray from the point along +u crosses
 *               the boundary an odd number of times (edges taken half-open in
 *               v, so a vertex on the test ray counts once);
 *   radial      the angle-sum test: the angles the edges subtend at the point
 *               add up to +-2 pi inside and to 0 outside;
 *   left-right  the point lies on the inner side of every edge (convex only).
 * Each first asks whether the point lies exactly on an edge: the polygon is
 * closed, so on an edge or a vertex is inside, whichever test runs. Host half:
 * host/scene/primitives/polygon.cpp. */
#ifndef PRISM_GEOMETRY_POLYGON_H
#define PRISM_GEOMETRY_POLYGON_H

#include "common/math.h"

/* Vertex k of the polygon projected on axes (iu, iv). */
inline float2 polygon_vertex(__global const float* verts, int k, int iu, int iv) {
  return (float2)(verts[3 * k + iu], verts[3 * k + iv]);
}

inline float polygon_cross(float2 a, float2 b) { return a.x * b.y - a.y * b.x; }

/* Whether p lies exactly on the segment ab. */
inline bool polygon_on_edge(float2 a, float2 b, float2 p) {
  return polygon_cross(b - a, p - a) == 0.0f && p.x >= fmin(a.x, b.x) && p.x <= fmax(a.x, b.x) &&
         p.y >= fmin(a.y, b.y) && p.y <= fmax(a.y, b.y);
}

inline bool polygon_inside_crossing(__global const float* verts, int n, int iu, int iv, float2 p) {
  bool inside = false;
  float2 a = polygon_vertex(verts, n - 1, iu, iv);
  for (int k = 0; k < n; ++k) {
    float2 b = polygon_vertex(verts, k, iu, iv);
    if (polygon_on_edge(a, b, p)) return true;
    if ((b.y > p.y) != (a.y > p.y)) {
      float x = b.x + (a.x - b.x) * (p.y - b.y) / (a.y - b.y); /* where the edge meets the line v = p.v */
      if (p.x < x) inside = !inside;
    }
    a = b;
  }
  return inside;
}

inline bool polygon_inside_radial(__global const float* verts, int n, int iu, int iv, float2 p) {
  float sum = 0.0f;
  float2 a = polygon_vertex(verts, n - 1, iu, iv);
  for (int k = 0; k < n; ++k) {
    float2 b = polygon_vertex(verts, k, iu, iv);
    if (polygon_on_edge(a, b, p)) return true;
    float2 ra = a - p, rb = b - p;
    sum += sb_atan2(polygon_cross(ra, rb), sb_dot2(ra, rb)); /* the signed angle from a to b seen from p */
    a = b;
  }
  return fabs(sum) > M_PI_F; /* +-2 pi inside, 0 outside */
}

/* orientation: +1 when the projected vertices turn counterclockwise. */
inline bool polygon_inside_left_right(__global const float* verts, int n, int iu, int iv, float orientation,
                                      float2 p) {
  float2 a = polygon_vertex(verts, n - 1, iu, iv);
  for (int k = 0; k < n; ++k) {
    float2 b = polygon_vertex(verts, k, iu, iv);
    if (orientation * polygon_cross(b - a, p - a) < 0.0f) return false;
    a = b;
  }
  return true; /* on the inner side of (or on) every edge */
}

/* q: the record's p[] (normal, offset, axes, count, test, orientation). */
inline bool polygon_intersect(float3 o, float3 d, float tmin, float tmax, __global const float* q,
                              __global const float* verts, float* t_out) {
  float3 n = (float3)(q[0], q[1], q[2]);
  float denom = sb_dot(n, d);
  if (denom == 0.0f) return false;
  float t = -(sb_dot(n, o) + q[3]) / denom;
  if (!(t > tmin && t < tmax)) return false;
  float3 x = o + t * d;
  int iu = (int)q[4], iv = (int)q[5], count = (int)q[6], test = (int)q[7];
  float xs[3] = {x.x, x.y, x.z};
  float2 p = (float2)(xs[iu], xs[iv]);
  bool inside = test == POLYGON_RADIAL     ? polygon_inside_radial(verts, count, iu, iv, p)
                : test == POLYGON_LEFT_RIGHT ? polygon_inside_left_right(verts, count, iu, iv, q[8], p)
                                             : polygon_inside_crossing(verts, count, iu, iv, p);
  if (!inside) return false;
  *t_out = t;
  return true;
}

/* Planar texture coordinates: the hit's projection. */
inline float2 polygon_uv(__global const float* q, float3 x) {
  float xs[3] = {x.x, x.y, x.z};
  return (float2)(xs[(int)q[4]], xs[(int)q[5]]);
}

#endif
