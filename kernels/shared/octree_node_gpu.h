/* One cell of the adaptive octree; shared by host and kernels
 * (kernels/accel/octree.h). A cell's extent is not stored: the root's cube
 * heads the node buffer and each inner cell splits at its centre (cx, cy, cz),
 * the float value the host used when it sorted primitives into the children,
 * so host and device agree on every boundary. Octant bits: 1 = x >= cx,
 * 2 = y >= cy, 4 = z >= cz.
 * What a cell does store is the box of its contents clipped to the cell
 * (lo, hi): the stretch of a ray inside that box is the cell's interval, and a
 * ray that misses it skips the cell. Octree cells are cubes that do not fit a
 * surface; the box gives back the empty space. (A root holding nothing has an
 * inverted box and nothing to test.)
 *   Inner cell: child_mask != 0 says which octants exist; they are stored
 *   consecutively from `first` in octant order, so octant k sits at
 *   first + popcount(child_mask & ((1 << k) - 1)).
 *   Leaf: child_mask == 0; packets [first, first + packet_count).
 * Three float4 words. */
#ifndef PRISM_OCTREE_NODE_GPU_H
#define PRISM_OCTREE_NODE_GPU_H

typedef struct OctreeNodeGpu {
  float lo_x, lo_y, lo_z;
  int first;
  float hi_x, hi_y, hi_z;
  int child_mask;
  float cx, cy, cz;
  int packet_count;
} OctreeNodeGpu;

#endif
