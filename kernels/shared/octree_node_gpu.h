/* One cell of the adaptive octree; shared by host and kernels
 * (kernels/accel/octree.h). A cell's extent is not stored: the root's box heads
 * the node buffer and each inner cell splits at its centre (cx, cy, cz), the
 * float value the host used when it sorted primitives into the children, so
 * host and device agree on every boundary. Octant bits: 1 = x >= cx,
 * 2 = y >= cy, 4 = z >= cz.
 *   Inner cell: child_mask != 0 says which octants exist; they are stored
 *   consecutively from first_child in octant order, so octant k sits at
 *   first_child + popcount(child_mask & ((1 << k) - 1)).
 *   Leaf: child_mask == 0; packets [packet_start, packet_start + packet_count). */
#ifndef PRISM_OCTREE_NODE_GPU_H
#define PRISM_OCTREE_NODE_GPU_H

typedef struct OctreeNodeGpu {
  float cx, cy, cz;
  int first_child;
  int child_mask;
  int packet_start;
  int packet_count;
  int pad; /* keeps the node at 32 bytes, two float4 */
} OctreeNodeGpu;

#endif
