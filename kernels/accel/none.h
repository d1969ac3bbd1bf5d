/* Brute force: every object against every ray. The reference the acceleration
 * structures are checked against; it ignores the tree buffers. */
#ifndef PRISM_ACCEL_NONE_H
#define PRISM_ACCEL_NONE_H

#include "accel/leaf_packets.h"

PRISM_HOT bool structure_closest(ACCEL_PARAMS, float3 o, float3 d, float time, float tmin, float tmax, HitGpu* hit) {
  accel_miss(hit);
  float best = tmax;
  for (int i = 0; i < geom->prim_count; ++i) {
    float t, u, v;
    if (prim_intersect(geom, i, o, d, time, tmin, best, &t, &u, &v)) {
      best = t;
      hit->t = t;
      hit->prim = i;
      hit->u = u;
      hit->v = v;
    }
  }
  return hit->prim >= 0;
}

/* Fraction of light a shadow feeler carries from tmin to tmax: an opaque object
 * blocks it, each semitransparent object it meets multiplies it by k_trans once. */
PRISM_HOT float structure_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials, float3 o, float3 d, float time,
                                    float tmin, float tmax) {
  float carried = 1.0f;
  for (int i = 0; i < geom->prim_count && carried > 0.0f; ++i) {
    float t, u, v;
    if (prim_intersect(geom, i, o, d, time, tmin, tmax, &t, &u, &v)) carried *= accel_transmit(materials, geom, i);
  }
  return carried;
}

#endif
