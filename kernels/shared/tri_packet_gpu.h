/* Four primitives of one leaf, stored so a ray meets all four triangles at once
 * with float4 arithmetic (PERF-NOTES: 4-wide leaves). Shared by host and kernels;
 * every acceleration structure's leaves are ranges of these packets.
 *   Lanes are structure-of-arrays: lane k of v0x..e2z is triangle k, with
 *   e1 = v1 - v0 and e2 = v2 - v0 rounded to float exactly as the kernel's
 *   scalar triangle_intersect computes them, so both give the same t, u, v.
 *   prim[k] >= 0: a triangle, its primitive id (a mesh's compact triangle or a
 *                 triangle record: geometry/primitive.h);
 *   prim[k] == PACKET_EMPTY: an unused lane (zero geometry, never hit);
 *   prim[k] <= -2: primitive -(prim[k] + 2), a sphere, box or transformed object
 *   tested through prim_intersect; such lanes share packets only with each
 *   other, and lane k's words 0..7 hold the object's slabs along the four
 *   diagonals (lo, hi of diagonal j in words 2j, 2j + 1: "set of normals"
 *   object bounds, tested under -DPRISM_OBJECT_KDOP).
 * A moving packet (PACKET_MOVING set in prim[0]) holds triangles of one moving
 * object in object space, lanes prim[k] = id | PACKET_MOVING (or empty): the
 * ray is mapped once per packet by that object's world-to-object transform at
 * its time (prim_world_to_object of the first lane), then meets the four at once. */
#ifndef PRISM_TRI_PACKET_GPU_H
#define PRISM_TRI_PACKET_GPU_H

#define PACKET_EMPTY (-1)
#define PACKET_LANES 4
#define PACKET_MOVING 0x40000000

typedef struct TriPacketGpu {
  float v0x[4], v0y[4], v0z[4];
  float e1x[4], e1y[4], e1z[4];
  float e2x[4], e2y[4], e2z[4];
  int prim[4];
} TriPacketGpu;

#endif
