/* The closest hit of a ray; shared by host and kernels. */
#ifndef PRISM_HIT_GPU_H
#define PRISM_HIT_GPU_H

typedef struct HitGpu {
  float t;  /* +inf on a miss */
  int prim; /* index of the hit object, -1 on a miss */
  float u, v; /* triangles: barycentrics of vertices 1 and 2 */
} HitGpu;

#endif
