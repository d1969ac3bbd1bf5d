/* BSP (kd-tree) traversal (host/accel/bsp_builder.cpp builds it), front to
 * back in the classic recursive form made iterative (Havran's TA_B, as in
 * pbrt): at each plane the ray's interval is split at the plane's parameter;
 * the near side is entered and the far side waits on the stack. The closest
 * hit is final once it lies before the exit of the leaf being searched.
 * Intervals are widened by ACCEL_CELL_EPS when deciding whether a side is
 * reached, so rounding never skips a cell the ray grazes. The leaf tests are
 * the octree's too (accel/cell_leaf.h). */
#ifndef PRISM_ACCEL_BSP_H
#define PRISM_ACCEL_BSP_H

#include "accel/cell_leaf.h"
#include "accel/leaf_packets.h"
#include "shared/bsp_node_gpu.h"

/* The far sides waiting, nearest on top, with the ray's interval in each;
 * the walk starts with the root alone. The descent keeps the cell, its
 * interval and the stack pointer in locals and touches this struct only to
 * push, pop and stop at a leaf: kept here during the descent they went
 * through memory at every step, which cost the BSP a third of its speed
 * (measured with prism-bench). */
typedef struct BspWalk {
  int sp;
  int stack_node[PRISM_ACCEL_STACK];
  float stack_t0[PRISM_ACCEL_STACK], stack_t1[PRISM_ACCEL_STACK];
} BspWalk;

/* Starts with the root and the ray's interval inside the scene's box; false
 * when the ray misses it. */
PRISM_HOT bool bsp_walk_start(BspWalk* w, __global const float4* header, float3 o, float3 inv, float tmin, float tmax) {
  float t0, t1;
  w->sp = 0;
  if (!accel_clip_scene(header, o, inv, tmin, tmax, &t0, &t1)) return false;
  w->stack_node[0] = 0;
  w->stack_t0[0] = t0;
  w->stack_t1[0] = t1;
  w->sp = 1;
  return true;
}

/* The next leaf along the ray; false when no cell is left that starts before
 * `cutoff` (the best hit so far). Descends from the nearest waiting cell,
 * pushing far sides. The ray's origin and reciprocal direction come as 3-element arrays. */
PRISM_HOT bool bsp_next_leaf(__global const BspNodeGpu* nodes, const float* org, const float* rcp, float cutoff,
                             BspWalk* w, CellLeaf* leaf) {
  int sp = w->sp;
  if (sp == 0) return false;
  --sp;
  int node = w->stack_node[sp];
  float t0 = w->stack_t0[sp], t1 = w->stack_t1[sp];
  if (accel_before(cutoff, t0)) return false;
  float t0e = t0 - ACCEL_CELL_EPS * fabs(t0);
  float t1e = t1 + ACCEL_CELL_EPS * fabs(t1);
  for (;;) {
    BspNodeGpu n = nodes[node];
    int axis = n.word & 3;
    if (axis == BSP_LEAF) {
      w->sp = sp;
      leaf->start = n.word >> 2;
      leaf->count = n.payload;
      leaf->t0 = t0;
      leaf->t1 = t1;
      return true;
    }
    /* Constant indices chosen by selects: as fast as org[axis] on PoCL, and a
     * GPU compiler can keep the arrays in registers, where a runtime index
     * would put them in scratch memory. (Selecting from the float3 lanes
     * instead made the BSP a quarter slower on PoCL.) */
    float ia = axis == 0 ? rcp[0] : (axis == 1 ? rcp[1] : rcp[2]);
    float oa = axis == 0 ? org[0] : (axis == 1 ? org[1] : org[2]);
    float tp = (as_float(n.payload) - oa) * ia;
    /* Moving up the axis, the ray is below the plane before tp, above after. */
    int above = n.word >> 2;
    int first = ia >= 0.0f ? node + 1 : above;
    int second = ia >= 0.0f ? above : node + 1;
    if (tp > t1e) {
      node = first;
    } else if (tp < t0e) {
      node = second;
    } else {
      float mid = min_t(max_t(tp, t0), t1);
      w->stack_node[sp] = second;
      w->stack_t0[sp] = mid;
      w->stack_t1[sp] = t1;
      ++sp;
      t1 = mid;
      t1e = t1 + ACCEL_CELL_EPS * fabs(t1);
      node = first;
    }
  }
}

PRISM_HOT bool structure_closest(ACCEL_PARAMS, float3 o, float3 d, float time, float tmin, float tmax, HitGpu* hit) {
  accel_miss(hit);
  float best = tmax;
  unbounded_closest(geom, accel_unbounded, accel_unbounded_count, o, d, time, tmin, &best, hit);
  float3 inv = accel_safe_rcp(d);
  BspWalk w;
  if (!bsp_walk_start(&w, accel_nodes, o, inv, tmin, best)) return hit->prim >= 0;
  PacketRay pr = packet_ray(o, d, time);
  __global const BspNodeGpu* nodes = (__global const BspNodeGpu*)(accel_nodes + 2);
  CellLeaf leaf;
  float org[3] = {o.x, o.y, o.z}, rcp[3] = {inv.x, inv.y, inv.z};
  while (bsp_next_leaf(nodes, org, rcp, best, &w, &leaf))
    if (cell_leaf_closest(&leaf, accel_packets, &pr, o, d, tmin, &best, hit, geom)) break;
  return hit->prim >= 0;
}

PRISM_HOT float structure_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials, float3 o, float3 d, float time,
                                    float tmin, float tmax) {
  float carried = unbounded_transmittance(geom, materials, accel_unbounded, accel_unbounded_count, o, d, time, tmin, tmax);
  if (carried == 0.0f) return 0.0f;
  float3 inv = accel_safe_rcp(d);
  BspWalk w;
  if (!bsp_walk_start(&w, accel_nodes, o, inv, tmin, tmax)) return carried;
  PacketRay pr = packet_ray(o, d, time);
  Mailbox mailbox;
  mailbox_init(&mailbox);
  __global const BspNodeGpu* nodes = (__global const BspNodeGpu*)(accel_nodes + 2);
  CellLeaf leaf;
  float org[3] = {o.x, o.y, o.z}, rcp[3] = {inv.x, inv.y, inv.z};
  while (carried > 0.0f && bsp_next_leaf(nodes, org, rcp, PRISM_INF, &w, &leaf))
    carried =
        cell_leaf_transmittance(&leaf, accel_packets, &pr, o, d, tmin, tmax, carried, &mailbox, geom, materials);
  return carried;
}

#endif
