/* One node of the BSP (SAH kd-) tree; shared by host and kernels
 * (kernels/accel/bsp.h). 8 bytes; nodes are in depth-first order, so an inner
 * node's lower child (coordinate <= split) directly follows it.
 *   word & 3 < 3: inner node splitting axis (word & 3) at the plane whose float
 *     bits are `payload`; the upper child's index is word >> 2.
 *   word & 3 == 3: leaf; packets [word >> 2, (word >> 2) + payload). */
#ifndef PRISM_BSP_NODE_GPU_H
#define PRISM_BSP_NODE_GPU_H

#define BSP_LEAF 3

typedef struct BspNodeGpu {
  int word;
  int payload;
} BspNodeGpu;

#endif
