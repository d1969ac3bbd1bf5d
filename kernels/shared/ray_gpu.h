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
/* What count_rays records per block of a queue: the live rays of each kind,
 * then the point-light feelers traced by shade (RayGpu.feelers). */
#define RAY_COUNT_FEELERS RAY_KIND_COUNT
#define RAY_COUNT_COLUMNS (RAY_KIND_COUNT + 1)

typedef struct RayGpu {
  float ox, oy, oz, tmin;
  float dx, dy, dz, tmax;
  /* Weight of the ray's contribution to its pixel (parent weight times the
   * coefficients on the way); for a shadow feeler, the light it would bring. */
  float wr, wg, wb;
  /* The film key its light is added to: in a render, the index of the primary
   * sample the ray descends from in the image's sample sequence (docs/sampling.md),
   * so queues sorted by key accumulate without atomics; elsewhere any index. */
  int pixel;
  int depth;  /* 0 for primary rays */
  int kind;   /* RAY_KIND_* */
  int sample; /* index of the sample within its pixel (per-pixel modes), else 0 */
  /* Primary rays: the pixel whose AOVs this sample writes, or -1 for none (see
   * kernels/supersample.cl); -1 for every other ray. */
  int aov_pixel;
  /* The stochastic state (kernels/sampling/sampler.h): the instant in the
   * shutter interval the ray lives at (motion blur), the next unused sample
   * dimension of its path, and the id of the group of `strata` samples whose
   * strata it shares (its pixel in the per-pixel modes). */
  float time;
  int dim;
  int strata_id;
  /* In the reflected-ray slot shade writes for each ray it shades: the point
   * lights' shadow feelers it traced at the hit (kernels/shade.cl), which
   * count_rays counts as shadow rays whether or not the slot holds a ray;
   * 0 everywhere else. */
  int feelers;
} RayGpu;

#endif
