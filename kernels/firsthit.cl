/* firsthit: the first-hit (Z-buffer) pass for a pinhole camera, scan conversion
 * on the device (host/render/firsthit.cpp drives it):
 *
 *   firsthit_count_cells, firsthit_sort_samples: the batch's sample positions
 *     sorted by film pixel (a counting sort; scan.cl in between), each stored
 *     with its primary ray's direction; positions that come in pixel order
 *     stay in it (firsthit_pixel_dirs stores their directions). The
 *     directions are stored by component (dirs: x of the batch's count of
 *     slots, then y, then z, then four floats of padding), so the raster loads
 *     four neighbouring samples' x in one vload4;
 *   firsthit_bound: per primitive, the film pixels its conservative bounds touch
 *     (sampling/film_bounds.h), how many 8x8-pixel blocks they span, and
 *     whether it is a triangle facing away from the camera, with the least t
 *     its tests can return (firsthit_least_t8);
 *   firsthit_emit: one (primitive, block) pair per such block, at offsets
 *     scanned from those counts (scan.cl), the pairs of triangles facing away
 *     after all the others;
 *   firsthit_raster: per pair, the ray test against every sample of the block's
 *     pixels inside the bounds, and an atomic minimum of (t, primitive) into the
 *     sample's depth + id entry;
 *   firsthit_row_far: between a raster launch over the other
 *     pairs and one over those facing away, the farthest depth kept in each
 *     row of each block, so that the second launch skips a row where the
 *     triangle's least t lies beyond it (on a closed mesh seen from outside,
 *     most of the rows of the half that faces away);
 *   firsthit_resolve: per sample, the winner's t, u, v by the tracer's own
 *     prim_intersect.
 *
 * The ray tests are the tracer's (prim_intersect; for a plain triangle its
 * triangle_intersect split at the origin, which gives the same bits), so a
 * sample's depth and id are what tracing its ray gives; equal depths go to the
 * lower primitive index, as in a brute-force loop over the scene. The minimum
 * does not depend on the order of the atomics, so neither does the result;
 * a skipped row is one where the triangle's every t would lose to the depth
 * already kept at each sample (depths only fall), so skipping changes nothing.
 *
 * Entries are 2 uints per sample, all bits set when empty (firsthit_place).
 * With 64-bit atomics (PRISM_ZBUFFER_WIDE) an entry is one ulong, t's bits
 * above the id: positive floats order as their bits, so one atom_min keeps the
 * nearest hit, lower id first. Without, two raster passes: the first keeps the
 * nearest t's bits in entry[0], the second the lowest id among the hits at
 * exactly that t in entry[1]. */
#ifdef PRISM_ZBUFFER_WIDE
#pragma OPENCL EXTENSION cl_khr_int64_extended_atomics : enable
#endif

#include "geometry/primitive.h"
#include "sampling/camera_ray.h"
#include "sampling/film_bounds.h"

#define FIRSTHIT_BLOCK 8 /* pixels per side of a raster block */
#define FIRSTHIT_BOUND_LANES 8 /* primitives a work-item of firsthit_bound (host: kFirstHitBoundLanes) */
#define FIRSTHIT_DIR_LANES 8 /* samples a work-item of firsthit_pixel_dirs (host: kFirstHitDirLanes) */

/* The film's width in 8x8 blocks (the last column of blocks may be partial). */
inline int firsthit_blocks_x(int width) { return (width + FIRSTHIT_BLOCK - 1) / FIRSTHIT_BLOCK; }

/* Cells (pixels) are numbered block by block, 8x8 pixels each, row by row
 * inside a block, so the samples of a block lie together once sorted by cell:
 * a (primitive, block) pair reads one run of them per row of the block, as it
 * does of samples in pixel order. Blocks past the film's edge hold empty cells. */
inline int firsthit_cell(int x, int y, int width) {
  int block = (y / FIRSTHIT_BLOCK) * firsthit_blocks_x(width) + x / FIRSTHIT_BLOCK;
  return block * FIRSTHIT_BLOCK * FIRSTHIT_BLOCK + (y % FIRSTHIT_BLOCK) * FIRSTHIT_BLOCK + x % FIRSTHIT_BLOCK;
}

/* The pixel of a film position (the far edges x = W, y = H to the last pixel). */
inline int firsthit_position_cell(__global const CameraGpu* camera, float x, float y) {
  int w = camera->width, h = camera->height;
  return firsthit_cell((int)floor(clamp(x, 0.0f, (float)w - 1.0f)), (int)floor(clamp(y, 0.0f, (float)h - 1.0f)), w);
}

/* Sample (x, y) into `slot`: its primary ray's direction, and an empty entry. */
inline void firsthit_place(__global const CameraGpu* camera, float x, float y, int slot, int count, __global float* dirs,
                           __global uint2* entries) {
  float3 d = camera_ray_dir(camera, x, y);
  dirs[slot] = d.x;
  dirs[count + slot] = d.y;
  dirs[2 * count + slot] = d.z;
  entries[slot] = (uint2)(0xffffffffu);
}

/* in_xy: where the batch's first position lies in xy. */
__kernel void firsthit_count_cells(__global const CameraGpu* camera, __global const float* xy, int in_xy, int count,
                                   __global int* cell_count) {
  int k = get_global_id(0);
  if (k >= count) return;
  atomic_inc(&cell_count[firsthit_position_cell(camera, xy[2 * (in_xy + k)], xy[2 * (in_xy + k) + 1])]);
}

/* Positions in any order: a counting sort. Within a cell the slots go in the
 * order the atomics come, which changes nothing: the raster's minimum does not
 * depend on order. cell_count comes back to zero (each sample takes a slot by
 * counting down), ready for the next batch. */
__kernel void firsthit_sort_samples(__global const CameraGpu* camera, __global const float* xy, int in_xy, int count,
                                    __global const int* cell_start, __global int* cell_count,
                                    __global float* dirs, __global int* slot_of, __global uint2* entries) {
  int k = get_global_id(0);
  if (k >= count) return;
  float x = xy[2 * (in_xy + k)], y = xy[2 * (in_xy + k) + 1];
  int cell = firsthit_position_cell(camera, x, y);
  int slot = cell_start[cell] + atomic_dec(&cell_count[cell]) - 1;
  firsthit_place(camera, x, y, slot, count, dirs, entries);
  slot_of[k] = slot;
}

/* Positions in pixel order, spp to a pixel (the per-pixel sampling modes:
 * sample g of the image lies in pixel g / spp): they need no sorting, since a
 * row of a block's pixels is already one run of samples. Slot k is the batch's
 * sample k; its direction is stored, its entry emptied. A work-item takes
 * FIRSTHIT_DIR_LANES samples, their directions in vector lanes: PoCL runs a
 * work-group's items one after another without vectorising across them, and
 * one at a time the directions' divisions and square roots were most of this
 * kernel. A last, partial group, and a group with a lane that needs the
 * normalisation's scaling (never at a camera's own directions), go one sample
 * at a time. */
__kernel void firsthit_pixel_dirs(__global const CameraGpu* camera, __global const float* xy, int in_xy, int count,
                                  __global float* dirs, __global uint2* entries) {
  int first = get_global_id(0) * FIRSTHIT_DIR_LANES;
  if (first >= count) return;
  float8 dx, dy, dz;
  if (count - first >= FIRSTHIT_DIR_LANES) {
    /* Lane by lane rather than a vload16's .even and .odd, whose shuffle
     * Oclgrind's check of uninitialised values takes for unset lanes. */
    __global const float* q = xy + 2 * (in_xy + first);
    float8 fx = (float8)(q[0], q[2], q[4], q[6], q[8], q[10], q[12], q[14]);
    float8 fy = (float8)(q[1], q[3], q[5], q[7], q[9], q[11], q[13], q[15]);
    if (camera_ray_dir8(camera, fx, fy, &dx, &dy, &dz)) {
      vstore8(dx, 0, dirs + first);
      vstore8(dy, 0, dirs + count + first);
      vstore8(dz, 0, dirs + 2 * count + first);
      vstore16((uint16)(0xffffffffu), 0, (__global uint*)(entries + first));
      return;
    }
  }
  for (int k = first; k < min(first + FIRSTHIT_DIR_LANES, count); ++k)
    firsthit_place(camera, xy[2 * (in_xy + k)], xy[2 * (in_xy + k) + 1], k, count, dirs, entries);
}

/* The slots [begin, end) of the samples in pixels x0..x1 of film row y: in
 * cell order (spp == 0) from the sort's cell starts; in pixel order, spp to a
 * pixel, in closed form, the batch's samples from number `first` on taking
 * slots 0, 1, ... (a row's run cut to the batch's count). */
inline int2 firsthit_row_slots(int x0, int x1, int y, int width, int spp, int first, int count,
                               __global const int* cell_start) {
  if (spp == 0) return (int2)(cell_start[firsthit_cell(x0, y, width)], cell_start[firsthit_cell(x1, y, width) + 1]);
  long row = (long)y * width;
  long begin = (row + x0) * spp - first, end = (row + x1 + 1) * spp - first;
  return (int2)((int)clamp(begin, 0L, (long)count), (int)clamp(end, 0L, (long)count));
}

/* A plain triangle (no transform: a static mesh's, or a triangle record) is
 * tested from its vertices; any other kind through prim_intersect, bounded by the host's world box of it (other_boxes,
 * 6 floats, infinite where it is unbounded). */
inline bool firsthit_plain_triangle(const Geometry* g, int id, float3* v0, float3* v1, float3* v2) {
  if (prim_is_compact(g, id)) {
    if (prim_mesh(g, id)->has_transform) return false;
    prim_triangle_vertices(g, prim_triangle_indices(g, id), v0, v1, v2);
    return true;
  }
  __global const ObjectGpu* ob = g->objects + id;
  if (ob->type != OBJECT_TRIANGLE || ob->has_transform) return false;
  *v0 = load3g(ob->p);
  *v1 = load3g(ob->p + 3);
  *v2 = load3g(ob->p + 6);
  return true;
}

inline int firsthit_prim(int item, int prims, __global const int* other_prims) {
  return item < prims ? item : other_prims[item - prims];
}

inline int firsthit_blocks(int4 r) {
  return r.z < r.x ? 0
                   : (r.z / FIRSTHIT_BLOCK - r.x / FIRSTHIT_BLOCK + 1) * (r.w / FIRSTHIT_BLOCK - r.y / FIRSTHIT_BLOCK + 1);
}

/* An item's cells cut to the film rows row_first..row_last that hold the
 * batch's samples (a batch in pixel order covers a band of the film; any
 * other, all of it), and the blocks they span (0 when culled). */
PRISM_HOT void firsthit_put_cells(const FilmProjector* c, const FilmHull* hull, int row_first, int row_last, int item,
                                  int items, int back, __global int4* cells, __global int* block_count) {
  int4 r = (int4)(0, 0, -1, -1);
  int4 bounded;
  if ((hull->front > 0 || hull->near > 0 || hull->behind > 0) &&
      film_hull_cells(c, hull, &bounded) != FILM_BOUNDS_CULLED && bounded.y <= row_last && bounded.w >= row_first)
    r = (int4)(bounded.x, max(bounded.y, row_first), bounded.z, min(bounded.w, row_last));
  cells[item] = r;
  block_count[item + (back ? items : 0)] = firsthit_blocks(r);
  block_count[item + (back ? 0 : items)] = 0;
}

/* A lower bound on every t the ray tests of firsthit_raster can return for a
 * triangle (edges e1, e2 from v0; tv = o - v0), eight triangles in lanes, over
 * the samples inside film box x0..x1, y0..y1. Only the tests that accept a hit
 * return a t, and their rays lie inside the box (sampling/film_bounds.h); it
 * is grown by a pixel and a half all the same, past every pixel it touches. t = e2.qv / det with e2.qv = tv.(e1 x e2),
 * and det = d.(e2 x e1), d = w / |w| for the unnormalised direction w = f + X r
 * + Y u. w.(e2 x e1) is linear in X and Y, so its largest size over the box is
 * at a corner; |w| is at least w.c / |c| for the box's central w = c, also
 * least at a corner. Each slack is 1e-4 of the size of what it covers, a
 * thousand times the rounding of the directions, of det and of e2.qv, so the
 * bound holds of the computed t, not only of the exact one. 0 where no bound
 * is known. */
PRISM_HOT float8 firsthit_least_t8(const FilmProjector* c, float8 tx, float8 ty, float8 tz, float8 ax, float8 ay,
                                   float8 az, float8 bx, float8 by, float8 bz, float8 x0, float8 y0, float8 x1,
                                   float8 y1) {
  float8 mx = by * az - bz * ay, my = bz * ax - bx * az, mz = bx * ay - by * ax; /* e2 x e1 */
  float8 e1n = fabs(ax) + fabs(ay) + fabs(az), e2n = fabs(bx) + fabs(by) + fabs(bz);
  float8 size = fabs(mx) + fabs(my) + fabs(mz) + e1n * e2n;
  float8 qv = fabs(tx * mx + ty * my + tz * mz) - 1e-4f * (fabs(tx) + fabs(ty) + fabs(tz)) * e1n * e2n;
  float8 fm = c->f.x * mx + c->f.y * my + c->f.z * mz, rm = c->r.x * mx + c->r.y * my + c->r.z * mz,
         um = c->u.x * mx + c->u.y * my + c->u.z * mz;
  float fn = fabs(c->f.x) + fabs(c->f.y) + fabs(c->f.z), rn = fabs(c->r.x) + fabs(c->r.y) + fabs(c->r.z),
        un = fabs(c->u.x) + fabs(c->u.y) + fabs(c->u.z);
  float8 xs[2] = {2.0f * (x0 - 1.5f) / c->w - 1.0f, 2.0f * (x1 + 1.5f) / c->w - 1.0f};
  float8 ys[2] = {1.0f - 2.0f * (y0 - 1.5f) / c->h, 1.0f - 2.0f * (y1 + 1.5f) / c->h};
  float8 cX = 0.5f * (xs[0] + xs[1]), cY = 0.5f * (ys[0] + ys[1]);
  float8 cx = c->f.x + cX * c->r.x + cY * c->u.x, cy = c->f.y + cX * c->r.y + cY * c->u.y,
         cz = c->f.z + cX * c->r.z + cY * c->u.z;
  float8 c_len = sqrt(cx * cx + cy * cy + cz * cz);
  float8 fc = c->f.x * cx + c->f.y * cy + c->f.z * cz, rc = c->r.x * cx + c->r.y * cy + c->r.z * cz,
         uc = c->u.x * cx + c->u.y * cy + c->u.z * cz;
  float8 most = (float8)(0.0f), least_w = (float8)(INFINITY);
  int8 finite = (int8)(-1); /* fmax and fmin pass a NaN by */
  for (int i = 0; i < 4; ++i) {
    float8 X = xs[i & 1], Y = ys[i >> 1];
    float8 w1 = fn + (1.0f + fabs(X)) * rn + (1.0f + fabs(Y)) * un; /* >= |w|, with X's rounding */
    float8 corner_det = fabs(fm + X * rm + Y * um) + 1e-4f * w1 * size;
    float8 corner_w = (fc + X * rc + Y * uc) / c_len - 1e-4f * w1;
    finite &= isfinite(corner_det) & isfinite(corner_w);
    most = fmax(most, corner_det);
    least_w = fmin(least_w, corner_w);
  }
  float8 t = qv / (most / least_w + 1e-4f * size) * 0.9999f;
  return select((float8)(0.0f), t, finite & (least_w > 0.0f) & (t > 0.0f) & (t < INFINITY));
}

/* block_count[item]: the blocks its cells span (0 when culled); the host turns
 * them into pair_start by an exclusive scan. Work-item k < groups bounds
 * primitives 8k to 8k + 7, their projections in float8 lanes (PoCL runs
 * work-items one after another, and one vertex at a time three divisions
 * each were most of this kernel: a third of the pass at 1.1M triangles); a
 * primitive that is not a plain triangle gets no cells here (it is bounded
 * among the others, by its host box). Each work-item past them bounds one of
 * the others. */
__kernel void firsthit_bound(__global const CameraGpu* camera, GEOMETRY_KERNEL_PARAMS,
                             __global const int* other_prims, __global const float* other_boxes, int others,
                             int row_first, int row_last, __global int4* cells, __global int* block_count,
                             __global float* least_t) {
  const Geometry g = GEOMETRY_INIT;
  const int prims = g.prim_count;
  const int groups = prims / FIRSTHIT_BOUND_LANES + (prims % FIRSTHIT_BOUND_LANES != 0);
  int k = get_global_id(0);
  if (k >= groups + others) return;
  FilmProjector c = film_projector(camera);
  if (k >= groups) {
    int item = prims + (k - groups);
    FilmHull hull = film_hull_empty();
    __global const float* b = other_boxes + 6 * (item - prims);
    for (int i = 0; i < 8; ++i)
      film_hull_add(&c, (float3)(b[(i & 1) ? 3 : 0], b[(i & 2) ? 4 : 1], b[(i & 4) ? 5 : 2]), &hull);
    firsthit_put_cells(&c, &hull, row_first, row_last, item, prims + others, 0, cells, block_count);
    return;
  }
  int first = k * FIRSTHIT_BOUND_LANES;
  float v[3][3][FIRSTHIT_BOUND_LANES];
  int plain[FIRSTHIT_BOUND_LANES];
  for (int l = 0; l < FIRSTHIT_BOUND_LANES; ++l) {
    float3 p[3] = {(float3)(0.0f), (float3)(0.0f), (float3)(0.0f)};
    plain[l] = first + l < prims && firsthit_plain_triangle(&g, first + l, &p[0], &p[1], &p[2]) ? -1 : 0;
    for (int i = 0; i < 3; ++i) {
      v[i][0][l] = p[i].x;
      v[i][1][l] = p[i].y;
      v[i][2][l] = p[i].z;
    }
  }
  int8 in = vload8(0, plain);

  int8 behind = (int8)(0), near = (int8)(0), front = (int8)(0);
  float8 x0 = (float8)(INFINITY), y0 = (float8)(INFINITY), x1 = (float8)(-INFINITY), y1 = (float8)(-INFINITY);
  for (int i = 0; i < 3; ++i)
    film_hull_add8(&c, vload8(0, v[i][0]), vload8(0, v[i][1]), vload8(0, v[i][2]), in, &behind, &near, &front,
                       &x0, &y0, &x1, &y1);
  /* Which way each triangle faces the camera: the sign of (o - v0).(e1 x e2),
   * the numerator of every t its tests compute (firsthit_raster's e2_qv, there
   * in another order of operations: a triangle seen edge-on may fall in either
   * class, which changes only the speed); and, for those facing away, the
   * least t their tests can return. A mesh wound inward is classed the other
   * way round: the same hits, no time saved. */
  float8 tx = (float8)(c.o.x) - vload8(0, v[0][0]), ty = (float8)(c.o.y) - vload8(0, v[0][1]),
         tz = (float8)(c.o.z) - vload8(0, v[0][2]);
  float8 ax = vload8(0, v[1][0]) - vload8(0, v[0][0]), ay = vload8(0, v[1][1]) - vload8(0, v[0][1]),
         az = vload8(0, v[1][2]) - vload8(0, v[0][2]);
  float8 bx = vload8(0, v[2][0]) - vload8(0, v[0][0]), by = vload8(0, v[2][1]) - vload8(0, v[0][1]),
         bz = vload8(0, v[2][2]) - vload8(0, v[0][2]);
  float8 facing = tx * (ay * bz - az * by) + ty * (az * bx - ax * bz) + tz * (ax * by - ay * bx);
  int8 back = in & (facing <= 0.0f);
  /* The box holds the whole triangle only where its three vertices lie in front. */
  int8 bounded = back & (front == (int8)(3));
  float8 least = (float8)(0.0f);
  if (any8_t(bounded))
    least = select(least, firsthit_least_t8(&c, tx, ty, tz, ax, ay, az, bx, by, bz, x0, y0, x1, y1), bounded);
  int ba[8], na[8], fa[8], back_a[8];
  float x0a[8], y0a[8], x1a[8], y1a[8];
  vstore8(back, 0, back_a);
  vstore8(least, 0, least_t + first);
  vstore8(behind, 0, ba);
  vstore8(near, 0, na);
  vstore8(front, 0, fa);
  vstore8(x0, 0, x0a);
  vstore8(y0, 0, y0a);
  vstore8(x1, 0, x1a);
  vstore8(y1, 0, y1a);
  for (int l = 0; l < FIRSTHIT_BOUND_LANES && first + l < prims; ++l) {
    FilmHull hull;
    hull.box = (float4)(x0a[l], y0a[l], x1a[l], y1a[l]);
    hull.behind = ba[l];
    hull.near = na[l];
    hull.front = fa[l];
    firsthit_put_cells(&c, &hull, row_first, row_last, first + l, prims + others, back_a[l], cells, block_count);
  }
}

/* Pairs of front-facing primitives first (block_count[item]), then those of
 * back-facing triangles (block_count[items + item]): one scan of both. */
__kernel void firsthit_emit(int items, __global const int4* cells, __global const int* block_count,
                            __global const int* pair_start, __global int2* pairs) {
  int item = get_global_id(0);
  if (item >= items) return;
  int blocks = firsthit_blocks(cells[item]);
  int start = block_count[item] ? pair_start[item] : pair_start[items + item];
  for (int b = 0; b < blocks; ++b) pairs[start + b] = (int2)(item, b);
}

/* The farthest kept depth of the batch's samples in each row of each 8x8
 * block of block rows by_first..by_last (row_far[8 * block + row]), as t's
 * bits (all bits set while a sample is empty; 0 for a row without samples),
 * for firsthit_raster's cull. One work-item a block: a batch in pixel order
 * holds samples only in the block rows of its pixels, and the raster reads
 * no other (firsthit_bound cuts its pairs to them). */
__kernel void firsthit_row_far(int width, int height, int by_first, int by_last, int spp, int first, int count,
                               __global const int* cell_start, __global const uint* entries,
                               __global uint* row_far) {
  int blocks_x = firsthit_blocks_x(width);
  int k = by_first * blocks_x + get_global_id(0);
  if (k >= (by_last + 1) * blocks_x) return;
  int bx = k % blocks_x, by = k / blocks_x;
  int x0 = bx * FIRSTHIT_BLOCK, x1 = min(width, x0 + FIRSTHIT_BLOCK) - 1;
  for (int row = 0; row < FIRSTHIT_BLOCK; ++row) {
    int y = by * FIRSTHIT_BLOCK + row;
    uint far = 0;
    int2 run = y < height ? firsthit_row_slots(x0, x1, y, width, spp, first, count, cell_start) : (int2)(0);
    for (int n = run.x; n < run.y; ++n) {
#ifdef PRISM_ZBUFFER_WIDE
      far = max(far, (uint)(((__global const ulong*)entries)[n] >> 32));
#else
      far = max(far, entries[2 * n]);
#endif
    }
    row_far[FIRSTHIT_BLOCK * k + row] = far;
  }
}

inline void firsthit_keep(__global uint* entries, int slot, float t, int prim, int pass) {
#ifdef PRISM_ZBUFFER_WIDE
  ulong key = ((ulong)as_uint(t) << 32) | (ulong)(uint)prim;
  atom_min((volatile __global ulong*)entries + slot, key);
#else
  if (pass == 0)
    atomic_min(&entries[2 * slot], as_uint(t));
  else if (entries[2 * slot] == as_uint(t))
    atomic_min(&entries[2 * slot + 1], (uint)prim);
#endif
}

__kernel void firsthit_raster(__global const CameraGpu* camera, GEOMETRY_KERNEL_PARAMS,
                              __global const int* other_prims, __global const int4* cells, int pair_first,
                              int pair_end, __global const int2* pairs, int spp, int first, int count,
                              __global const int* cell_start, __global const float* dirs, int pass,
                              __global const float* least_t, __global const uint* row_far, int cull,
                              __global uint* entries) {
  const Geometry g = GEOMETRY_INIT;
  const int prims = g.prim_count;
  int k = pair_first + get_global_id(0);
  if (k >= pair_end) return;
  int2 pair = pairs[k];
  int4 r = cells[pair.x];
  int prim = firsthit_prim(pair.x, prims, other_prims);
  int bx0 = r.x / FIRSTHIT_BLOCK, by0 = r.y / FIRSTHIT_BLOCK;
  int blocks_x = r.z / FIRSTHIT_BLOCK - bx0 + 1;
  int bx = bx0 + pair.y % blocks_x, by = by0 + pair.y / blocks_x;
  int x0 = max(r.x, bx * FIRSTHIT_BLOCK), x1 = min(r.z, bx * FIRSTHIT_BLOCK + FIRSTHIT_BLOCK - 1);
  int y0 = max(r.y, by * FIRSTHIT_BLOCK), y1 = min(r.w, by * FIRSTHIT_BLOCK + FIRSTHIT_BLOCK - 1);
  int width = camera->width;
  /* A back-facing triangle's pair, rasterised after the rest, skips each row
   * of its block where none of its tests could return a t as near as the
   * row's farthest kept depth (firsthit_least_t8; an empty sample's all-ones
   * bits read as NaN: never skipped), and the whole pair where that holds of
   * every row it spans. */
  float least = 0.0f;
  __global const uint* rows = row_far; /* the block's, row y at rows[y - top] */
  const int top = by * FIRSTHIT_BLOCK;
  if (cull) {
    least = least_t[pair.x];
    rows = row_far + FIRSTHIT_BLOCK * (by * firsthit_blocks_x(width) + bx);
    bool needed = false;
    for (int y = y0; y <= y1; ++y) needed |= !(least > as_float(rows[y - top]));
    if (!needed) return;
  }
  float3 o = load3g(camera->origin);
  float time = camera->shutter_open;
  /* Two loops, not one with a branch inside: the plain triangle's tests four
   * samples at once, triangle_intersect_from lane by lane (the same operations
   * in the same order, so the same bits; e2.qv is the same in every lane). */
  float3 v0, v1, v2;
  if (pair.x < prims && firsthit_plain_triangle(&g, prim, &v0, &v1, &v2)) { /* (firsthit_bound culled the rest) */
    TriangleFromOrigin tri = triangle_from_origin(o, v0, v1, v2);
    const float e2_qv = tri_dot(tri.e2, tri.qv);
    for (int y = y0; y <= y1; ++y) {
      if (cull && least > as_float(rows[y - top])) continue;
      int2 run = firsthit_row_slots(x0, x1, y, width, spp, first, count, cell_start);
      int end = run.y;
      for (int n = run.x; n < end; n += 4) {
        /* Lanes past the run read the next slots, or the padding: their
         * results are masked out below. */
        float4 dx = vload4(0, dirs + n), dy = vload4(0, dirs + count + n), dz = vload4(0, dirs + 2 * count + n);
        float4 pvx = dy * tri.e2.z - dz * tri.e2.y;
        float4 pvy = dz * tri.e2.x - dx * tri.e2.z;
        float4 pvz = dx * tri.e2.y - dy * tri.e2.x;
        float4 det = tri.e1.x * pvx + tri.e1.y * pvy + tri.e1.z * pvz;
        float4 inv_det = 1.0f / det;
        float4 u = (tri.tv.x * pvx + tri.tv.y * pvy + tri.tv.z * pvz) * inv_det;
        float4 v = (dx * tri.qv.x + dy * tri.qv.y + dz * tri.qv.z) * inv_det;
        float4 t = e2_qv * inv_det;
        int4 ok = ((int4)(n) + (int4)(0, 1, 2, 3) < (int4)(end)) & (det != 0.0f) & (u >= 0.0f) & (u <= 1.0f) &
                  (v >= 0.0f) & (u + v <= 1.0f) & (t > 0.0f) & (t < PRISM_INF);
        if (!any4_t(ok)) continue;
        if (ok.s0) firsthit_keep(entries, n, t.s0, prim, pass);
        if (ok.s1) firsthit_keep(entries, n + 1, t.s1, prim, pass);
        if (ok.s2) firsthit_keep(entries, n + 2, t.s2, prim, pass);
        if (ok.s3) firsthit_keep(entries, n + 3, t.s3, prim, pass);
      }
    }
  } else {
    for (int y = y0; y <= y1; ++y) {
      int2 run = firsthit_row_slots(x0, x1, y, width, spp, first, count, cell_start);
      for (int n = run.x; n < run.y; ++n) {
        float t, u, v;
        if (prim_intersect(&g, prim, o, (float3)(dirs[n], dirs[count + n], dirs[2 * count + n]), time, 0.0f, PRISM_INF,
                           &t, &u, &v))
          firsthit_keep(entries, n, t, prim, pass);
      }
    }
  }
}

/* The hit of the sample in `slot`: the winner its entry names, by the
 * tracer's own prim_intersect (a miss when no primitive won). */
inline HitGpu firsthit_slot_hit(const Geometry* g, __global const CameraGpu* camera, __global const float* dirs,
                                int batch, __global const uint* entries, int slot) {
#ifdef PRISM_ZBUFFER_WIDE
  int prim = (int)(((__global const ulong*)entries)[slot] & 0xffffffffu);
#else
  int prim = (int)entries[2 * slot + 1];
#endif
  HitGpu hit;
  hit.t = PRISM_INF;
  hit.prim = -1;
  hit.u = 0.0f;
  hit.v = 0.0f;
  if (prim >= 0) {
    float3 d = (float3)(dirs[slot], dirs[batch + slot], dirs[2 * batch + slot]);
    float t, u, v;
    if (prim_intersect(g, prim, load3g(camera->origin), d, camera->shutter_open, 0.0f, PRISM_INF, &t, &u, &v)) {
      hit.t = t;
      hit.prim = prim;
      hit.u = u;
      hit.v = v;
    }
  }
  return hit;
}

/* A chunk of the batch: first is the chunk's first sample within the batch,
 * whose slots are slot_of's (a sorted batch) or, in_order, the samples' own
 * numbers (a batch in pixel order). */
__kernel void firsthit_resolve(__global const CameraGpu* camera, GEOMETRY_KERNEL_PARAMS, int count, int in_order,
                               __global const int* slot_of, __global const float* dirs, int batch,
                               __global const uint* entries, int first, __global HitGpu* hits) {
  const Geometry g = GEOMETRY_INIT;
  int k = get_global_id(0);
  if (k >= count) return;
  int slot = in_order ? first + k : slot_of[first + k];
  hits[k] = firsthit_slot_hit(&g, camera, dirs, batch, entries, slot);
}
