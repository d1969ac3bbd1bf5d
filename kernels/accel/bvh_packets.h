/* The BVH's walk of eight rays together (accel/rays8.h has the lanes and the
 * leaf tests). A node's children are tested one by one against all eight rays
 * (where one ray tests all eight children at once, accel/bvh.h), so the
 * node's loads, the stack and the branches are paid once for eight rays. A
 * child goes on the stack when any ray meets it, with each ray's entry
 * distance, and is skipped when popped if no ray still needs it.
 *
 * Each lane tests only the leaves its own box tests admit, with the same
 * operations as structure_closest (a box's near and far planes taken by min
 * and max where the lanes' directions differ in sign: the same values), so the
 * hits are structure_closest's to the bit, on every ray the tests trace. What
 * the order can change, as between the structures, is a hit at a grazing
 * angle whose computed t lies before its own leaf's box (Moller-Trumbore's t
 * was measured 3e-5 early there, leaf_packets.h): a walk that has found a
 * nearer hit first culls that leaf.
 *
 * Not with a BVH over moving primitives' linear bounds (a node's boxes are
 * read at shutter open only) nor with k-DOP node bounds (whose slabs the walk
 * does not test): accel/packet_queries.h leaves the walk out there, and
 * host/render/ray_kernel.cpp never asks for packets. Moving triangles in a BVH
 * of swept boxes are tested ray by ray. */
#ifndef PRISM_ACCEL_BVH_PACKETS_H
#define PRISM_ACCEL_BVH_PACKETS_H

#include "accel/rays8.h"

#ifdef PRISM_BVH_PACKETS

/* Child i of node nf: the lanes of `reach` that meet its box within [tmin,
 * best], and their entry distances (+inf in the other lanes). */
PRISM_HOT int8 rays8_child(__global const float* nf, int i, int8 reach, const RayPacket* p, float8* entry) {
  float8 near_t, far_t;
  if (p->same_signs) {
    float8 ax = ((float8)(nf[p->nx + i]) - p->ox) * p->ix, bx = ((float8)(nf[(p->nx ^ 8) + i]) - p->ox) * p->ix;
    float8 ay = ((float8)(nf[p->ny + i]) - p->oy) * p->iy, by = ((float8)(nf[(p->ny ^ 8) + i]) - p->oy) * p->iy;
    float8 az = ((float8)(nf[p->nz + i]) - p->oz) * p->iz, bz = ((float8)(nf[(p->nz ^ 8) + i]) - p->oz) * p->iz;
    near_t = rays8_max(rays8_max(ax, ay), rays8_max(az, p->tmin));
    far_t = rays8_min(rays8_min(rays8_min(bx, by), bz), p->best);
  } else {
    rays8_box((float3)(nf[i], nf[16 + i], nf[32 + i]), (float3)(nf[8 + i], nf[24 + i], nf[40 + i]), p, &near_t, &far_t);
    far_t = rays8_min(far_t, p->best);
  }
  far_t *= ACCEL_FAR_SCALE;
  int8 meets = (near_t <= far_t) & reach;
  *entry = select((float8)(PRISM_INF), near_t, meets);
  return meets;
}


/* The walk both queries share: children stacked nearest on top with their
 * lanes' entry distances; a popped child skipped when none of those is within
 * its lane's p->best. Ends when the stack is empty or every lane is closed. */
PRISM_HOT void structure_packet_walk(ACCEL_PARAMS, __global const MaterialGpu* materials, const RayLanes* r, RayPacket* p,
                          int transmittance) {
  __global const float8* nodes = (__global const float8*)(accel_nodes + 2);
  int stack_code[PRISM_ACCEL_STACK];
  float8 stack_entry[PRISM_ACCEL_STACK];
  float stack_key[PRISM_ACCEL_STACK]; /* the least entry distance */
  int sp = 0;
  int code = 0; /* the root */
  /* The lanes whose own tests admit `code`: at the root, those that meet the
   * scene's box (bvh_meets_scene's test, eight rays at a time). */
  float8 t0, t1;
  rays8_clip_scene(accel_nodes, p, &t0, &t1);
  int8 reach = rays8_open(p) & (t0 <= t1);
  if (!any8_t(reach)) return;
  for (;;) {
    if (code >= 0) {
      __global const float* nf = (__global const float*)(nodes + BVH_NODE_WORDS * code);
      __global const int* child = (__global const int*)(nf + 48);
      int base = sp;
      for (int i = 0; i < BVH_WIDTH; ++i) {
        int c = child[i];
        if (c == 0) continue;
        float8 entry;
        if (!any8_t(rays8_child(nf, i, reach, p, &entry))) continue;
        float key = rays8_least(entry);
        int j = sp++;
        while (j > base && stack_key[j - 1] < key) {
          stack_key[j] = stack_key[j - 1];
          stack_entry[j] = stack_entry[j - 1];
          stack_code[j] = stack_code[j - 1];
          --j;
        }
        stack_key[j] = key;
        stack_entry[j] = entry;
        stack_code[j] = c;
      }
      if (sp == base + 1) { /* one child met: on with it */
        --sp;
        code = stack_code[sp];
        reach = stack_entry[sp] != (float8)(PRISM_INF);
        continue;
      }
    } else {
      int start, count;
      bvh_leaf_range(code, &start, &count);
      rays8_leaf(accel_packets + start, count, reach, r, p, geom, materials, transmittance);
      if (!any8_t(rays8_open(p))) break;
    }
    float8 limit = p->best * ACCEL_FAR_SCALE;
    while (sp > 0 && !any8_t(stack_entry[sp - 1] <= limit)) --sp;
    if (sp == 0) break;
    --sp;
    code = stack_code[sp];
    reach = stack_entry[sp] <= limit; /* as each ray's own walk culls */
  }
}


#endif
#endif
