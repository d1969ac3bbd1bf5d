/* Conservative film-space bounds of a convex hull (a triangle's vertices, a
 * box's corners) seen through the pinhole camera of camera_ray_dir: every film
 * position whose primary ray can meet the hull lies inside them. The first-hit
 * pass visits only the samples inside a primitive's bounds.
 *
 * Film coordinates of a point P, v = P - origin, z = v.forward:
 *   X = W/2 (1 + (v.right) / (|right|^2 z)),  Y = H/2 (1 - (v.up) / (|up|^2 z)).
 * Points near the camera plane (|z| within 1e-4 of |v|) or on both sides of it
 * make the image unbounded: the whole film. A hull wholly behind the plane is
 * culled. The pad is 0.1 pixel plus a bound on the float error of the
 * projection itself (about 17 ulp of its terms); the error of a ray direction
 * (about 1e-4 pixel) and of the intersection tests is far below it.
 * The functions are PRISM_HOT: PoCL otherwise calls them through pointers to
 * the projector and the hull, once per vertex. */
#ifndef PRISM_SAMPLING_FILM_BOUNDS_H
#define PRISM_SAMPLING_FILM_BOUNDS_H

#include "common/math.h"
#include "shared/camera_gpu.h"

#define FILM_BOUNDS_CULLED 0
#define FILM_BOUNDS_FINITE 1
#define FILM_BOUNDS_WHOLE_FILM 2

typedef struct {
  float3 o, f, r, u;
  float rr, uu, r_len, u_len, w, h;
} FilmProjector;

PRISM_HOT FilmProjector film_projector(__global const CameraGpu* camera) {
  FilmProjector p;
  p.o = load3g(camera->origin);
  p.f = load3g(camera->forward);
  p.r = load3g(camera->right);
  p.u = load3g(camera->up);
  p.rr = sb_dot(p.r, p.r);
  p.uu = sb_dot(p.u, p.u);
  p.r_len = sqrt(p.rr);
  p.u_len = sqrt(p.uu);
  p.w = (float)camera->width;
  p.h = (float)camera->height;
  return p;
}

typedef struct {
  float4 box; /* x0, y0, x1, y1 */
  int behind, near, front;
} FilmHull;

PRISM_HOT FilmHull film_hull_empty(void) {
  FilmHull h;
  h.box = (float4)(INFINITY, INFINITY, -INFINITY, -INFINITY);
  h.behind = 0;
  h.near = 0;
  h.front = 0;
  return h;
}

PRISM_HOT void film_hull_add(const FilmProjector* c, float3 p, FilmHull* h) {
  float3 v = p - c->o;
  float len = fabs(v.x) + fabs(v.y) + fabs(v.z); /* >= |v| */
  float z = sb_dot(v, c->f);
  float tol = 1e-4f * len;
  if (!(z >= -tol)) { /* NaN counts as near: never culled */
    if (z < -tol)
      h->behind += 1;
    else
      h->near += 1;
    return;
  }
  if (z <= tol) {
    h->near += 1;
    return;
  }
  h->front += 1;
  float sx = sb_dot(v, c->r) / (c->rr * z), sy = sb_dot(v, c->u) / (c->uu * z);
  float rel = 1e-6f * len / z;
  float pad_x = 0.1f + 0.5f * c->w * rel * (fabs(sx) + c->r_len / c->rr);
  float pad_y = 0.1f + 0.5f * c->h * rel * (fabs(sy) + c->u_len / c->uu);
  float x = 0.5f * c->w * (1.0f + sx), y = 0.5f * c->h * (1.0f - sy);
  h->box = (float4)(fmin(h->box.x, x - pad_x), fmin(h->box.y, y - pad_y), fmax(h->box.z, x + pad_x),
                    fmax(h->box.w, y + pad_y));
}

/* film_hull_add of one vertex in each of eight lanes (eight hulls: their
 * counts and film boxes x0, y0, x1, y1 lane by lane), with its operations in
 * the same order, so the same bounds; only the lanes of `in` count. */
PRISM_HOT void film_hull_add8(const FilmProjector* c, float8 px, float8 py, float8 pz, int8 in, int8* behind,
                              int8* near, int8* front, float8* x0, float8* y0, float8* x1, float8* y1) {
  float8 vx = px - c->o.x, vy = py - c->o.y, vz = pz - c->o.z;
  float8 len = fabs(vx) + fabs(vy) + fabs(vz);
  float8 z = vx * c->f.x + vy * c->f.y + vz * c->f.z;
  float8 tol = 1e-4f * len;
  /* film_hull_add's three cases as masks, without a bitwise not: Oclgrind
   * 21.10 computes a not of a vector comparison wrongly in optimised builds.
   * tol is at least 0 or NaN, so z > tol is film_hull_add's front; a NaN z or
   * tol is near, as there. */
  int8 behind_m = in & (z < -tol);
  int8 near_m = in & (((z >= -tol) & (z <= tol)) | (z != z) | (tol != tol));
  int8 is_front = in & (z > tol);
  *behind -= behind_m; /* true is -1 */
  *near -= near_m;
  *front -= is_front;
  float8 sx = (vx * c->r.x + vy * c->r.y + vz * c->r.z) / (c->rr * z);
  float8 sy = (vx * c->u.x + vy * c->u.y + vz * c->u.z) / (c->uu * z);
  float8 rel = 1e-6f * len / z;
  float8 pad_x = 0.1f + 0.5f * c->w * rel * (fabs(sx) + c->r_len / c->rr);
  float8 pad_y = 0.1f + 0.5f * c->h * rel * (fabs(sy) + c->u_len / c->uu);
  float8 x = 0.5f * c->w * (1.0f + sx), y = 0.5f * c->h * (1.0f - sy);
  *x0 = select(*x0, fmin(*x0, x - pad_x), is_front);
  *y0 = select(*y0, fmin(*y0, y - pad_y), is_front);
  *x1 = select(*x1, fmax(*x1, x + pad_x), is_front);
  *y1 = select(*y1, fmax(*y1, y + pad_y), is_front);
}

/* The hull's verdict; for FILM_BOUNDS_FINITE, *cells is the inclusive rectangle of
 * film pixels (x0, y0, x1, y1) its bounds touch, clamped to the film. */
PRISM_HOT int film_hull_cells(const FilmProjector* c, const FilmHull* h, int4* cells) {
  int w = (int)c->w, hgt = (int)c->h;
  if (h->behind > 0 && h->near == 0 && h->front == 0) return FILM_BOUNDS_CULLED;
  if (h->near > 0 || (h->behind > 0 && h->front > 0) || !(isfinite(h->box.x) && isfinite(h->box.y) &&
                                                          isfinite(h->box.z) && isfinite(h->box.w))) {
    *cells = (int4)(0, 0, w - 1, hgt - 1);
    return FILM_BOUNDS_WHOLE_FILM;
  }
  float4 b = h->box;
  if (b.z < 0.0f || b.x > c->w || b.w < 0.0f || b.y > c->h) return FILM_BOUNDS_CULLED;
  /* Clamped in float first: a far-off bound must not overflow the conversion. */
  *cells = (int4)((int)floor(clamp(b.x, 0.0f, c->w - 1.0f)), (int)floor(clamp(b.y, 0.0f, c->h - 1.0f)),
                  (int)floor(clamp(b.z, 0.0f, c->w - 1.0f)), (int)floor(clamp(b.w, 0.0f, c->h - 1.0f)));
  return FILM_BOUNDS_FINITE;
}

#endif
