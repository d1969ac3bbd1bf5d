/* The queries of eight rays at a time (extend_packets, occlude_packets), for
 * the structures that have a packet walk; PACKET_RAYS is defined where one
 * does. Each such structure's header defines
 *   void structure_packet_walk(ACCEL_PARAMS, __global const MaterialGpu* materials,
 *                              const RayLanes* r, RayPacket* p, int transmittance);
 * which runs the lanes' searches (closest hits in p->best, p->prim, p->u,
 * p->v; or transmittance in p->light and p->alone) through its cells or
 * nodes; the two queries below start and finish the lanes around it.
 *
 * Which rays share a packet is fixed by their place in the sample sequence
 * (slices and units are multiples of eight), so an image does not depend on
 * how a frame is split. */
#ifndef PRISM_ACCEL_PACKET_QUERIES_H
#define PRISM_ACCEL_PACKET_QUERIES_H

#include "accel/accel.h"

/* The BVH walk reads a node's boxes at one instant and does not test k-DOP
 * slabs (accel/bvh_packets.h). */
#if defined(PRISM_ACCEL_BVH) && !defined(PRISM_BVH_MOTION) && !defined(PRISM_BVH_KDOP)
#define PRISM_BVH_PACKETS
#define PACKET_RAYS 8
#elif defined(PRISM_ACCEL_OCTREE)
#define PRISM_OCTREE_PACKETS
#define PACKET_RAYS 8
#elif defined(PRISM_ACCEL_BSP)
#define PRISM_BSP_PACKETS
#define PACKET_RAYS 8
#endif

/* Each included outside any #if: the host's include resolver inlines a file
 * once, so its first inclusion must not sit in a skipped branch. */
#include "accel/rays8.h"
#include "accel/bvh_packets.h"
#include "accel/octree_packets.h"
#include "accel/bsp_packets.h"

#ifdef PACKET_RAYS

/* rays[0, lanes) (lanes <= 8) into hits[0, lanes), as accel_closest answers each. */
PRISM_HOT void rays8_closest(ACCEL_PARAMS, __global const RayGpu* rays, int lanes, __global HitGpu* hits) {
  RayLanes r;
  rays8_lanes(rays, lanes, &r);
  RayHits8 found;
  for (int l = 0; l < PACKET_RAYS; ++l) {
    HitGpu h;
    accel_miss(&h);
    found.best[l] = r.tmax[l];
    if (r.live & (1 << l)) {
      float3 o = rays8_origin(&r, l), d = rays8_dir(&r, l);
      unbounded_closest(geom, accel_unbounded, accel_unbounded_count, o, d, r.time[l], r.tmin[l], &found.best[l],
                        &h);
    }
    rays8_keep(&found, l, &h);
  }
  RayPacket p;
  rays8_packet(&r, found.best, &p);
  rays8_hits_in(&found, &p);
  if (r.live) structure_packet_walk(ACCEL_ARGS, 0, &r, &p, 0);
  rays8_hits_out(&p, &found);
  for (int l = 0; l < lanes; ++l) hits[l] = rays8_hit(&found, l);
}

/* The light rays[0, lanes) (lanes <= 8) carry, into carried[0, lanes), as
 * accel_transmittance answers each. */
PRISM_HOT void rays8_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials,
                                   __global const RayGpu* rays, int lanes, float* carried) {
  RayLanes r;
  rays8_lanes(rays, lanes, &r);
  float extent[8], light[8];
  int alone[8];
  for (int l = 0; l < PACKET_RAYS; ++l) {
    float c = 1.0f;
    if (r.live & (1 << l)) {
      float3 o = rays8_origin(&r, l), d = rays8_dir(&r, l);
      c = unbounded_transmittance(geom, materials, accel_unbounded, accel_unbounded_count, o, d, r.time[l],
                                  r.tmin[l], r.tmax[l]);
    }
    /* A plane that took some of the light sends the ray alone, and one that
     * took all of it settles it. */
    alone[l] = c != 0.0f && c != 1.0f ? -1 : 0;
    light[l] = c;
    extent[l] = c == 1.0f ? r.tmax[l] : RAYS8_CLOSED;
  }
  RayPacket p;
  rays8_packet(&r, extent, &p);
  p.light = vload8(0, light);
  p.alone = vload8(0, alone);
  if (any8_t(rays8_open(&p))) structure_packet_walk(ACCEL_ARGS, materials, &r, &p, 1);
  vstore8(p.light, 0, light);
  vstore8(p.alone, 0, alone);
  for (int l = 0; l < lanes; ++l) {
    float c = light[l];
    if (alone[l]) {
      float3 o = rays8_origin(&r, l), d = rays8_dir(&r, l);
      c = accel_transmittance(ACCEL_ARGS, materials, o, d, r.time[l], r.tmin[l], r.tmax[l]);
    }
    carried[l] = c;
  }
}


#endif
#endif
