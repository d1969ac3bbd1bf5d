/* The interface every acceleration structure implements for the extend and
 * occlude kernels. Each structure's header provides
 *   bool accel_closest(ACCEL_PARAMS, float3 o, float3 d, float time, float tmin, float tmax, HitGpu* hit);
 *   float accel_transmittance(ACCEL_PARAMS, __global const MaterialGpu* materials,
 *                             float3 o, float3 d, float time, float tmin, float tmax);
 * (time: the ray's instant, at which moving objects are tested; their boxes in
 * every structure cover their whole motion)
 * (transmittance multiplies k_trans once per primitive the segment meets; an
 * opaque one gives 0; materials == NULL treats every primitive as opaque, a plain
 * occlusion query). The program is built with -DPRISM_ACCEL_<NAME>
 * (host/accel/accel_structure.h gives the options); without one it is `none`.
 *
 * ACCEL_PARAMS is the same list for every structure, so the host binds one set:
 *   objects, object_count   every primitive (ObjectGpu), the index is its id;
 *   accel_nodes             float4 words: [0], [1] the box of the bounded
 *                           primitives, then the structure's nodes;
 *   accel_packets           leaf contents, TriPacketGpu;
 *   accel_unbounded, accel_unbounded_count   ids tested by every ray (planes). */
#ifndef PRISM_ACCEL_ACCEL_H
#define PRISM_ACCEL_ACCEL_H

/* Included here, outside the #if below, because the host's include resolver
 * inlines each file once: the first inclusion must not sit in a skipped branch. */
#include "accel/leaf_packets.h"

#define ACCEL_PARAMS                                                                       \
  __global const ObjectGpu *objects, int object_count, __global const float4 *accel_nodes, \
      __global const TriPacketGpu *accel_packets, __global const int *accel_unbounded, int accel_unbounded_count
#define ACCEL_ARGS objects, object_count, accel_nodes, accel_packets, accel_unbounded, accel_unbounded_count

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

#endif
