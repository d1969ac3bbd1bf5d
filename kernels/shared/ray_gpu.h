/* A ray in a wavefront queue; shared by host (C++) and kernels (OpenCL C).
 * Plain int/float fields only: no float3, whose size differs between the two. */
#ifndef PRISM_RAY_GPU_H
#define PRISM_RAY_GPU_H

#define RAY_KIND_NONE (-1) /* an empty slot, removed by compaction */
#define RAY_KIND_PRIMARY 0
#define RAY_KIND_REFLECTED 1
#define RAY_KIND_REFRACTED 2
#define RAY_KIND_SHADOW 3
#define RAY_KIND_COUNT 4

typedef struct RayGpu {
  float ox, oy, oz, tmin;
  float dx, dy, dz, tmax;
  /* Weight of the ray's contribution to its pixel (parent weight times the
   * coefficients on the way); for a shadow feeler, the light it would bring. */
  float wr, wg, wb;
  int pixel;
  int depth;  /* 0 for primary rays */
  int kind;   /* RAY_KIND_* */
  int sample; /* sample index within the pixel; AOVs come from sample 0 */
  int pad;    /* keeps the struct at 64 bytes, a multiple of float4 */
} RayGpu;

#endif
