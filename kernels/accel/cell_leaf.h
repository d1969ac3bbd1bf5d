/* What the octree and the BSP (kernels/accel/octree.h, bsp.h) do in a leaf.
 * Each structure walks its cells front to back with its own descent and
 * stack and hands every leaf it reaches over as a CellLeaf: the leaf's packets
 * and the stretch of the ray inside it.
 *
 * Cells do not overlap, so a closest hit that lies before the exit of the
 * leaf being searched is final, and a cell that starts after the best hit
 * need not be searched. A primitive may sit in several cells: shadow rays
 * count it in the first cell that finds it (Mailbox, leaf_packets.h). */
#ifndef PRISM_ACCEL_CELL_LEAF_H
#define PRISM_ACCEL_CELL_LEAF_H

#include "accel/leaf_packets.h"

typedef struct CellLeaf {
  int start, count; /* packets [start, start + count) */
  float t0, t1;     /* the ray's interval inside the leaf */
} CellLeaf;

/* Tests the leaf's packets for the closest hit; true when that hit is final. */
PRISM_HOT bool cell_leaf_closest(const CellLeaf* leaf, __global const TriPacketGpu* packets, const PacketRay* pr,
                                 float3 o, float3 d, float tmin, float* best, HitGpu* hit,
                                 const Geometry* geom) {
  for (int p = 0; p < leaf->count; ++p) packet_closest(packets + leaf->start + p, pr, o, d, tmin, best, hit, geom);
  return accel_before(*best, leaf->t1);
}

/* Multiplies in the k_trans of the leaf's primitives the segment meets that
 * the mailbox has not counted yet. */
PRISM_HOT float cell_leaf_transmittance(const CellLeaf* leaf, __global const TriPacketGpu* packets, const PacketRay* pr,
                                        float3 o, float3 d, float tmin, float tmax, float carried, Mailbox* mailbox,
                                        const Geometry* geom, __global const MaterialGpu* materials) {
  return leaf_transmittance(packets + leaf->start, leaf->count, pr, o, d, tmin, tmax, carried, mailbox, geom, materials);
}

#endif
