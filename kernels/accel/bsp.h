/* BSP (kd-tree) traversal (host/accel/bsp_builder.cpp builds it), front to
 * back in the classic recursive form made iterative (Havran's TA_B, as in
 * pbrt): at each plane the ray's interval is split at the plane's parameter;
 * the near side is entered and the far side waits on the stack. The closest
 * hit is final once it lies before the exit of the leaf being searched.
 * Intervals are widened by ACCEL_CELL_EPS when deciding whether a side is
 * reached, so rounding never skips a cell the ray grazes. */
#ifndef PRISM_ACCEL_BSP_H
#define PRISM_ACCEL_BSP_H

#include "accel/leaf_packets.h"
#include "shared/bsp_node_gpu.h"

inline float bsp_axis(float3 v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

/* Descends from `node` over [*t0, *t1] to a leaf, pushing far sides. */
inline int bsp_descend(__global const BspNodeGpu* nodes, int node, float3 o, float3 inv, float* t0,
                       float* t1, int* stack_node, float* stack_t0, float* stack_t1, int* sp) {
  for (;;) {
    BspNodeGpu n = nodes[node];
    int axis = n.word & 3;
    if (axis == BSP_LEAF) return node;
    float ia = bsp_axis(inv, axis);
    float tp = (as_float(n.payload) - bsp_axis(o, axis)) * ia;
    /* Moving up the axis, the ray is below the plane before tp, above after. */
    int above = n.word >> 2;
    int first = ia >= 0.0f ? node + 1 : above;
    int second = ia >= 0.0f ? above : node + 1;
    float t0e = *t0 - ACCEL_CELL_EPS * fabs(*t0);
    float t1e = *t1 + ACCEL_CELL_EPS * fabs(*t1);
    if (tp > t1e) {
      node = first;
    } else if (tp < t0e) {
      node = second;
    } else {
      float mid = fmin(fmax(tp, *t0), *t1);
      stack_node[*sp] = second;
      stack_t0[*sp] = mid;
      stack_t1[*sp] = *t1;
      ++*sp;
      *t1 = mid;
      node = first;
    }
  }
}

inline bool accel_closest(ACCEL_PARAMS, float3 o, float3 d, float tmin, float tmax, HitGpu* hit) {
  accel_miss(hit);
  float best = tmax;
  unbounded_closest(objects, accel_unbounded, accel_unbounded_count, o, d, tmin, &best, hit);
  float3 inv = accel_safe_rcp(d);
  float t0, t1;
  if (!accel_clip_scene(accel_nodes, o, inv, tmin, best, &t0, &t1)) return hit->prim >= 0;
  PacketRay pr = packet_ray(o, d);
  __global const BspNodeGpu* nodes = (__global const BspNodeGpu*)(accel_nodes + 2);
  int stack_node[PRISM_ACCEL_STACK];
  float stack_t0[PRISM_ACCEL_STACK], stack_t1[PRISM_ACCEL_STACK];
  int sp = 0;
  int node = 0;
  for (;;) {
    node = bsp_descend(nodes, node, o, inv, &t0, &t1, stack_node, stack_t0, stack_t1, &sp);
    BspNodeGpu leaf = nodes[node];
    int start = leaf.word >> 2, count = leaf.payload;
    for (int p = 0; p < count; ++p) packet_closest(accel_packets + start + p, &pr, o, d, tmin, &best, hit, objects);
    if (accel_before(best, t1) || sp == 0) break;
    --sp;
    node = stack_node[sp];
    t0 = stack_t0[sp];
    t1 = stack_t1[sp];
    if (accel_before(best, t0)) break;
  }
  return hit->prim >= 0;
}

inline float accel_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials, float3 o, float3 d, float tmin,
                                 float tmax) {
  float carried =
      unbounded_transmittance(objects, materials, accel_unbounded, accel_unbounded_count, o, d, tmin, tmax);
  if (carried == 0.0f) return 0.0f;
  float3 inv = accel_safe_rcp(d);
  float t0, t1;
  if (!accel_clip_scene(accel_nodes, o, inv, tmin, tmax, &t0, &t1)) return carried;
  PacketRay pr = packet_ray(o, d);
  Mailbox mailbox;
  mailbox_init(&mailbox);
  __global const BspNodeGpu* nodes = (__global const BspNodeGpu*)(accel_nodes + 2);
  int stack_node[PRISM_ACCEL_STACK];
  float stack_t0[PRISM_ACCEL_STACK], stack_t1[PRISM_ACCEL_STACK];
  int sp = 0;
  int node = 0;
  for (;;) {
    node = bsp_descend(nodes, node, o, inv, &t0, &t1, stack_node, stack_t0, stack_t1, &sp);
    BspNodeGpu leaf = nodes[node];
    int start = leaf.word >> 2, count = leaf.payload;
    float lo = t0 - ACCEL_CELL_EPS * fabs(t0), hi = t1 + ACCEL_CELL_EPS * fabs(t1);
    for (int p = 0; p < count; ++p) {
      carried = packet_transmittance(accel_packets + start + p, &pr, o, d, tmin, tmax, carried, lo, hi, &mailbox,
                                     objects, materials);
      if (carried == 0.0f) return 0.0f;
    }
    if (sp == 0) break;
    --sp;
    node = stack_node[sp];
    t0 = stack_t0[sp];
    t1 = stack_t1[sp];
  }
  return carried;
}

#endif
