/* The octree's walk of eight rays together (accel/rays8.h has the lanes and
 * the leaf tests). A popped cell's content box is tested against all eight
 * rays at once, so the cell's loads, the stack and the branches are paid once
 * for eight rays; a lane goes on into the cell when its ray meets the box
 * before its best hit, as octree_next_leaf lets one ray in (accel/octree.h),
 * and the cell is passed over when no lane does.
 *
 * An inner cell pushes every stored octant, in an order that is front to back
 * for every ray whose direction has the signs of lane 0's: octant k ^ away
 * for k = 0..7, where `away` holds the axes along which lane 0 moves down (a
 * ray moving up along x can pass from an octant with x's bit clear into one
 * with it set, never back). Rays that share their direction's signs, as
 * neighbouring camera rays mostly do, so meet their cells front to back and
 * drop the cells behind their best hits at the box test. Lanes of other signs
 * meet them in another order and find the same hits: the hit rule (nearest t,
 * then the lower id) does not depend on the order.
 *
 * A lane tests the leaves whose boxes it meets within its search, a superset
 * of those its own walk reaches (which also drops the octants its ray does not
 * pass through the centre planes, and stops at the first cell past its best
 * hit): the extra leaves hold no hit nearer than the one its walk finds, but
 * for a hit at a grazing angle whose computed t lies outside every cell the
 * ray passes (accel/cell_leaf.h), which the extra leaves may find. As between
 * the structures, such a hit can differ; every other is octree_next_leaf's to
 * the bit.
 *
 * Shadow rays need no mailbox here: the packet settles only an opaque
 * primitive (found again in another cell, it gives 0 again) and sends a ray
 * that meets a semitransparent one alone, to structure_transmittance and its
 * mailbox (accel/packet_queries.h). */
#ifndef PRISM_ACCEL_OCTREE_PACKETS_H
#define PRISM_ACCEL_OCTREE_PACKETS_H

#include "accel/rays8.h"

#ifdef PRISM_OCTREE_PACKETS

/* The lanes that meet cell n's content box and do not enter it after their
 * best hit (by more than the slack octree_next_leaf allows: accel_before,
 * whose test is negated as it stands, NaN included); the box's far end
 * widened as octree_far widens it. */
PRISM_HOT int8 rays8_cell(__global const OctreeNodeGpu* n, const RayPacket* p) {
  float8 near_t, far_t;
  rays8_box((float3)(n->lo_x, n->lo_y, n->lo_z), (float3)(n->hi_x, n->hi_y, n->hi_z), p, &near_t, &far_t);
  far_t *= select((float8)(2.0f - ACCEL_FAR_SCALE), (float8)(ACCEL_FAR_SCALE), far_t >= 0.0f);
  return (near_t <= far_t) & !(p->best < near_t - ACCEL_CELL_EPS * fabs(near_t));
}

PRISM_HOT void structure_packet_walk(ACCEL_PARAMS, __global const MaterialGpu* materials, const RayLanes* r,
                                     RayPacket* p, int transmittance) {
  __global const OctreeNodeGpu* nodes = (__global const OctreeNodeGpu*)(accel_nodes + 2);
  const int away = (p->ix.s0 < 0.0f ? 1 : 0) | (p->iy.s0 < 0.0f ? 2 : 0) | (p->iz.s0 < 0.0f ? 4 : 0);
  int stack[PRISM_ACCEL_STACK];
  int sp = 0;
  stack[sp++] = 0; /* the root */
  while (sp > 0) {
    __global const OctreeNodeGpu* n = nodes + stack[--sp];
    int8 reach = rays8_cell(n, p);
    if (!any8_t(reach)) continue;
    int mask = n->child_mask;
    if (mask) {
      /* Farthest first, so that octant `away` is popped first. */
      for (int k = 7; k >= 0; --k) {
        int octant = k ^ away;
        stack[sp] = n->first + popcount(mask & ((1 << octant) - 1));
        sp += (mask >> octant) & 1;
      }
      continue;
    }
    rays8_leaf(accel_packets + n->first, n->packet_count, reach, r, p, geom, materials, transmittance);
    if (transmittance && !any8_t(rays8_open(p))) break;
  }
}

#endif
#endif
