/* Which sample dimension each stochastic choice of a path uses, and the sampler
 * as a ray sees it. The film position has its own numbers (supersample.cl). A
 * primary ray spends DIM_TIME and DIM_LENS; each hit spends, from the ray's
 * `dim`, one 2-D dimension per lobe and one per light, and its children continue
 * after them, so no two choices of one path share a dimension. */
#ifndef PRISM_SAMPLING_DIMENSIONS_H
#define PRISM_SAMPLING_DIMENSIONS_H

#include "sampling/sampler.h"
#include "shared/ray_gpu.h"

#define DIM_TIME 0
#define DIM_LENS 1
#define DIM_FIRST_HIT 2 /* the `dim` of a primary ray */

#define DIM_REFLECT_LOBE 0 /* offsets from a hit ray's `dim` */
#define DIM_TRANSMIT_LOBE 1
#define DIM_FIRST_LIGHT 2

inline int dim_children(int dim, int light_count) { return dim + DIM_FIRST_LIGHT + light_count; }

/* The sampler for sub-sample `sub` of `subs` of a ray's sample: the group's
 * `strata` samples times `subs` form one stratified set (a light's extra shadow
 * rays refine the pixel's strata). strata == 0: independent random numbers
 * (aa mode random), for comparison. */
inline float2 ray_sample_2d(uint seed, int strata, int strata_id, int sample, int dim, int sub, int subs) {
  if (strata <= 0) return sample_2d(seed, pcg_hash((uint)strata_id ^ pcg_hash((uint)(sample * subs + sub))), 0, 1, dim);
  return sample_2d(seed, (uint)strata_id, sample * subs + sub, strata * subs, dim);
}

/* ray_sample_2d for eight rays' samples in vector lanes (sampler_point8): the
 * same points, lane by lane, in *x and *y. */
inline void ray_sample_2d8(uint seed, int strata, int8 strata_id, int8 sample, int8 dim, int8 sub, int8 subs,
                           float8* x, float8* y) {
  if (strata <= 0)
    sampler_point8(seed, pcg_hash8(as_uint8(strata_id) ^ pcg_hash8(as_uint8(sample * subs + sub))), (int8)(0),
                   (int8)(1), dim, x, y);
  else
    sampler_point8(seed, as_uint8(strata_id), sample * subs + sub, (int8)(strata) * subs, dim, x, y);
}

inline float ray_sample_1d(uint seed, int strata, int strata_id, int sample, int dim) {
  if (strata <= 0) return sample_1d(seed, pcg_hash((uint)strata_id ^ pcg_hash((uint)sample)), 0, 1, dim);
  return sample_1d(seed, (uint)strata_id, sample, strata, dim);
}

/* ray_sample_1d for eight rays' samples in vector lanes (sampler_value8). */
inline float8 ray_sample_1d8(uint seed, int strata, int8 strata_id, int8 sample, int dim) {
  if (strata <= 0)
    return sampler_value8(seed, pcg_hash8(as_uint8(strata_id) ^ pcg_hash8(as_uint8(sample))), (int8)(0), (int8)(1),
                          (int8)(dim));
  return sampler_value8(seed, as_uint8(strata_id), sample, (int8)(strata), (int8)(dim));
}

#endif
