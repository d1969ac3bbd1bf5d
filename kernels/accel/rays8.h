/* Eight rays in the lanes of float8 words (ray packets, Wald et al. 2001), for
 * rays that travel alike: the camera rays of neighbouring samples, the shadow
 * rays of one shaded point. Lane l of every float8 is ray l. This file holds
 * what every structure's packet walk shares (accel/packet_queries.h says
 * which structures have one): the lanes, the packet, and the tests of a leaf
 * packet's triangles against the eight rays.
 *
 * The triangle test is packet_intersect's, operation for operation
 * (MOLLER_TRUMBORE_LANES), and the hit rule (nearest t, then the lower id)
 * does not depend on the order in which primitives come, so a walk that tests
 * in each lane the leaves that ray's own walk tests finds its hits to the bit.
 * The triangle test divides a float8 where packet_intersect divides a float4:
 * the same bits where division rounds correctly, which prism asks of every
 * device that offers it (and PoCL does).
 *
 * Transmittance is a product whose bits depend on the order of its factors,
 * and a packet meets primitives in another order than one ray does. So the
 * packet settles only what no order changes: a ray that meets nothing (or
 * only primitives with k_trans 1) carries 1, and one that meets an opaque
 * primitive carries 0. A ray that meets a semitransparent one leaves the
 * packet and is walked alone at the end (accel_transmittance). */
#ifndef PRISM_ACCEL_RAYS8_H
#define PRISM_ACCEL_RAYS8_H

#include "accel/accel.h"
#include "shared/ray_gpu.h"

#ifdef PACKET_RAYS

/* min and max without OpenCL's NaN rule: no NaN reaches them (origins are
 * finite, accel_safe_rcp keeps reciprocals finite and nonzero, and boxes are
 * finite or inverted: no 0 * inf, no inf - inf). As min_t and max_t, a tie
 * returns b; where fmin or fmax would have, the sign of a zero end may differ,
 * which no comparison sees. */
PRISM_HOT float8 rays8_min(float8 a, float8 b) { return select(b, a, a < b); }
PRISM_HOT float8 rays8_max(float8 a, float8 b) { return select(b, a, a > b); }
PRISM_HOT float rays8_least(float8 a) {
  float4 m4 = select(a.hi, a.lo, a.lo < a.hi);
  float2 m2 = select(m4.hi, m4.lo, m4.lo < m4.hi);
  return m2.x < m2.y ? m2.x : m2.y;
}

/* The far end of a closed lane's search: no box's far distance or triangle's
 * t is below it (tmin is finite in every walkable ray). */
#define RAYS8_CLOSED (-PRISM_INF)

/* The packet's rays one by one. A lane without a walkable ray holds one that
 * searches nothing (tmax RAYS8_CLOSED). */
typedef struct RayLanes {
  float ox[8], oy[8], oz[8], dx[8], dy[8], dz[8], tmin[8], tmax[8], time[8];
  int live; /* bit l: lane l holds a walkable ray */
} RayLanes;

PRISM_HOT void rays8_lanes(__global const RayGpu* rays, int lanes, RayLanes* r) {
  r->live = 0;
  for (int l = 0; l < PACKET_RAYS; ++l) {
    float3 o = (float3)(0.0f), d = (float3)(1.0f);
    float lo = 0.0f, hi = RAYS8_CLOSED, time = 0.0f;
    if (l < lanes) {
      RayGpu q = rays[l];
      float3 qo = (float3)(q.ox, q.oy, q.oz), qd = (float3)(q.dx, q.dy, q.dz);
      if (accel_ray_walkable(qo, qd, q.tmin, q.tmax)) {
        r->live |= 1 << l;
        o = qo;
        d = qd;
        lo = q.tmin;
        hi = q.tmax;
        time = q.time;
      }
    }
    r->ox[l] = o.x;
    r->oy[l] = o.y;
    r->oz[l] = o.z;
    r->dx[l] = d.x;
    r->dy[l] = d.y;
    r->dz[l] = d.z;
    r->tmin[l] = lo;
    r->tmax[l] = hi;
    r->time[l] = time;
  }
  /* Lanes without a ray point the way the first ray does, so that they do not
   * keep the packet from choosing its planes once (RayPacket). */
  if (r->live) {
    int first = 31 - clz(r->live & -r->live);
    for (int l = 0; l < PACKET_RAYS; ++l) {
      if (r->live & (1 << l)) continue;
      r->dx[l] = r->dx[first];
      r->dy[l] = r->dy[first];
      r->dz[l] = r->dz[first];
    }
  }
}

/* Ray l of the lanes, alone. */
PRISM_HOT float3 rays8_origin(const RayLanes* r, int l) { return (float3)(r->ox[l], r->oy[l], r->oz[l]); }
PRISM_HOT float3 rays8_dir(const RayLanes* r, int l) { return (float3)(r->dx[l], r->dy[l], r->dz[l]); }

typedef struct RayPacket {
  float8 ox, oy, oz, dx, dy, dz, ix, iy, iz, tmin;
  /* Per lane, the far end of the search: the best t so far (closest hits) or
   * tmax (transmittance); RAYS8_CLOSED in a lane with nothing left to find. */
  float8 best;
  /* Closest hits: per lane, what accel_accept keeps besides best. */
  float8 u, v;
  int8 prim;
  /* Transmittance: per lane, the light settled (1 until a ray meets an opaque
   * primitive), and whether the ray is to be walked alone at the end. */
  float8 light;
  int8 alone;
  /* Lanes whose directions share each axis's sign meet each box's near planes
   * first, as one ray does; then the near and far plane of each axis are
   * chosen once for the packet (nx, ny, nz: offsets of the near planes' floats
   * in a node; the far ones are offset ^ 8). */
  bool same_signs;
  int nx, ny, nz;
} RayPacket;

/* Where the eight rays enter the box lo..hi (no earlier than their tmin) and
 * leave it (its far planes, not yet cut to the rays' far ends): the test the
 * octree's cells, the scene's box (rays8_clip_scene) and the BVH's children in
 * packets of mixed direction signs share; each caller cuts and widens the far
 * end as its one-ray walk does. */
PRISM_HOT void rays8_box(float3 lo, float3 hi, const RayPacket* p, float8* near_t, float8* far_t) {
  float8 ax = ((float8)(lo.x) - p->ox) * p->ix, bx = ((float8)(hi.x) - p->ox) * p->ix;
  float8 ay = ((float8)(lo.y) - p->oy) * p->iy, by = ((float8)(hi.y) - p->oy) * p->iy;
  float8 az = ((float8)(lo.z) - p->oz) * p->iz, bz = ((float8)(hi.z) - p->oz) * p->iz;
  *near_t = rays8_max(rays8_max(rays8_max(rays8_min(ax, bx), rays8_min(ay, by)), rays8_min(az, bz)), p->tmin);
  *far_t = rays8_min(rays8_min(rays8_max(ax, bx), rays8_max(ay, by)), rays8_max(az, bz));
}

/* The packet's rays clipped to the scene's box (the header words) as
 * accel_clip_scene clips one ray: entry *t0, exit *t1 cut to each lane's best
 * and widened by ACCEL_FAR_SCALE; a lane meets the box where t0 <= t1.
 * accel_clip_scene's fmin and fmax give the same ends as rays8_min and
 * rays8_max: no NaN reaches them (the box is finite, or inverted where the
 * scene has only unbounded primitives), and a zero end's sign, which they may
 * leave otherwise, is only ever compared. */
PRISM_HOT void rays8_clip_scene(__global const float4* header, const RayPacket* p, float8* t0, float8* t1) {
  rays8_box(header[0].xyz, header[1].xyz, p, t0, t1);
  *t1 = rays8_min(*t1, p->best) * ACCEL_FAR_SCALE;
}

/* The lanes still searching: those whose far end is not RAYS8_CLOSED. */
PRISM_HOT int8 rays8_open(const RayPacket* p) { return p->best != (float8)(RAYS8_CLOSED); }

/* A packet's closest hits lane by lane, for what takes the rays one at a time:
 * best[l] the far end of lane l's search, prim[l] its hit (-1: none yet). */
typedef struct RayHits8 {
  float best[8], u[8], v[8];
  int prim[8];
} RayHits8;

PRISM_HOT void rays8_hits_out(const RayPacket* p, RayHits8* h) {
  vstore8(p->best, 0, h->best);
  vstore8(p->u, 0, h->u);
  vstore8(p->v, 0, h->v);
  vstore8(p->prim, 0, h->prim);
}

PRISM_HOT void rays8_hits_in(const RayHits8* h, RayPacket* p) {
  p->best = vload8(0, h->best);
  p->u = vload8(0, h->u);
  p->v = vload8(0, h->v);
  p->prim = vload8(0, h->prim);
}

/* Lane l's hit as one ray's (a miss where it has none), and back (its prim,
 * u and v; best is searched in place). */
PRISM_HOT HitGpu rays8_hit(const RayHits8* h, int l) {
  HitGpu g;
  accel_miss(&g);
  if (h->prim[l] >= 0) {
    g.t = h->best[l];
    g.prim = h->prim[l];
    g.u = h->u[l];
    g.v = h->v[l];
  }
  return g;
}

PRISM_HOT void rays8_keep(RayHits8* h, int l, const HitGpu* g) {
  h->prim[l] = g->prim;
  h->u[l] = g->u;
  h->v[l] = g->v;
}

/* The packet of lanes r, its search reaching to best[l] in lane l; no hit yet. */
PRISM_HOT void rays8_packet(const RayLanes* r, const float* best, RayPacket* p) {
  float ix[8], iy[8], iz[8];
  for (int l = 0; l < PACKET_RAYS; ++l) {
    float3 inv = accel_safe_rcp(rays8_dir(r, l));
    ix[l] = inv.x;
    iy[l] = inv.y;
    iz[l] = inv.z;
  }
  p->ox = vload8(0, r->ox);
  p->oy = vload8(0, r->oy);
  p->oz = vload8(0, r->oz);
  p->dx = vload8(0, r->dx);
  p->dy = vload8(0, r->dy);
  p->dz = vload8(0, r->dz);
  p->ix = vload8(0, ix);
  p->iy = vload8(0, iy);
  p->iz = vload8(0, iz);
  p->tmin = vload8(0, r->tmin);
  p->best = vload8(0, best);
  p->u = p->v = (float8)(0.0f);
  p->prim = (int8)(-1);
  p->light = (float8)(1.0f);
  p->alone = (int8)(0);
  p->same_signs = (all(p->ix >= 0.0f) || all(p->ix < 0.0f)) && (all(p->iy >= 0.0f) || all(p->iy < 0.0f)) &&
                  (all(p->iz >= 0.0f) || all(p->iz < 0.0f));
  p->nx = ix[0] >= 0.0f ? 0 : 8;
  p->ny = iy[0] >= 0.0f ? 16 : 24;
  p->nz = iz[0] >= 0.0f ? 32 : 40;
}

/* Triangle k of a leaf packet against the eight rays, with packet_intersect's
 * operations (MOLLER_TRUMBORE_LANES) on its lane k: the lanes it meets within
 * (tmin, best] (closed) or (tmin, best) (not), and there t, u and v. The
 * packet is read as float4 words, as packet_intersect reads it (a float
 * pointer into the record reads to a bounds checker as an index past its
 * first member array). */
PRISM_HOT int8 rays8_triangle(__global const TriPacketGpu* pk, int k, const RayPacket* p, int closed,
                              float8* t_out, float8* u_out, float8* v_out) {
  __global const float4* q = (__global const float4*)pk;
  float8 v0x = (float8)(accel_lane(q[0], k)), v0y = (float8)(accel_lane(q[1], k)), v0z = (float8)(accel_lane(q[2], k));
  float8 e1x = (float8)(accel_lane(q[3], k)), e1y = (float8)(accel_lane(q[4], k)), e1z = (float8)(accel_lane(q[5], k));
  float8 e2x = (float8)(accel_lane(q[6], k)), e2y = (float8)(accel_lane(q[7], k)), e2z = (float8)(accel_lane(q[8], k));
  float8 ox = p->ox, oy = p->oy, oz = p->oz, dx = p->dx, dy = p->dy, dz = p->dz;
  MOLLER_TRUMBORE_LANES(float8, int8, p->tmin, p->best, closed);
  *t_out = t;
  *u_out = u;
  *v_out = v;
  return hit;
}

/* Closest hits, leaf packet pk, in the lanes of `reach` (those whose own box
 * tests admit the leaf): triangles lane by lane against the eight rays, with
 * accel_accept's rule in every lane; other kinds of objects and moving
 * triangles ray by ray, through packet_closest. */
PRISM_HOT void rays8_leaf_closest(__global const TriPacketGpu* pk, int8 reach, const RayLanes* r, RayPacket* p,
                                  const Geometry* geom) {
  if (!packet_still_triangles(pk)) { /* tested ray by ray */
    int in[8];
    vstore8(reach, 0, in);
    RayHits8 hits;
    rays8_hits_out(p, &hits);
    for (int l = 0; l < PACKET_RAYS; ++l) {
      if (!in[l]) continue;
      float3 o = rays8_origin(r, l), d = rays8_dir(r, l);
      PacketRay pr = packet_ray(o, d, r->time[l]);
      HitGpu h = rays8_hit(&hits, l);
      packet_closest(pk, &pr, o, d, r->tmin[l], &hits.best[l], &h, geom);
      rays8_keep(&hits, l, &h);
    }
    rays8_hits_in(&hits, p);
    return;
  }
  for (int lane = 0; lane < PACKET_LANES; ++lane) {
    int id = pk->prim[lane];
    if (id < 0) continue;
    float8 t, u, v;
    int8 ok = rays8_triangle(pk, lane, p, 1, &t, &u, &v) & reach;
    int8 take = ok & ((t < p->best) | ((t == p->best) & (p->prim >= 0) & ((int8)(id) < p->prim)));
    p->best = select(p->best, t, take);
    p->u = select(p->u, u, take);
    p->v = select(p->v, v, take);
    p->prim = select(p->prim, (int8)(id), take);
  }
}

/* Transmittance: the lanes in `met` have met a primitive of transmittance k.
 * Opaque, they carry 0 and are done; semitransparent, they are done here and
 * walked alone at the end; k_trans 1 changes nothing. */
PRISM_HOT void rays8_meet(int8 met, float k, RayPacket* p) {
  if (k == 1.0f) return;
  if (k == 0.0f)
    p->light = select(p->light, (float8)(0.0f), met);
  else
    p->alone |= met;
  p->best = select(p->best, (float8)(RAYS8_CLOSED), met);
}

/* Transmittance, leaf packet pk, in the lanes of `reach`: triangles lane by
 * lane against the eight rays; other kinds of objects and moving triangles ray
 * by ray, through packet_transmittance (a ray whose light it leaves as it was
 * met nothing that counts; any other goes alone, since packet_transmittance's
 * 0 may be a product). */
PRISM_HOT void rays8_leaf_transmittance(__global const TriPacketGpu* pk, int8 reach, const RayLanes* r,
                                        RayPacket* p, const Geometry* geom, __global const MaterialGpu* materials) {
  if (!packet_still_triangles(pk)) { /* tested ray by ray */
    int in[8], alone[8];
    vstore8(reach & rays8_open(p), 0, in);
    for (int l = 0; l < PACKET_RAYS; ++l) {
      alone[l] = 0;
      if (!in[l]) continue;
      float3 o = rays8_origin(r, l), d = rays8_dir(r, l);
      PacketRay pr = packet_ray(o, d, r->time[l]);
      alone[l] = packet_transmittance(pk, &pr, o, d, r->tmin[l], r->tmax[l], 1.0f, 0, geom, materials) != 1.0f ? -1 : 0;
    }
    int8 leave = vload8(0, alone);
    p->alone |= leave;
    p->best = select(p->best, (float8)(RAYS8_CLOSED), leave);
    return;
  }
  for (int lane = 0; lane < PACKET_LANES; ++lane) {
    int id = pk->prim[lane];
    if (id < 0) continue;
    float8 t, u, v;
    int8 met = rays8_triangle(pk, lane, p, 0, &t, &u, &v) & reach;
    if (any8_t(met)) {
      rays8_meet(met, accel_transmit(materials, geom, id), p);
      reach &= rays8_open(p);
      if (!any8_t(reach)) return;
    }
  }
}

/* A leaf's `count` packets from pk, in the lanes of `reach`. Transmittance
 * stops once every lane of reach is settled: the leaf's later packets cannot
 * change a closed lane (no t lies below its far end, RAYS8_CLOSED). */
PRISM_HOT void rays8_leaf(__global const TriPacketGpu* pk, int count, int8 reach, const RayLanes* r, RayPacket* p,
                          const Geometry* geom, __global const MaterialGpu* materials, int transmittance) {
  for (int k = 0; k < count; ++k) {
    if (!transmittance) {
      rays8_leaf_closest(pk + k, reach, r, p, geom);
      continue;
    }
    rays8_leaf_transmittance(pk + k, reach, r, p, geom, materials);
    reach &= rays8_open(p);
    if (!any8_t(reach)) return;
  }
}

#endif
#endif
