/* 8-wide BVH traversal (host/accel/bvh_builder.cpp builds it). Per ray, the
 * near and far slab of each axis is chosen once by the sign of the direction,
 * a node's eight boxes are tested with float8 arithmetic into a hit mask, and
 * the children hit are visited nearest first: one goes on directly, the others
 * wait on a stack sorted by entry distance (PERF-NOTES' best strict variant).
 * Any-hit queries skip the sorting. */
#ifndef PRISM_ACCEL_BVH_H
#define PRISM_ACCEL_BVH_H

#include "common/math.h"
#include "accel/leaf_packets.h"
#include "shared/bvh_node_gpu.h"

/* A node's size in float8 words: the node, then with moving primitives its
 * children's boxes at shutter close, then with k-DOP bounds their diagonal
 * slabs (shared/bvh_node_gpu.h). */
#ifdef PRISM_BVH_MOTION
#define BVH_MOTION_WORDS 6
#else
#define BVH_MOTION_WORDS 0
#endif
#ifdef PRISM_BVH_KDOP
#define BVH_KDOP_WORDS 8
#else
#define BVH_KDOP_WORDS 0
#endif
#define BVH_KDOP_AT (7 + BVH_MOTION_WORDS)
#define BVH_NODE_WORDS (7 + BVH_MOTION_WORDS + BVH_KDOP_WORDS)

typedef struct BvhRay {
  float8 ox, oy, oz, ix, iy, iz;
  int nx, ny, nz; /* float8 index of the near slab per axis; far is index ^ 1 */
#ifdef PRISM_BVH_MOTION
  float8 s; /* the ray's time as a fraction of the shutter */
#endif
#ifdef PRISM_BVH_KDOP
  /* Per diagonal j: 1 / (d.n_j), the offsets added to its near and far slab
   * before that scaling (-o.n_j widened by a bound on its rounding), and the
   * near slab's index (2j or 2j + 1; far is index ^ 1). */
  float kinv[BVH_KDOP_DIAGONALS], knear[BVH_KDOP_DIAGONALS], kfar[BVH_KDOP_DIAGONALS];
  int kn[BVH_KDOP_DIAGONALS];
#endif
} BvhRay;

/* Fills *ray from the ray and inv = accel_safe_rcp(d), which the caller has
 * for the scene's box already (not returned by value: a struct this size
 * would come back through a hidden noalias pointer, whose inlining marks
 * Oclgrind cannot read). */
PRISM_HOT void bvh_ray(BvhRay* ray, float3 o, float3 d, float3 inv, float time, __global const float4* header) {
  BvhRay r;
#ifdef PRISM_BVH_MOTION
  float open = header[0].w, close = header[1].w;
  r.s = (float8)(close > open ? clamp((time - open) / (close - open), 0.0f, 1.0f) : 0.0f);
#endif
#ifdef PRISM_BVH_KDOP
  /* o.n_j is rounded twice, and a slab value less its projection loses what
   * their magnitudes allow: widening each slab by 2^-20 of the origin's and
   * the scene's magnitudes keeps the test conservative. */
  float3 a = fabs(o), b = fmax(fabs(header[0].xyz), fabs(header[1].xyz));
  float slack = ((a.x + a.y + a.z) + (b.x + b.y + b.z)) * 0x1p-20f;
  for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
    float dn = accel_diagonal_dot(j, d), on = accel_diagonal_dot(j, o);
    float ki = 1.0f / (fabs(dn) < 1e-30f ? copysign(1e-30f, dn) : dn);
    r.kinv[j] = ki;
    r.kn[j] = 2 * j + (ki >= 0.0f ? 0 : 1);
    r.knear[j] = -on + (ki >= 0.0f ? -slack : slack);
    r.kfar[j] = -on + (ki >= 0.0f ? slack : -slack);
  }
#endif
  r.ox = (float8)(o.x);
  r.oy = (float8)(o.y);
  r.oz = (float8)(o.z);
  r.ix = (float8)(inv.x);
  r.iy = (float8)(inv.y);
  r.iz = (float8)(inv.z);
  r.nx = inv.x >= 0.0f ? 0 : 1;
  r.ny = inv.y >= 0.0f ? 2 : 3;
  r.nz = inv.z >= 0.0f ? 4 : 5;
  *ray = r;
}

/* Bit i set when the ray meets child i's box within [tmin, tlimit]; entry
 * distances in *tn. The limit is scaled with the far distances: a primitive
 * whose t ties the best hit to the last bits (a vertex shared by several
 * triangles at a box corner) must still be reached. */
#ifdef PRISM_BVH_MOTION
#define BVH_SLAB(k) sb_mix(n[k], n[7 + (k)], r->s)
#else
#define BVH_SLAB(k) n[k]
#endif
PRISM_HOT int bvh_node_mask(__global const float8* n, const BvhRay* r, float tmin, float tlimit, float8* tn) {
  float8 nx = (BVH_SLAB(r->nx) - r->ox) * r->ix;
  float8 ny = (BVH_SLAB(r->ny) - r->oy) * r->iy;
  float8 nz = (BVH_SLAB(r->nz) - r->oz) * r->iz;
  float8 fx = (BVH_SLAB(r->nx ^ 1) - r->ox) * r->ix;
  float8 fy = (BVH_SLAB(r->ny ^ 1) - r->oy) * r->iy;
  float8 fz = (BVH_SLAB(r->nz ^ 1) - r->oz) * r->iz;
  float8 near_t = fmax(fmax(nx, ny), fmax(nz, (float8)(tmin)));
  float8 far_t = fmin(fmin(fmin(fx, fy), fz), (float8)(tlimit));
#ifdef PRISM_BVH_KDOP
  __global const float8* k = n + BVH_KDOP_AT;
  for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
    near_t = fmax(near_t, (k[r->kn[j]] + r->knear[j]) * r->kinv[j]);
    far_t = fmin(far_t, (k[r->kn[j] ^ 1] + r->kfar[j]) * r->kinv[j]);
  }
#endif
  far_t *= ACCEL_FAR_SCALE;
  int8 hit = near_t <= far_t;
  int8 bits = hit & (int8)(1, 2, 4, 8, 16, 32, 64, 128);
  int4 b4 = bits.lo | bits.hi;
  int2 b2 = b4.lo | b4.hi;
  *tn = near_t;
  return b2.x | b2.y;
}

/* Whether the ray can meet anything in the tree: the root's slab test on the
 * scene's box (the header words), which holds every child's box, both being
 * unions of the same primitive boxes. Taking the nearer and the farther of
 * each axis' two slabs gives an entry no later and an exit no earlier than the
 * sign-chosen slabs of the same box, and the arithmetic is monotone in the
 * box, so this turns away only rays the root would, before the walk's set-up:
 * most incoherent rays miss the scene (73% of prism-bench's random rays). Not
 * over moving primitives: their boxes at shutter open and close may lie
 * outside the swept box the scene's is made of (movingBoxes pushes them out),
 * and a blend of them rounds. */
PRISM_HOT bool bvh_meets_scene(__global const float4* header, float3 o, float3 inv, float tmin, float tlimit) {
#ifdef PRISM_BVH_MOTION
  return true;
#else
  float t0, t1;
  return accel_clip_scene(header, o, inv, tmin, tlimit, &t0, &t1);
#endif
}

PRISM_HOT void bvh_leaf_range(int code, int* start, int* count) {
  int x = ~code;
  *start = x >> BVH_LEAF_COUNT_BITS;
  *count = (x & (BVH_LEAF_MAX_PACKETS - 1)) + 1;
}

PRISM_HOT bool structure_closest(ACCEL_PARAMS, float3 o, float3 d, float time, float tmin, float tmax, HitGpu* hit) {
  accel_miss(hit);
  float best = tmax;
  unbounded_closest(geom, accel_unbounded, accel_unbounded_count, o, d, time, tmin, &best, hit);
  float3 inv = accel_safe_rcp(d);
  if (!bvh_meets_scene(accel_nodes, o, inv, tmin, best)) return hit->prim >= 0;
  BvhRay r;
  bvh_ray(&r, o, d, inv, time, accel_nodes);
  PacketRay pr = packet_ray(o, d, time);
  __global const float8* nodes = (__global const float8*)(accel_nodes + 2);
  int stack_code[PRISM_ACCEL_STACK];
  float stack_t[PRISM_ACCEL_STACK];
  int sp = 0;
  int code = 0; /* the root */
  for (;;) {
    if (code >= 0) {
      __global const float8* n = nodes + BVH_NODE_WORDS * code;
      float8 tn;
      int mask = bvh_node_mask(n, &r, tmin, best, &tn);
      if (mask) {
        __global const int* child = (__global const int*)(n + 6);
        int i = accel_ctz(mask);
        mask &= mask - 1;
        if (!mask) {
          code = child[i];
          continue;
        }
        /* Several children: all onto the stack, sorted so the nearest is on
         * top, then continue with it. */
        float tna[8];
        vstore8(tn, 0, tna);
        int base = sp;
        for (;;) {
          float t = tna[i];
          int j = sp++;
          while (j > base && stack_t[j - 1] < t) {
            stack_t[j] = stack_t[j - 1];
            stack_code[j] = stack_code[j - 1];
            --j;
          }
          stack_t[j] = t;
          stack_code[j] = child[i];
          if (!mask) break;
          i = accel_ctz(mask);
          mask &= mask - 1;
        }
        code = stack_code[--sp];
        continue;
      }
    } else {
      int start, count;
      bvh_leaf_range(code, &start, &count);
      for (int p = 0; p < count; ++p) packet_closest(accel_packets + start + p, &pr, o, d, tmin, &best, hit, geom);
    }
    while (sp > 0 && stack_t[sp - 1] > best * ACCEL_FAR_SCALE) --sp;
    if (sp == 0) break;
    code = stack_code[--sp];
  }
  return hit->prim >= 0;
}

PRISM_HOT float structure_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials, float3 o, float3 d, float time,
                                    float tmin, float tmax) {
  float carried = unbounded_transmittance(geom, materials, accel_unbounded, accel_unbounded_count, o, d, time, tmin, tmax);
  if (carried == 0.0f) return 0.0f;
  float3 inv = accel_safe_rcp(d);
  if (!bvh_meets_scene(accel_nodes, o, inv, tmin, tmax)) return carried;
  BvhRay r;
  bvh_ray(&r, o, d, inv, time, accel_nodes);
  PacketRay pr = packet_ray(o, d, time);
  __global const float8* nodes = (__global const float8*)(accel_nodes + 2);
  int stack[PRISM_ACCEL_STACK];
  int sp = 0;
  int code = 0;
  for (;;) {
    if (code >= 0) {
      __global const float8* n = nodes + BVH_NODE_WORDS * code;
      float8 tn;
      int mask = bvh_node_mask(n, &r, tmin, tmax, &tn);
      __global const int* child = (__global const int*)(n + 6);
      while (mask) {
        stack[sp++] = child[accel_ctz(mask)];
        mask &= mask - 1;
      }
    } else {
      int start, count;
      bvh_leaf_range(code, &start, &count);
      carried = leaf_transmittance(accel_packets + start, count, &pr, o, d, tmin, tmax, carried, 0, geom, materials);
      if (carried == 0.0f) return 0.0f;
    }
    if (sp == 0) break;
    code = stack[--sp];
  }
  return carried;
}

#endif
