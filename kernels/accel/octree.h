/* Octree traversal (host/accel/octree_builder.cpp builds it): front to back
 * through the cells along the ray. Every cell stores the box of its contents
 * (kernels/shared/octree_node_gpu.h); the stretch of the ray inside that box
 * is the cell's interval, and a cell whose box the ray misses is skipped. In
 * an inner cell the ray's parameters at the three centre planes, sorted, cut
 * its interval into at most four pieces, one per octant it passes (in the
 * spirit of Revelles et al. 2000); the octants that exist are pushed farthest
 * first, so the stack holds cells in the order the ray meets them. Where
 * crossings round together, the octants of the other orders go on too
 * (docs/accel.md, "Crossings that round together").
 *
 * The stack holds cell indices only: a cell's interval is recomputed from its
 * box when it is entered. Since the boxes lie inside their cells, the entries
 * of the cells on the stack still grow from top to bottom (within
 * ACCEL_CELL_EPS among tied octants), so the first cell that starts after the
 * best hit by more than that ends the search.
 *
 * Interval ends are widened by ACCEL_CELL_EPS when deciding which octants a
 * ray passes, so rounding never skips an octant it grazes. */
#ifndef PRISM_ACCEL_OCTREE_H
#define PRISM_ACCEL_OCTREE_H

#include "accel/cell_leaf.h"
#include "accel/leaf_packets.h"
#include "shared/octree_node_gpu.h"

typedef struct OctreeWalk {
  int sp;
  int stack[PRISM_ACCEL_STACK];
} OctreeWalk;

/* Starts with the root alone; its content box clips the ray on entry. */
PRISM_HOT void octree_walk_start(OctreeWalk* w) {
  w->stack[0] = 0;
  w->sp = 1;
}

/* Writes octant `octant` on top of the stack and keeps it when `take` and the
 * octant exists: no branch, since which octants a ray passes is data the
 * branch predictor cannot learn. */
PRISM_HOT void octree_push1(__global const OctreeNodeGpu* n, int mask, int octant, bool take, OctreeWalk* w, int* sp) {
  w->stack[*sp] = n->first + popcount(mask & ((1 << octant) - 1));
  *sp += (take && ((mask >> octant) & 1)) ? 1 : 0;
}

/* Whether two sorted crossings, a <= b, lie within the slack accel_before
 * allows, so that rounding may have swapped them; false where b is none. */
PRISM_HOT bool octree_tie(float a, float b) { return b != PRISM_INF && b - a <= ACCEL_CELL_EPS * fabs(b); }

/* Pushes the octants an inner cell's interval [t0, t1] passes, farthest
 * first. The ray's parameters at the three centre planes, sorted, cut the
 * interval into at most four pieces; crossing a plane flips that axis' octant
 * bit. */
PRISM_HOT void octree_push(__global const OctreeNodeGpu* n, float3 o, float3 inv, float t0, float t1, OctreeWalk* w,
                           int* sp) {
  float3 tm = ((float3)(n->cx, n->cy, n->cz) - o) * inv;
  float t0e = t0 - ACCEL_CELL_EPS * fabs(t0);
  float t1e = t1 + ACCEL_CELL_EPS * fabs(t1);
  /* Octant just before entry: on the high side of a plane when moving up and
   * past it, or moving down and not yet there. */
  int bits = (inv.x >= 0.0f ? t0e >= tm.x : t0e < tm.x) ? 1 : 0;
  bits |= (inv.y >= 0.0f ? t0e >= tm.y : t0e < tm.y) ? 2 : 0;
  bits |= (inv.z >= 0.0f ? t0e >= tm.z : t0e < tm.z) ? 4 : 0;
  /* Crossings inside the interval, sorted by a network of selects; the others
   * sink to the end as +inf. Only their order matters: piece k exists when
   * crossing k-1 does. */
  float s0 = tm.x > t0e && tm.x <= t1e ? tm.x : PRISM_INF;
  float s1 = tm.y > t0e && tm.y <= t1e ? tm.y : PRISM_INF;
  float s2 = tm.z > t0e && tm.z <= t1e ? tm.z : PRISM_INF;
  int a0 = 1, a1 = 2, a2 = 4, ta;
  float ts;
  // clang-format off
  bool swap = s0 > s1;
  ts = swap ? s1 : s0; s1 = swap ? s0 : s1; s0 = ts;
  ta = swap ? a1 : a0; a1 = swap ? a0 : a1; a0 = ta;
  swap = s1 > s2;
  ts = swap ? s2 : s1; s2 = swap ? s1 : s2; s1 = ts;
  ta = swap ? a2 : a1; a2 = swap ? a1 : a2; a1 = ta;
  swap = s0 > s1;
  ts = swap ? s1 : s0; s1 = swap ? s0 : s1; s0 = ts;
  ta = swap ? a1 : a0; a1 = swap ? a0 : a1; a0 = ta;
  // clang-format on
  int b1 = bits ^ a0, b2 = b1 ^ a1, b3 = b2 ^ a2;
  /* Crossings this close may lie the other way round: the ray then passes an
   * octant of the other order instead, over a stretch too short for the
   * floats to place. Those octants are pushed too, each above the one it may
   * replace; a box the ray truly misses fails its clip on entry. Ties are
   * rare, so a branch the predictor learns skips them. */
  bool tie01 = octree_tie(s0, s1), tie12 = octree_tie(s1, s2), tie02 = octree_tie(s0, s2);
  int mask = n->child_mask;
  octree_push1(n, mask, b3, s2 != PRISM_INF, w, sp);
  octree_push1(n, mask, b2, s1 != PRISM_INF, w, sp);
  if (tie12 | tie02) {
    octree_push1(n, mask, bits ^ a1 ^ a2, tie02, w, sp);
    octree_push1(n, mask, b1 ^ a2, tie12, w, sp);
  }
  octree_push1(n, mask, b1, s0 != PRISM_INF, w, sp);
  if (tie01 | tie02) {
    octree_push1(n, mask, bits ^ a2, tie02, w, sp);
    octree_push1(n, mask, bits ^ a1, tie01, w, sp);
  }
  octree_push1(n, mask, bits, true, w, sp);
}

/* Widens a far distance as the BVH does (ACCEL_FAR_SCALE, Ize 2013), so that
 * float slab tests stay conservative; on either sign of t. */
PRISM_HOT float octree_far(float t) { return t * (t >= 0.0f ? ACCEL_FAR_SCALE : 2.0f - ACCEL_FAR_SCALE); }

/* The stretch [*t0, *t1] of the ray inside the cell's box, from tmin on;
 * false when the ray misses the box. */
PRISM_HOT bool octree_clip(__global const OctreeNodeGpu* n, float3 o, float3 inv, float tmin, float* t0, float* t1) {
  float3 a = ((float3)(n->lo_x, n->lo_y, n->lo_z) - o) * inv;
  float3 b = ((float3)(n->hi_x, n->hi_y, n->hi_z) - o) * inv;
  float3 near = min3_t(a, b), far = max3_t(a, b);
  *t0 = max_t(max_t(max_t(near.x, near.y), near.z), tmin);
  *t1 = octree_far(min_t(min_t(far.x, far.y), far.z));
  return *t0 <= *t1;
}

/* The next leaf along the ray; false when no cell is left that starts before
 * `cutoff` (the best hit so far). A cell is dropped only once its entry lies
 * beyond the cutoff by ACCEL_CELL_EPS (accel_before) or beyond the widened
 * tmax, so a primitive that ties the best hit to the last bits is still
 * reached. `ordered` false (where the order of the cells does not matter):
 * every stored octant is pushed and the boxes of those the ray misses drop
 * them on entry, which costs less than working out the octants the ray passes
 * (shadow rays 1.2-1.3x faster, measured with prism-bench). */
PRISM_HOT bool octree_next_leaf(__global const OctreeNodeGpu* nodes, float3 o, float3 inv, float tmin, float tmax,
                                float cutoff, bool ordered, OctreeWalk* w, CellLeaf* leaf) {
  const float tmax_far = octree_far(tmax);
  int sp = w->sp;
  for (;;) {
    if (sp == 0) return false;
    __global const OctreeNodeGpu* n = nodes + w->stack[--sp];
    float t0, t1;
    if (!octree_clip(n, o, inv, tmin, &t0, &t1)) continue;
    if (accel_before(cutoff, t0)) return false;
    t1 = min_t(t1, tmax_far);
    if (t0 > t1) continue;
    if (!n->child_mask) {
      w->sp = sp;
      leaf->start = n->first;
      leaf->count = n->packet_count;
      leaf->t0 = t0;
      leaf->t1 = t1;
      return true;
    }
    if (ordered) {
      octree_push(n, o, inv, t0, t1, w, &sp);
    } else {
      for (int c = popcount(n->child_mask) - 1; c >= 0; --c) w->stack[sp++] = n->first + c;
    }
  }
}

PRISM_HOT bool structure_closest(ACCEL_PARAMS, float3 o, float3 d, float time, float tmin, float tmax, HitGpu* hit) {
  accel_miss(hit);
  float best = tmax;
  unbounded_closest(geom, accel_unbounded, accel_unbounded_count, o, d, time, tmin, &best, hit);
  float3 inv = accel_safe_rcp(d);
  PacketRay pr = packet_ray(o, d, time);
  __global const OctreeNodeGpu* nodes = (__global const OctreeNodeGpu*)(accel_nodes + 2);
  OctreeWalk w;
  octree_walk_start(&w);
  CellLeaf leaf;
  while (octree_next_leaf(nodes, o, inv, tmin, tmax, best, true, &w, &leaf))
    if (cell_leaf_closest(&leaf, accel_packets, &pr, o, d, tmin, &best, hit, geom)) break;
  return hit->prim >= 0;
}

/* Shadow rays walk the cells in any order (every stored octant pushed, the
 * content boxes dropping the ones missed: cheaper than ordering them); the
 * mailbox counts each primitive once whatever the order. */
PRISM_HOT float structure_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials, float3 o, float3 d, float time,
                                    float tmin, float tmax) {
  float carried = unbounded_transmittance(geom, materials, accel_unbounded, accel_unbounded_count, o, d, time, tmin, tmax);
  if (carried == 0.0f) return 0.0f;
  float3 inv = accel_safe_rcp(d);
  PacketRay pr = packet_ray(o, d, time);
  __global const OctreeNodeGpu* nodes = (__global const OctreeNodeGpu*)(accel_nodes + 2);
  Mailbox mailbox;
  mailbox_init(&mailbox);
  OctreeWalk w;
  octree_walk_start(&w);
  CellLeaf leaf;
  while (carried > 0.0f && octree_next_leaf(nodes, o, inv, tmin, tmax, PRISM_INF, false, &w, &leaf))
    carried =
        cell_leaf_transmittance(&leaf, accel_packets, &pr, o, d, tmin, tmax, carried, &mailbox, geom, materials);
  return carried;
}

#endif
