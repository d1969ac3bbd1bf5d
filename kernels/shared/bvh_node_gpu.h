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

/* "Set of normals" bounds (Kay and Kajiya 1986), -DPRISM_BVH_KDOP: besides the
 * three axes' slabs, each child is bounded by slabs along the four diagonals
 * (1,1,1), (1,1,-1), (1,-1,1), (-1,1,1) (unnormalised: a slab holds n.x over
 * the child), a 14-sided polytope that hugs slanted geometry closer than its
 * box. 256 bytes = 8 float8, after the node (and its motion bounds). Empty
 * slots are inverted here too. */
#define BVH_KDOP_DIAGONALS 4
typedef struct BvhKdopGpu {
  float slab[2 * BVH_KDOP_DIAGONALS][8]; /* float8 2j: the children's lows along diagonal j; 2j + 1: highs */
} BvhKdopGpu;

#endif
