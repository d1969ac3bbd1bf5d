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

/* The octants an inner cell's interval [t0, t1] passes, nearest first:
 * out_bits[k] (octant), [out_t0[k], out_t1[k]]; returns their number. */
inline int octree_segments(__global const OctreeNodeGpu* n, float3 o, float3 inv, float t0, float t1, int* out_bits,
                           float* out_t0, float* out_t1) {
  float3 tm = ((float3)(n->cx, n->cy, n->cz) - o) * inv;
  float t0e = t0 - ACCEL_CELL_EPS * fabs(t0);
  float t1e = t1 + ACCEL_CELL_EPS * fabs(t1);
  /* Octant just before entry: on the high side of a plane when moving up and
   * past it, or moving down and not yet there. */
  int bits = (inv.x >= 0.0f ? t0e >= tm.x : t0e < tm.x) ? 1 : 0;
  bits |= (inv.y >= 0.0f ? t0e >= tm.y : t0e < tm.y) ? 2 : 0;
  bits |= (inv.z >= 0.0f ? t0e >= tm.z : t0e < tm.z) ? 4 : 0;
  /* The three crossings, sorted. */
  float s0 = tm.x, s1 = tm.y, s2 = tm.z, tmp;
  int a0 = 1, a1 = 2, a2 = 4, ta;
  if (s0 > s1) { tmp = s0; s0 = s1; s1 = tmp; ta = a0; a0 = a1; a1 = ta; }
  if (s1 > s2) { tmp = s1; s1 = s2; s2 = tmp; ta = a1; a1 = a2; a2 = ta; }
  if (s0 > s1) { tmp = s0; s0 = s1; s1 = tmp; ta = a0; a0 = a1; a1 = ta; }
  float sv[3] = {s0, s1, s2};
  int av[3] = {a0, a1, a2};
  int count = 0;
  float prev = t0;
  for (int k = 0; k < 3; ++k) {
    float s = sv[k];
    if (!(s > t0e && s <= t1e)) continue;
    float end = fmin(fmax(s, t0), t1);
    out_bits[count] = bits;
    out_t0[count] = prev;
    out_t1[count] = end;
    ++count;
    prev = end;
    bits ^= av[k];
  }
  out_bits[count] = bits;
  out_t0[count] = prev;
  out_t1[count] = t1;
  return count + 1;
}

inline int octree_child(__global const OctreeNodeGpu* n, int octant) {
  return n->first_child + popcount(n->child_mask & ((1 << octant) - 1));
}

/* Pushes the octants of an inner cell farthest first, so the nearest is on top. */
inline void octree_push(__global const OctreeNodeGpu* n, float3 o, float3 inv, float t0, float t1, int* stack_node,
                        float* stack_t0, float* stack_t1, int* sp) {
  int bits[4];
  float s0[4], s1[4];
  int count = octree_segments(n, o, inv, t0, t1, bits, s0, s1);
  for (int k = count - 1; k >= 0; --k) {
    if (!((n->child_mask >> bits[k]) & 1)) continue;
    stack_node[*sp] = octree_child(n, bits[k]);
    stack_t0[*sp] = s0[k];
    stack_t1[*sp] = s1[k];
    ++*sp;
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
