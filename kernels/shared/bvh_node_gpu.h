/* One node of the 8-wide BVH; shared by host and kernels (kernels/accel/bvh.h).
 * The children's boxes are stored as structure-of-arrays so one float8 load
 * gives a slab of all eight (PERF-NOTES: wide nodes tested with vector types
 * were the single biggest step on PoCL). 224 bytes = 7 float8.
 *   child[i] > 0: an inner node, its index in the node array (the root, 0, is
 *                 nobody's child);
 *   child[i] == 0: an empty slot (its box is inverted, lo = +inf, hi = -inf, so
 *                 no ray meets it);
 *   child[i] < 0: a leaf, ~child[i] = packet_start << BVH_LEAF_COUNT_BITS |
 *                 (packet_count - 1), a range of TriPacketGpu. */
#ifndef PRISM_BVH_NODE_GPU_H
#define PRISM_BVH_NODE_GPU_H

#define BVH_WIDTH 8
#define BVH_LEAF_COUNT_BITS 3
#define BVH_LEAF_MAX_PACKETS (1 << BVH_LEAF_COUNT_BITS)

typedef struct BvhNodeGpu {
  float lo_x[8], hi_x[8]; /* float8 index 0, 1 */
  float lo_y[8], hi_y[8]; /* 2, 3 */
  float lo_z[8], hi_z[8]; /* 4, 5 */
  int child[8];           /* 6 */
} BvhNodeGpu;

/* Over moving primitives (-DPRISM_BVH_MOTION) each node is followed by its
 * children's boxes at shutter close (192 bytes = 6 float8), the node's own being
 * those at shutter open; a ray at fraction s of the shutter tests the boxes
 * lerp(open, close, s), which hold each child over its whole motion (linear
 * bounds, as in Embree's linear motion blur). The header words' w lanes hold
 * the shutter interval. */
typedef struct BvhMotionBoundsGpu {
  float lo_x[8], hi_x[8];
  float lo_y[8], hi_y[8];
  float lo_z[8], hi_z[8];
} BvhMotionBoundsGpu;

#endif
