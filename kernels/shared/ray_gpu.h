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
 * then the point-light feelers traced by shade. */
#define RAY_COUNT_FEELERS RAY_KIND_COUNT
#define RAY_COUNT_COLUMNS (RAY_KIND_COUNT + 1)
/* What scan_blocks totals for the host: the live rays of each kind, then their
 * sum, then the point-light feelers. */
#define RAY_TOTAL_LIVE RAY_KIND_COUNT
#define RAY_TOTAL_FEELERS (RAY_KIND_COUNT + 1)
#define RAY_TOTALS (RAY_KIND_COUNT + 2)

/* A queue's slots have tags beside them, one int each, so that compaction
 * reads four bytes per slot rather than a ray, and a producer writes a ray only
 * into a slot it fills: the kind of the slot's ray (RAY_KIND_NONE: empty, its
 * ray never read) and, above it, the point-light feelers that shade traced at
 * the hit which wrote the slot (counted as shadow rays; 0 elsewhere). */
#define SLOT_KIND_BITS 4
#define SLOT_TAG(kind, feelers) (((kind) + 1) | ((feelers) << SLOT_KIND_BITS))
#define SLOT_KIND(tag) (((tag) & ((1 << SLOT_KIND_BITS) - 1)) - 1)
#define SLOT_FEELERS(tag) ((tag) >> SLOT_KIND_BITS)

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
  int pad;
} RayGpu;

#endif
