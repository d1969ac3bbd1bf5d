/* firsthit: the first-hit (Z-buffer) pass for a pinhole camera, scan conversion
 * on the device (host/render/firsthit.cpp drives it):
 *
 *   firsthit_count_cells, firsthit_sort_samples: the batch's sample positions
 *     sorted by film pixel (a counting sort; scan.cl in between), each stored
 *     with its primary ray's direction (firsthit_pixel_major instead where they
 *     come in pixel order);
 *   firsthit_bound: per primitive, the film pixels its conservative bounds touch
 *     (sampling/film_bounds.h) and how many 8x8-pixel blocks they span;
 *   firsthit_emit: one (primitive, block) pair per such block, at offsets
 *     scanned from those counts (scan.cl);
 *   firsthit_raster: per pair, the ray test against every sample of the block's
 *     pixels inside the bounds, and an atomic minimum of (t, primitive) into the
 *     sample's depth + id entry;
 *   firsthit_resolve: per sample, the winner's t, u, v by the tracer's own
 *     object_intersect.
 *
 * The ray tests are the tracer's (object_intersect; for a plain triangle its
 * triangle_intersect split at the origin, which gives the same bits), so a
 * sample's depth and id are what tracing its ray gives; equal depths go to the
 * lower primitive index, as in a brute-force loop over the scene. The minimum
 * does not depend on the order of the atomics, so neither does the result.
 *
 * Entries are 2 uints per sample, all bits set when empty. With 64-bit atomics
 * (PRISM_ZBUFFER_WIDE) an entry is one ulong, t's bits above the id: positive
 * floats order as their bits, so one atom_min keeps the nearest hit, lower id
 * first. Without, two raster passes: the first keeps the nearest t's bits in
 * entry[0], the second the lowest id among the hits at exactly that t in
 * entry[1]. */
#ifdef PRISM_ZBUFFER_WIDE
#pragma OPENCL EXTENSION cl_khr_int64_extended_atomics : enable
#endif

#include "geometry/object.h"
#include "sampling/camera_ray.h"
#include "sampling/film_bounds.h"

#define FIRSTHIT_BLOCK 8 /* pixels per side of a raster block */

__kernel void firsthit_count_cells(__global const CameraGpu* camera, __global const float* xy, int first, int count,
                                   __global int* cell_count) {
  int k = get_global_id(0);
  if (k >= count) return;
  FilmProjector c = film_projector(camera);
  atomic_inc(&cell_count[film_cell(&c, xy[2 * (first + k)], xy[2 * (first + k) + 1])]);
}

/* cell_count comes back to zero (each sample takes one slot by counting down),
 * ready for the next batch. */
__kernel void firsthit_sort_samples(__global const CameraGpu* camera, __global const float* xy, int first, int count,
                                    __global const int* cell_start, __global int* cell_count,
                                    __global float4* sorted, __global uint* entries) {
  int k = get_global_id(0);
  if (k >= count) return;
  FilmProjector c = film_projector(camera);
  float x = xy[2 * (first + k)], y = xy[2 * (first + k) + 1];
  int cell = film_cell(&c, x, y);
  int slot = cell_start[cell] + atomic_dec(&cell_count[cell]) - 1;
  float3 d = camera_ray_dir(camera, x, y);
  sorted[slot] = (float4)(d.x, d.y, d.z, as_float(k));
  entries[2 * k] = 0xffffffffu;
  entries[2 * k + 1] = 0xffffffffu;
}

/* The same result for positions already in pixel order, spp to a pixel (the
 * per-pixel sampling modes: sample g of the image lies in pixel g / spp): the
 * batch's own order is sorted, and the cell starts follow from the numbering. */
__kernel void firsthit_pixel_major(__global const CameraGpu* camera, __global const float* xy, long first, int count,
                                   int spp, int cells, __global int* cell_start, __global float4* sorted,
                                   __global uint* entries) {
  int k = get_global_id(0);
  if (k <= cells) cell_start[k] = (int)clamp((long)k * spp - first, 0L, (long)count);
  if (k >= count) return;
  float3 d = camera_ray_dir(camera, xy[2 * (first + k)], xy[2 * (first + k) + 1]);
  sorted[k] = (float4)(d.x, d.y, d.z, as_float(k));
  entries[2 * k] = 0xffffffffu;
  entries[2 * k + 1] = 0xffffffffu;
}

/* A plain triangle (no transform) is tested from its vertices; any other kind
 * through object_intersect, bounded by the host's world box of it (other_boxes,
 * 6 floats, infinite where it is unbounded). */
inline bool firsthit_plain_triangle(__global const ObjectGpu* ob) {
  return ob->type == OBJECT_TRIANGLE && ob->has_transform == 0;
}

inline int firsthit_prim(int item, int prims, __global const int* other_prims) {
  return item < prims ? item : other_prims[item - prims];
}

inline int firsthit_blocks(int4 r) {
  return r.z < r.x ? 0
                   : (r.z / FIRSTHIT_BLOCK - r.x / FIRSTHIT_BLOCK + 1) * (r.w / FIRSTHIT_BLOCK - r.y / FIRSTHIT_BLOCK + 1);
}

/* block_count[item]: the blocks its cells span (0 when culled); the host turns
 * them into pair_start by an exclusive scan. */
__kernel void firsthit_bound(__global const CameraGpu* camera, __global const ObjectGpu* objects, int prims,
                             __global const int* other_prims, __global const float* other_boxes, int others,
                             __global int4* cells, __global int* block_count) {
  int item = get_global_id(0);
  if (item >= prims + others) return;
  FilmProjector c = film_projector(camera);
  FilmHull hull = film_hull_empty();
  int4 r = (int4)(0, 0, -1, -1);
  if (item < prims) {
    __global const ObjectGpu* ob = &objects[item];
    if (firsthit_plain_triangle(ob))
      for (int i = 0; i < 3; ++i) film_hull_add(&c, load3g(ob->p + 3 * i), &hull);
  } else {
    __global const float* b = other_boxes + 6 * (item - prims);
    for (int i = 0; i < 8; ++i)
      film_hull_add(&c, (float3)(b[(i & 1) ? 3 : 0], b[(i & 2) ? 4 : 1], b[(i & 4) ? 5 : 2]), &hull);
  }
  int4 bounded;
  if ((hull.front > 0 || hull.near > 0 || hull.behind > 0) && film_hull_cells(&c, &hull, &bounded) != FILM_BOUNDS_CULLED)
    r = bounded;
  cells[item] = r;
  block_count[item] = firsthit_blocks(r);
}

__kernel void firsthit_emit(int items, __global const int4* cells, __global const int* pair_start,
                            __global int2* pairs) {
  int item = get_global_id(0);
  if (item >= items) return;
  int blocks = firsthit_blocks(cells[item]);
  int start = pair_start[item];
  for (int b = 0; b < blocks; ++b) pairs[start + b] = (int2)(item, b);
}

inline void firsthit_keep(__global uint* entries, int sample, float t, int prim, int pass) {
#ifdef PRISM_ZBUFFER_WIDE
  ulong key = ((ulong)as_uint(t) << 32) | (ulong)(uint)prim;
  atom_min((volatile __global ulong*)entries + sample, key);
#else
  if (pass == 0)
    atomic_min(&entries[2 * sample], as_uint(t));
  else if (entries[2 * sample] == as_uint(t))
    atomic_min(&entries[2 * sample + 1], (uint)prim);
#endif
}

__kernel void firsthit_raster(__global const CameraGpu* camera, __global const ObjectGpu* objects, int prims,
                              __global const int* other_prims, __global const int4* cells, int pair_count,
                              __global const int2* pairs, __global const int* cell_start,
                              __global const float4* sorted, int pass, __global uint* entries) {
  int k = get_global_id(0);
  if (k >= pair_count) return;
  int2 pair = pairs[k];
  int4 r = cells[pair.x];
  int prim = firsthit_prim(pair.x, prims, other_prims);
  int bx0 = r.x / FIRSTHIT_BLOCK, by0 = r.y / FIRSTHIT_BLOCK;
  int blocks_x = r.z / FIRSTHIT_BLOCK - bx0 + 1;
  int bx = bx0 + pair.y % blocks_x, by = by0 + pair.y / blocks_x;
  int x0 = max(r.x, bx * FIRSTHIT_BLOCK), x1 = min(r.z, bx * FIRSTHIT_BLOCK + FIRSTHIT_BLOCK - 1);
  int y0 = max(r.y, by * FIRSTHIT_BLOCK), y1 = min(r.w, by * FIRSTHIT_BLOCK + FIRSTHIT_BLOCK - 1);
  int width = camera->width;
  float3 o = load3g(camera->origin);
  float time = camera->shutter_open;
  __global const ObjectGpu* ob = &objects[prim];
  /* Two loops, not one with a branch inside: the plain triangle's is short. */
  if (pair.x < prims) {
    TriangleFromOrigin tri = triangle_from_origin(o, load3g(ob->p), load3g(ob->p + 3), load3g(ob->p + 6));
    for (int y = y0; y <= y1; ++y) {
      int end = cell_start[y * width + x1 + 1];
      for (int n = cell_start[y * width + x0]; n < end; ++n) {
        float4 s = sorted[n];
        float t, u, v;
        if (triangle_intersect_from(&tri, (float3)(s.x, s.y, s.z), 0.0f, PRISM_INF, &t, &u, &v))
          firsthit_keep(entries, as_int(s.w), t, prim, pass);
      }
    }
  } else {
    for (int y = y0; y <= y1; ++y) {
      int end = cell_start[y * width + x1 + 1];
      for (int n = cell_start[y * width + x0]; n < end; ++n) {
        float4 s = sorted[n];
        float t, u, v;
        if (object_intersect(ob, o, (float3)(s.x, s.y, s.z), time, 0.0f, PRISM_INF, &t, &u, &v))
          firsthit_keep(entries, as_int(s.w), t, prim, pass);
      }
    }
  }
}

__kernel void firsthit_resolve(__global const CameraGpu* camera, __global const ObjectGpu* objects,
                               __global const float* xy, int count, __global const uint* entries, int first,
                               __global HitGpu* hits) {
  int k = get_global_id(0);
  if (k >= count) return;
  int prim = (int)entries[2 * (first + k) + 1];
#ifdef PRISM_ZBUFFER_WIDE
  prim = (int)(((__global const ulong*)entries)[first + k] & 0xffffffffu);
#endif
  HitGpu hit;
  hit.t = PRISM_INF;
  hit.prim = -1;
  hit.u = 0.0f;
  hit.v = 0.0f;
  if (prim >= 0) {
    float3 o = load3g(camera->origin);
    float3 d = camera_ray_dir(camera, xy[2 * k], xy[2 * k + 1]);
    float t, u, v;
    if (object_intersect(&objects[prim], o, d, camera->shutter_open, 0.0f, PRISM_INF, &t, &u, &v)) {
      hit.t = t;
      hit.prim = prim;
      hit.u = u;
      hit.v = v;
    }
  }
  hits[k] = hit;
}
