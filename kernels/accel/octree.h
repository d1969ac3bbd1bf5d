/* Octree traversal (host/accel/octree_builder.cpp builds it): front to back
 * through the cells along the ray. In an inner cell the ray's parameters at
 * the three centre planes, sorted, cut its interval into at most four pieces,
 * one per octant it passes (in the spirit of Revelles et al. 2000); the nearest
 * existing octant is entered and the others wait on the stack with their
 * intervals. The closest hit is final as soon as it lies before the exit of
 * the cell being searched, since every cell still waiting is farther.
 * Interval ends are widened by ACCEL_CELL_EPS so rounding never skips an
 * octant the ray grazes. */
#ifndef PRISM_ACCEL_OCTREE_H
#define PRISM_ACCEL_OCTREE_H

#include "accel/leaf_packets.h"
#include "shared/octree_node_gpu.h"

inline int octree_child(__global const OctreeNodeGpu* n, int octant) {
  return n->first_child + popcount(n->child_mask & ((1 << octant) - 1));
}

inline void octree_push1(__global const OctreeNodeGpu* n, int octant, float lo, float hi, int* stack_node,
                         float* stack_t0, float* stack_t1, int* sp) {
  if (!((n->child_mask >> octant) & 1)) return;
  stack_node[*sp] = octree_child(n, octant);
  stack_t0[*sp] = lo;
  stack_t1[*sp] = hi;
  ++*sp;
}

/* Pushes the octants an inner cell's interval [t0, t1] passes, farthest
 * first, so the nearest is on top. The ray's parameters at the three centre
 * planes, sorted, cut the interval into at most four pieces; crossing a plane
 * flips that axis' octant bit. */
inline void octree_push(__global const OctreeNodeGpu* n, float3 o, float3 inv, float t0, float t1, int* stack_node,
                        float* stack_t0, float* stack_t1, int* sp) {
  float3 tm = ((float3)(n->cx, n->cy, n->cz) - o) * inv;
  float t0e = t0 - ACCEL_CELL_EPS * fabs(t0);
  float t1e = t1 + ACCEL_CELL_EPS * fabs(t1);
  /* Octant just before entry: on the high side of a plane when moving up and
   * past it, or moving down and not yet there. */
  int bits = (inv.x >= 0.0f ? t0e >= tm.x : t0e < tm.x) ? 1 : 0;
  bits |= (inv.y >= 0.0f ? t0e >= tm.y : t0e < tm.y) ? 2 : 0;
  bits |= (inv.z >= 0.0f ? t0e >= tm.z : t0e < tm.z) ? 4 : 0;
  /* Crossings inside the interval, sorted; the others sink to the end as +inf. */
  float s0 = tm.x > t0e && tm.x <= t1e ? tm.x : PRISM_INF;
  float s1 = tm.y > t0e && tm.y <= t1e ? tm.y : PRISM_INF;
  float s2 = tm.z > t0e && tm.z <= t1e ? tm.z : PRISM_INF;
  int a0 = 1, a1 = 2, a2 = 4, ta;
  float tmp;
  if (s0 > s1) { tmp = s0; s0 = s1; s1 = tmp; ta = a0; a0 = a1; a1 = ta; }
  if (s1 > s2) { tmp = s1; s1 = s2; s2 = tmp; ta = a1; a1 = a2; a2 = ta; }
  if (s0 > s1) { tmp = s0; s0 = s1; s1 = tmp; ta = a0; a0 = a1; a1 = ta; }
  float e0 = fmin(fmax(s0, t0), t1), e1 = fmin(fmax(s1, t0), t1), e2 = fmin(fmax(s2, t0), t1);
  int b1 = bits ^ a0, b2 = b1 ^ a1, b3 = b2 ^ a2;
  if (s2 != PRISM_INF) {
    octree_push1(n, b3, e2, t1, stack_node, stack_t0, stack_t1, sp);
    octree_push1(n, b2, e1, e2, stack_node, stack_t0, stack_t1, sp);
    octree_push1(n, b1, e0, e1, stack_node, stack_t0, stack_t1, sp);
    octree_push1(n, bits, t0, e0, stack_node, stack_t0, stack_t1, sp);
  } else if (s1 != PRISM_INF) {
    octree_push1(n, b2, e1, t1, stack_node, stack_t0, stack_t1, sp);
    octree_push1(n, b1, e0, e1, stack_node, stack_t0, stack_t1, sp);
    octree_push1(n, bits, t0, e0, stack_node, stack_t0, stack_t1, sp);
  } else if (s0 != PRISM_INF) {
    octree_push1(n, b1, e0, t1, stack_node, stack_t0, stack_t1, sp);
    octree_push1(n, bits, t0, e0, stack_node, stack_t0, stack_t1, sp);
  } else {
    octree_push1(n, bits, t0, t1, stack_node, stack_t0, stack_t1, sp);
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
  __global const OctreeNodeGpu* nodes = (__global const OctreeNodeGpu*)(accel_nodes + 2);
  int stack_node[PRISM_ACCEL_STACK];
  float stack_t0[PRISM_ACCEL_STACK], stack_t1[PRISM_ACCEL_STACK];
  int sp = 0;
  int node = 0;
  for (;;) {
    __global const OctreeNodeGpu* n = nodes + node;
    if (n->child_mask) {
      octree_push(n, o, inv, t0, t1, stack_node, stack_t0, stack_t1, &sp);
    } else {
      int start = n->packet_start, count = n->packet_count;
      for (int p = 0; p < count; ++p) packet_closest(accel_packets + start + p, &pr, o, d, tmin, &best, hit, objects);
      if (accel_before(best, t1)) break;
    }
    if (sp == 0) break;
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
  __global const OctreeNodeGpu* nodes = (__global const OctreeNodeGpu*)(accel_nodes + 2);
  int stack_node[PRISM_ACCEL_STACK];
  float stack_t0[PRISM_ACCEL_STACK], stack_t1[PRISM_ACCEL_STACK];
  int sp = 0;
  int node = 0;
  for (;;) {
    __global const OctreeNodeGpu* n = nodes + node;
    if (n->child_mask) {
      octree_push(n, o, inv, t0, t1, stack_node, stack_t0, stack_t1, &sp);
    } else {
      int start = n->packet_start, count = n->packet_count;
      float lo = t0 - ACCEL_CELL_EPS * fabs(t0), hi = t1 + ACCEL_CELL_EPS * fabs(t1);
      for (int p = 0; p < count; ++p) {
        carried = packet_transmittance(accel_packets + start + p, &pr, o, d, tmin, tmax, carried, lo, hi, &mailbox,
                                       objects, materials);
        if (carried == 0.0f) return 0.0f;
      }
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
