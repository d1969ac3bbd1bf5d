/* The interface every acceleration structure implements for the extend,
 * shade and occlude kernels:
 *   bool accel_closest(ACCEL_PARAMS, float3 o, float3 d, float time, float tmin, float tmax, HitGpu* hit);
 *   float accel_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials,
 *                             float3 o, float3 d, float time, float tmin, float tmax);
 * Each structure's header provides them as structure_closest and
 * structure_transmittance; the two above turn away, as misses, rays no
 * structure can walk (accel_ray_walkable), then call those.
 * (time: the ray's instant, at which moving objects are tested; their boxes in
 * every structure cover their whole motion)
 * (transmittance multiplies k_trans once per primitive the segment meets; an
 * opaque one gives 0; materials == NULL treats every primitive as opaque, a plain
 * occlusion query). The program is built with -DPRISM_ACCEL_<NAME>
 * (host/accel/accel_structure.h gives the options); without one it is `none`.
 *
 * ACCEL_PARAMS is the same list for every structure, so the host binds one set
 * (a kernel takes ACCEL_KERNEL_PARAMS and makes `geom` with ACCEL_GEOMETRY):
 *   geom                    every primitive by id (geometry/primitive.h);
 *   accel_nodes             float4 words: [0], [1] the box of the bounded
 *                           primitives, then the structure's nodes;
 *   accel_packets           leaf contents, TriPacketGpu;
 *   accel_unbounded, accel_unbounded_count   ids tested by every ray (planes). */
#ifndef PRISM_ACCEL_ACCEL_H
#define PRISM_ACCEL_ACCEL_H

/* Included here, outside the #if below, because the host's include resolver
 * inlines each file once: the first inclusion must not sit in a skipped branch. */
#include "accel/leaf_packets.h"

#define ACCEL_BUFFER_PARAMS                                                                            \
  __global const float4 *accel_nodes, __global const TriPacketGpu *accel_packets, __global const int *accel_unbounded, \
      int accel_unbounded_count
#define ACCEL_PARAMS const Geometry *geom, ACCEL_BUFFER_PARAMS
#define ACCEL_ARGS geom, accel_nodes, accel_packets, accel_unbounded, accel_unbounded_count
#define ACCEL_KERNEL_PARAMS GEOMETRY_KERNEL_PARAMS, ACCEL_BUFFER_PARAMS
/* The first statement of a kernel that takes ACCEL_KERNEL_PARAMS. */
#define ACCEL_GEOMETRY                     \
  const Geometry geom_value = GEOMETRY_INIT; \
  const Geometry* geom = &geom_value

#ifndef PRISM_ACCEL_STACK
#define PRISM_ACCEL_STACK 64
#endif

/* Outside the #if for the same reason. */
#include "accel/cell_leaf.h"

#if defined(PRISM_ACCEL_BVH)
#include "accel/bvh.h"
#elif defined(PRISM_ACCEL_OCTREE)
#include "accel/octree.h"
#elif defined(PRISM_ACCEL_BSP)
#include "accel/bsp.h"
#else
#include "accel/none.h"
#endif

/* A ray with a NaN or infinite origin or direction component, a zero
 * direction, or a NaN bound meets nothing. Turned away here, before any
 * structure: NaN slab distances vanish in fmin/fmax, so a tree walk would take
 * every child of every node and overrun its stack. */
PRISM_HOT bool accel_ray_walkable(float3 o, float3 d, float tmin, float tmax) {
  float3 sum = fabs(o) + fabs(d); /* inf or NaN when any component is */
  return isfinite(sum.x) && isfinite(sum.y) && isfinite(sum.z) && (d.x != 0.0f || d.y != 0.0f || d.z != 0.0f) &&
         isfinite(tmin) && !isnan(tmax);
}

PRISM_HOT bool accel_closest(ACCEL_PARAMS, float3 o, float3 d, float time, float tmin, float tmax, HitGpu* hit) {
  if (!accel_ray_walkable(o, d, tmin, tmax)) {
    accel_miss(hit);
    return false;
  }
  return structure_closest(ACCEL_ARGS, o, d, time, tmin, tmax, hit);
}

PRISM_HOT float accel_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials, float3 o, float3 d,
                                    float time, float tmin, float tmax) {
  if (!accel_ray_walkable(o, d, tmin, tmax)) return 1.0f; /* nothing in the way of a ray that goes nowhere */
  return structure_transmittance(ACCEL_ARGS, materials, o, d, time, tmin, tmax);
}

#endif
