/* The BSP's walk of eight rays together (accel/rays8.h has the lanes and the
 * leaf tests), in the manner of Wald's coherent kd-tree traversal: the
 * packet descends as one, each lane with its own interval. At a plane each
 * lane's interval is split as bsp_next_leaf splits one ray's (accel/bsp.h),
 * with the same operations: a lane goes to the near side, the far side or
 * both, and the packet enters the near side with the lanes that reach it and
 * leaves the far side on the stack with the others' intervals (a lane that
 * does not reach a side holds an empty interval there). So each lane reaches
 * the leaves its own walk reaches, with the same intervals, and drops a cell
 * that starts after its best hit, as its own walk stops there.
 *
 * Which side is near depends on the direction's sign along the plane's axis;
 * the lanes share it only where their directions share each axis's sign
 * (RayPacket.same_signs: neighbouring camera rays nearly always, the feelers
 * of a point under an area light seldom). A packet of mixed signs is walked
 * lane by lane, each ray alone through structure_closest (closest hits) or
 * sent to structure_transmittance at the end (p->alone). So the BSP's feelers
 * stay one ray a work-item in a render (render/ray_kernel.h); its packet
 * transmittance serves coherent shadow queries. */
#ifndef PRISM_ACCEL_BSP_PACKETS_H
#define PRISM_ACCEL_BSP_PACKETS_H

#include "accel/rays8.h"

#ifdef PRISM_BSP_PACKETS

/* A lane's empty interval: no cell holds any of it. */
#define BSP8_EMPTY_T0 PRISM_INF
#define BSP8_EMPTY_T1 (-PRISM_INF)

/* The lanes whose interval [t0, t1] is not empty and does not start after
 * their best hit (accel_before, negated as it stands). */
PRISM_HOT int8 bsp8_live(float8 t0, float8 t1, const RayPacket* p) {
  return (t0 <= t1) & !(p->best < t0 - ACCEL_CELL_EPS * fabs(t0));
}

/* Each lane alone, for a packet whose directions differ in sign. */
PRISM_HOT void bsp8_one_by_one(ACCEL_PARAMS, const RayLanes* r, RayPacket* p, int transmittance) {
  if (transmittance) {
    p->alone |= rays8_open(p);
    p->best = (float8)(RAYS8_CLOSED);
    return;
  }
  RayHits8 hits;
  rays8_hits_out(p, &hits);
  for (int l = 0; l < PACKET_RAYS; ++l) {
    if (!(r->live & (1 << l))) continue;
    HitGpu h;
    /* The whole query again, planes included: the one-ray walk's answer. */
    structure_closest(ACCEL_ARGS, rays8_origin(r, l), rays8_dir(r, l), r->time[l], r->tmin[l], r->tmax[l], &h);
    if (h.prim >= 0) hits.best[l] = h.t;
    rays8_keep(&hits, l, &h);
  }
  rays8_hits_in(&hits, p);
}

PRISM_HOT void structure_packet_walk(ACCEL_PARAMS, __global const MaterialGpu* materials, const RayLanes* r,
                                     RayPacket* p, int transmittance) {
  if (!p->same_signs) {
    bsp8_one_by_one(ACCEL_ARGS, r, p, transmittance);
    return;
  }
  __global const BspNodeGpu* nodes = (__global const BspNodeGpu*)(accel_nodes + 2);
  float8 t0, t1;
  rays8_clip_scene(accel_nodes, p, &t0, &t1);
  /* The near side along each axis, the same for every lane. */
  const int up[3] = {p->ix.s0 >= 0.0f, p->iy.s0 >= 0.0f, p->iz.s0 >= 0.0f};
  int stack_node[PRISM_ACCEL_STACK];
  float8 stack_t0[PRISM_ACCEL_STACK], stack_t1[PRISM_ACCEL_STACK];
  int sp = 0;
  int node = 0;
  for (;;) {
    int8 live = bsp8_live(t0, t1, p);
    if (any8_t(live)) {
      t0 = select((float8)(BSP8_EMPTY_T0), t0, live);
      t1 = select((float8)(BSP8_EMPTY_T1), t1, live);
      BspNodeGpu n = nodes[node];
      int axis = n.word & 3;
      if (axis != BSP_LEAF) {
        float8 ia = axis == 0 ? p->ix : (axis == 1 ? p->iy : p->iz);
        float8 oa = axis == 0 ? p->ox : (axis == 1 ? p->oy : p->oz);
        float8 tp = ((float8)(as_float(n.payload)) - oa) * ia;
        float8 t0e = t0 - ACCEL_CELL_EPS * fabs(t0), t1e = t1 + ACCEL_CELL_EPS * fabs(t1);
        int above = n.word >> 2;
        bool ascending = axis == 0 ? up[0] : (axis == 1 ? up[1] : up[2]);
        int first = ascending ? node + 1 : above;
        int second = ascending ? above : node + 1;
        /* As bsp_next_leaf: past the interval, the first side only; before
         * it, the second only; else both, split at tp clamped to it. */
        int8 first_only = tp > t1e, second_only = !first_only & (tp < t0e);
        int8 both = live & !first_only & !second_only;
        float8 mid = fmin(fmax(tp, t0), t1);
        int8 to_first = live & !second_only, to_second = live & !first_only;
        if (!any8_t(to_first)) { /* every lane on the second side alone, its interval as it was */
          node = second;
          continue;
        }
        if (any8_t(to_second)) {
          stack_node[sp] = second;
          stack_t0[sp] = select((float8)(BSP8_EMPTY_T0), select(t0, mid, both), to_second);
          stack_t1[sp] = select((float8)(BSP8_EMPTY_T1), t1, to_second);
          ++sp;
        }
        t0 = select(t0, (float8)(BSP8_EMPTY_T0), second_only);
        t1 = select(select(t1, mid, both), (float8)(BSP8_EMPTY_T1), second_only);
        node = first;
        continue;
      }
      rays8_leaf(accel_packets + (n.word >> 2), n.payload, live, r, p, geom, materials, transmittance);
    }
    if (sp == 0) break;
    --sp;
    node = stack_node[sp];
    t0 = stack_t0[sp];
    t1 = stack_t1[sp];
  }
}

#endif
#endif
