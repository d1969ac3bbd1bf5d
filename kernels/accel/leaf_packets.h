/* What every tree's traversal shares: the 4-wide leaf packet tests (closest
 * hit and transmittance), the brute-force list of unbounded primitives
 * (planes), the hit acceptance rule and the mailbox that counts a primitive
 * referenced by several cells once.
 *
 * Hit rule, the same in every structure: the nearest t wins and an exact tie
 * goes to the lower primitive id. `none` scans in id order with a strict
 * t < best, which picks the same one, so all four answer alike.
 * The packet test is triangle_intersect (geometry/triangle.h) written for
 * four triangles at once, operation for operation (no contraction, see
 * common/math.h), so it returns the same t, u and v bits. */
#ifndef PRISM_ACCEL_LEAF_PACKETS_H
#define PRISM_ACCEL_LEAF_PACKETS_H

#include "geometry/primitive.h"
#include "shared/material_gpu.h"
#include "shared/tri_packet_gpu.h"

/* Ize, "Robust BVH ray traversal" (JCGT 2013): a far distance scaled by
 * 1 + 2 gamma(3) keeps float slab tests conservative. */
#define ACCEL_FAR_SCALE 1.0000004f
/* Relative slack on cell intervals of the spatial subdivisions, so rounding
 * never skips a cell a ray grazes. */
#define ACCEL_CELL_EPS 1e-6f

/* In the spatial subdivisions, the closest hit is final once it lies before
 * the exit t1 of the cell searched, and cells entered after `best` need no
 * search; both with the same slack, since a primitive in a later cell may hit
 * a few ulps before that cell's computed entry. */
PRISM_HOT bool accel_before(float best, float t) { return best < t - ACCEL_CELL_EPS * fabs(t); }

/* 1/d without infinities: a zero component becomes a tiny one of the same
 * sign, so (plane - o) * inv is never 0 * inf = NaN. */
PRISM_HOT float3 accel_safe_rcp(float3 d) {
  const float tiny = 1e-30f;
  float3 s = (float3)(fabs(d.x) < tiny ? copysign(tiny, d.x) : d.x, fabs(d.y) < tiny ? copysign(tiny, d.y) : d.y,
                      fabs(d.z) < tiny ? copysign(tiny, d.z) : d.z);
  return 1.0f / s;
}

PRISM_HOT int accel_ctz(int x) { return 31 - clz(x & -x); }

/* Diagonal j of the "set of normals" slabs (shared/bvh_node_gpu.h), (1,1,1),
 * (1,1,-1), (1,-1,1) or (-1,1,1), dotted with v. */
PRISM_HOT float accel_diagonal_dot(int j, float3 v) {
  return j == 0 ? v.x + v.y + v.z : j == 1 ? v.x + v.y - v.z : j == 2 ? v.x - v.y + v.z : -v.x + v.y + v.z;
}

PRISM_HOT float accel_lane(float4 v, int k) { return k == 0 ? v.x : k == 1 ? v.y : k == 2 ? v.z : v.w; }

/* Whether the ray can meet lane k's object between tmin and tlimit by its
 * diagonal slabs (host/accel/leaf_packets.cpp; "set of normals" object
 * bounds). o.n and the slab values are rounded, so each slab is widened by
 * 2^-20 of their magnitudes, as the BVH's are (accel/bvh.h). */
PRISM_HOT bool packet_lane_slabs_meet(__global const TriPacketGpu* pk, int k, float3 o, float3 d, float tmin,
                                      float tlimit) {
  /* Read as float4 words, as packet_intersect reads them: a float pointer
   * cast from the record is folded into an index of its first member array
   * (v0x[4]), which a bounds checker then sees overrun. */
  __global const float4* q = (__global const float4*)pk;
  float3 a = fabs(o);
  float magnitude = a.x + a.y + a.z;
  float t0 = tmin, t1 = tlimit;
  for (int j = 0; j < 4; ++j) {
    float lo = accel_lane(q[2 * j], k), hi = accel_lane(q[2 * j + 1], k);
    float slack = (magnitude + fabs(lo) + fabs(hi)) * 0x1p-20f;
    float on = accel_diagonal_dot(j, o), dn = accel_diagonal_dot(j, d);
    float inv = 1.0f / (fabs(dn) < 1e-30f ? copysign(1e-30f, dn) : dn);
    float ta = (lo - slack - on) * inv, tb = (hi + slack - on) * inv;
    t0 = fmax(t0, fmin(ta, tb));
    t1 = fmin(t1, fmax(ta, tb));
  }
  return t0 <= t1 * ACCEL_FAR_SCALE;
}

typedef struct PacketRay {
  float4 ox, oy, oz, dx, dy, dz;
  float time; /* for moving objects, which are tested one by one */
} PacketRay;

PRISM_HOT PacketRay packet_ray(float3 o, float3 d, float time) {
  PacketRay r;
  r.time = time;
  r.ox = (float4)(o.x);
  r.oy = (float4)(o.y);
  r.oz = (float4)(o.z);
  r.dx = (float4)(d.x);
  r.dy = (float4)(d.y);
  r.dz = (float4)(d.z);
  return r;
}

PRISM_HOT void accel_miss(HitGpu* hit) {
  hit->t = PRISM_INF;
  hit->prim = -1;
  hit->u = 0.0f;
  hit->v = 0.0f;
}

PRISM_HOT void accel_accept(float t, float u, float v, int prim, float* best, HitGpu* hit) {
  if (t < *best || (t == *best && hit->prim >= 0 && prim < hit->prim)) {
    *best = t;
    hit->t = t;
    hit->prim = prim;
    hit->u = u;
    hit->v = v;
  }
}

/* Moller-Trumbore in lanes of vector type V (mask type M): four triangles
 * against one ray (packet_intersect) or one triangle against eight rays
 * (accel/rays8.h), the same operations in the same order, so both give
 * the same t, u, v bits. Reads V v0x..v0z, e1x..e2z, ox..oz and dx..dz;
 * declares V t, u, v and M hit, the lanes met within (tmin, tlimit] (or
 * (tmin, tlimit) when `closed` is 0). The mask is a select, not ~reject &
 * in_range, which Oclgrind 21.10 computed wrongly (lanes of -2, hits with
 * v = 8 accepted). */
#define MOLLER_TRUMBORE_LANES(V, M, tmin, tlimit, closed)                              \
  V pvx = dy * e2z - dz * e2y;                                                       \
  V pvy = dz * e2x - dx * e2z;                                                       \
  V pvz = dx * e2y - dy * e2x;                                                       \
  V det = e1x * pvx + e1y * pvy + e1z * pvz;                                         \
  V inv_det = 1.0f / det;                                                            \
  V tvx = ox - v0x, tvy = oy - v0y, tvz = oz - v0z;                                  \
  V u = (tvx * pvx + tvy * pvy + tvz * pvz) * inv_det;                               \
  V qvx = tvy * e1z - tvz * e1y;                                                     \
  V qvy = tvz * e1x - tvx * e1z;                                                     \
  V qvz = tvx * e1y - tvy * e1x;                                                     \
  V v = (dx * qvx + dy * qvy + dz * qvz) * inv_det;                                  \
  V t = (e2x * qvx + e2y * qvy + e2z * qvz) * inv_det;                               \
  M reject = (det == 0.0f) | (u < 0.0f) | (u > 1.0f) | (v < 0.0f) | (u + v > 1.0f); \
  M in_range = (t > (tmin)) & ((closed) ? (t <= (tlimit)) : (t < (tlimit)));         \
  M hit = select(in_range, (M)(0), reject)

/* Moller-Trumbore on four triangles: t, u, v and a lane mask of hits in
 * (tmin, tlimit] (or (tmin, tlimit) when `closed` is 0). */
PRISM_HOT int4 packet_intersect(__global const TriPacketGpu* pk, const PacketRay* r, float tmin, float tlimit,
                                int closed, float4* t_out, float4* u_out, float4* v_out) {
  __global const float4* q = (__global const float4*)pk;
  float4 v0x = q[0], v0y = q[1], v0z = q[2];
  float4 e1x = q[3], e1y = q[4], e1z = q[5];
  float4 e2x = q[6], e2y = q[7], e2z = q[8];
  float4 ox = r->ox, oy = r->oy, oz = r->oz, dx = r->dx, dy = r->dy, dz = r->dz;
  MOLLER_TRUMBORE_LANES(float4, int4, tmin, tlimit, closed);
  *t_out = t;
  *u_out = u;
  *v_out = v;
  return hit;
}

/* The ray of a moving packet: mapped into its object's space at the ray's time
 * (t, u and v are the same in both spaces). */
PRISM_HOT PacketRay moving_packet_ray(__global const TriPacketGpu* pk, const PacketRay* r, float3 o, float3 d,
                                      const Geometry* geom) {
  float m[12];
  prim_world_to_object(geom, pk->prim[0] & ~PACKET_MOVING, r->time, m);
  return packet_ray(xform_point(m, o), xform_vector(m, d), r->time);
}

/* Whether pk is a moving packet (only scenes with moving objects have any). */
PRISM_HOT bool packet_moves(__global const TriPacketGpu* pk) {
#ifdef PRISM_MOTION
  int p0 = pk->prim[0];
  return p0 >= 0 && (p0 & PACKET_MOVING) != 0;
#else
  return false;
#endif
}

/* Whether pk holds only still triangles (and empty lanes): what the tests
 * that take a packet's triangles in vector lanes take whole; a packet with
 * other kinds of objects, or moving, goes through packet_closest or
 * packet_transmittance. */
PRISM_HOT bool packet_still_triangles(__global const TriPacketGpu* pk) {
  return !any4_t(vload4(0, pk->prim) < -1) && !packet_moves(pk);
}

PRISM_HOT void packet_closest(__global const TriPacketGpu* pk, const PacketRay* r, float3 o, float3 d, float tmin,
                              float* best, HitGpu* hit, const Geometry* geom) {
  float4 t, u, v;
  int4 ok, prim = vload4(0, pk->prim);
  if (packet_moves(pk)) {
    PacketRay moved = moving_packet_ray(pk, r, o, d, geom);
    ok = packet_intersect(pk, &moved, tmin, *best, 1, &t, &u, &v);
    prim = select(prim, prim & (int4)(~PACKET_MOVING), prim >= 0); /* ids of the filled lanes */
  } else if (any4_t(prim >= 0)) {
    ok = packet_intersect(pk, r, tmin, *best, 1, &t, &u, &v);
  } else { /* spheres, boxes or transformed objects only: no triangle to test */
    ok = (int4)(0);
  }
  if (any4_t(ok)) {
    float ta[4], ua[4], va[4];
    int oka[4], pa[4];
    vstore4(t, 0, ta);
    vstore4(u, 0, ua);
    vstore4(v, 0, va);
    vstore4(ok, 0, oka);
    vstore4(prim, 0, pa);
    for (int k = 0; k < 4; ++k)
      if (oka[k]) accel_accept(ta[k], ua[k], va[k], pa[k], best, hit);
  }
  if (any4_t(prim < -1)) {
    for (int k = 0; k < 4; ++k) {
      int id = -pk->prim[k] - 2;
      if (id < 0) continue;
      float tt, uu, vv;
#ifdef PRISM_OBJECT_KDOP
      if (!packet_lane_slabs_meet(pk, k, o, d, tmin, nextafter(*best, PRISM_INF))) continue;
#endif
      /* nextafter: an exact tie must reach accel_accept */
      if (prim_intersect(geom, id, o, d, r->time, tmin, nextafter(*best, PRISM_INF), &tt, &uu, &vv))
        accel_accept(tt, uu, vv, id, best, hit);
    }
  }
}

/* k_trans of a primitive; NULL materials (plain occlusion queries): opaque. */
PRISM_HOT float accel_transmit(__global const MaterialGpu* materials, const Geometry* geom, int prim) {
  return materials ? materials[prim_material(geom, prim)].transmit : 0.0f;
}

/* Shadow rays in the spatial subdivisions, where one primitive sits in several
 * cells and a walk may find it in each: a hit counts in the first cell that
 * finds it, and the mailbox, which remembers every primitive counted on the
 * ray, keeps it from counting again, in whatever order the cells come.
 * Counting by where the hit lies instead (the cell whose interval holds its t)
 * loses hits: Moller-Trumbore's t on a millimetre triangle seen at a grazing
 * angle from several units away was measured 3e-5 (relative) before the
 * triangle's own bounds. And a mailbox that forgot its oldest entries counted
 * a large triangle again after more than that many other semitransparent hits.
 * A ray that meets more than MAILBOX_SIZE semitransparent primitives is taken
 * as blocked: at k_trans 0.9 it carries at most 0.9^64 = 0.001 of the light. */
#define MAILBOX_SIZE 64
typedef struct Mailbox {
  int ids[MAILBOX_SIZE];
  int filled;
} Mailbox;

PRISM_HOT void mailbox_init(Mailbox* m) { m->filled = 0; }

/* 1 the first time `prim` is offered, 0 after that, -1 when the mailbox is
 * full and `prim` is new. */
PRISM_HOT int mailbox_first(Mailbox* m, int prim) {
  for (int i = 0; i < m->filled; ++i)
    if (m->ids[i] == prim) return 0;
  if (m->filled == MAILBOX_SIZE) return -1;
  m->ids[m->filled++] = prim;
  return 1;
}

/* `carried` after a hit on prim; the mailbox only for the spatial
 * subdivisions (NULL: every hit counts, as in the BVH, which holds each
 * primitive once). */
PRISM_HOT float accel_count_hit(float carried, int prim, Mailbox* mailbox, const Geometry* geom,
                                __global const MaterialGpu* materials) {
  float k = accel_transmit(materials, geom, prim);
  if (k == 0.0f) return 0.0f; /* opaque: blocked wherever it is */
  if (mailbox) {
    int first = mailbox_first(mailbox, prim);
    if (first < 0) return 0.0f;
    if (!first) return carried;
  }
  return carried * k;
}

PRISM_HOT float packet_transmittance(__global const TriPacketGpu* pk, const PacketRay* r, float3 o, float3 d,
                                     float tmin, float tmax, float carried, Mailbox* mailbox,
                                     const Geometry* geom, __global const MaterialGpu* materials) {
  float4 t, u, v;
  int4 ok, prim = vload4(0, pk->prim);
  if (packet_moves(pk)) {
    PacketRay moved = moving_packet_ray(pk, r, o, d, geom);
    ok = packet_intersect(pk, &moved, tmin, tmax, 0, &t, &u, &v);
    prim = select(prim, prim & (int4)(~PACKET_MOVING), prim >= 0); /* ids of the filled lanes */
  } else if (any4_t(prim >= 0)) {
    ok = packet_intersect(pk, r, tmin, tmax, 0, &t, &u, &v);
  } else { /* spheres, boxes or transformed objects only: no triangle to test */
    ok = (int4)(0);
  }
  if (any4_t(ok)) {
    int oka[4], pa[4];
    vstore4(ok, 0, oka);
    vstore4(prim, 0, pa);
    for (int k = 0; k < 4; ++k) {
      if (!oka[k]) continue;
      carried = accel_count_hit(carried, pa[k], mailbox, geom, materials);
      if (carried == 0.0f) return 0.0f;
    }
  }
  if (any4_t(prim < -1)) {
    for (int k = 0; k < 4; ++k) {
      int id = -pk->prim[k] - 2;
      if (id < 0) continue;
      float tt, uu, vv;
#ifdef PRISM_OBJECT_KDOP
      if (!packet_lane_slabs_meet(pk, k, o, d, tmin, tmax)) continue;
#endif
      if (prim_intersect(geom, id, o, d, r->time, tmin, tmax, &tt, &uu, &vv)) {
        carried = accel_count_hit(carried, id, mailbox, geom, materials);
        if (carried == 0.0f) return 0.0f;
      }
    }
  }
  return carried;
}

/* Two float4 as one float8, lane by lane: Oclgrind 21.10 crashes on a
 * vector built of two halves, (float8)(float4, float4) or (int8)(int4,
 * int4), under -cl-opt-disable. */
PRISM_HOT float8 pair8(float4 lo, float4 hi) { return (float8)(lo.x, lo.y, lo.z, lo.w, hi.x, hi.y, hi.z, hi.w); }

/* The lanes of a pair's eight triangles met within (tmin, tmax) by the
 * ray r: packet_intersect's operations lane for lane, so the same answers. */
PRISM_HOT int8 packet_pair_met(__global const TriPacketGpu* pk, const PacketRay* r, float tmin, float tmax) {
  __global const float4* a = (__global const float4*)pk;
  __global const float4* b = (__global const float4*)(pk + 1);
  float8 v0x = pair8(a[0], b[0]), v0y = pair8(a[1], b[1]), v0z = pair8(a[2], b[2]);
  float8 e1x = pair8(a[3], b[3]), e1y = pair8(a[4], b[4]), e1z = pair8(a[5], b[5]);
  float8 e2x = pair8(a[6], b[6]), e2y = pair8(a[7], b[7]), e2z = pair8(a[8], b[8]);
  float8 ox = (float8)(r->ox.x), oy = (float8)(r->oy.x), oz = (float8)(r->oz.x);
  float8 dx = (float8)(r->dx.x), dy = (float8)(r->dy.x), dz = (float8)(r->dz.x);
  MOLLER_TRUMBORE_LANES(float8, int8, tmin, tmax, 0);
  return hit;
}

/* What a leaf's `count` packets leave of `carried`. Shadow rays take the
 * packets two at a time: packets p and p + 1 in the low and high lanes of
 * float8 (a leaf averages about three packets, and a float8 costs the CPU's
 * vector unit about what a float4 does). Only pairs of still triangles; a
 * pair with a moving packet or an object lane goes packet by packet. The
 * hits are counted in the order packet by packet would count them (a
 * product's bits depend on the order of its factors, and the mailbox on the
 * order of its ids). Closest hits stay packet by packet: in pairs, random
 * rays ran 5-12% slower (docs/accel.md, "Leaves"). On a GPU, where a
 * work-item's lanes run one after another, a pair costs what its two packets
 * do, with more registers live: not measured there yet. */
PRISM_HOT float leaf_transmittance(__global const TriPacketGpu* pk, int count, const PacketRay* r, float3 o,
                                   float3 d, float tmin, float tmax, float carried, Mailbox* mailbox,
                                   const Geometry* geom, __global const MaterialGpu* materials) {
  int p = 0;
  for (; p + 1 < count && carried > 0.0f; p += 2) {
    if (!(packet_still_triangles(pk + p) && packet_still_triangles(pk + p + 1))) {
      carried = packet_transmittance(pk + p, r, o, d, tmin, tmax, carried, mailbox, geom, materials);
      if (carried > 0.0f)
        carried = packet_transmittance(pk + p + 1, r, o, d, tmin, tmax, carried, mailbox, geom, materials);
      continue;
    }
    int8 ok = packet_pair_met(pk + p, r, tmin, tmax);
    if (any8_t(ok)) {
      int oka[8];
      vstore8(ok, 0, oka);
      for (int k = 0; k < 8; ++k) {
        if (!oka[k]) continue;
        carried = accel_count_hit(carried, pk[p + (k >> 2)].prim[k & 3], mailbox, geom, materials);
        if (carried == 0.0f) return 0.0f;
      }
    }
  }
  if (p < count && carried > 0.0f)
    carried = packet_transmittance(pk + p, r, o, d, tmin, tmax, carried, mailbox, geom, materials);
  return carried;
}

/* Planes and other unbounded primitives: tested by every ray. */
PRISM_HOT void unbounded_closest(const Geometry* geom, __global const int* list, int count, float3 o,
                                 float3 d, float time, float tmin, float* best, HitGpu* hit) {
  for (int i = 0; i < count; ++i) {
    int id = list[i];
    float t, u, v;
    if (prim_intersect(geom, id, o, d, time, tmin, nextafter(*best, PRISM_INF), &t, &u, &v))
      accel_accept(t, u, v, id, best, hit);
  }
}

PRISM_HOT float unbounded_transmittance(const Geometry* geom, __global const MaterialGpu* materials,
                                        __global const int* list, int count, float3 o, float3 d, float time,
                                        float tmin, float tmax) {
  float carried = 1.0f;
  for (int i = 0; i < count && carried > 0.0f; ++i) {
    int id = list[i];
    float t, u, v;
    if (prim_intersect(geom, id, o, d, time, tmin, tmax, &t, &u, &v)) carried *= accel_transmit(materials, geom, id);
  }
  return carried;
}

/* Entry and exit of the ray in the box at accel_nodes[0..1]: false if it misses. */
PRISM_HOT bool accel_clip_scene(__global const float4* header, float3 o, float3 inv, float tmin, float tmax, float* t0,
                                float* t1) {
  float3 lo = header[0].xyz, hi = header[1].xyz;
  float3 a = (lo - o) * inv, b = (hi - o) * inv;
  float3 n = fmin(a, b), f = fmax(a, b);
  float tn = fmax(fmax(n.x, n.y), fmax(n.z, tmin));
  float tf = fmin(fmin(fmin(f.x, f.y), f.z), tmax) * ACCEL_FAR_SCALE;
  *t0 = tn;
  *t1 = tf;
  return tn <= tf;
}

#endif
