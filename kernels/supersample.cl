/* supersample: film positions of samples [first, first + count) of an image's
 * sample sequence (docs/sampling.md). Per-pixel modes (none, grid, jitter, poisson,
 * random) number the samples pixel by pixel, spp each, every sample inside its own
 * pixel; quincunx numbers the (W+1)(H+1) pixel corners row by row, then the W*H
 * pixel centres. Writes x in [0, W], y in [0, H] into xy[2k], xy[2k+1], and into
 * aov_pixel[k] the pixel whose AOVs the sample writes (sample 0 of a pixel, or a
 * quincunx centre), else -1. Adaptive sampling is driven by the host. */
#include "sampling/sample_modes.h"
#include "sampling/strata.h"

__kernel void supersample(int mode, int width, int height, int spp, uint seed, __global const float* tile, long first,
                          int count, __global float* xy, __global int* aov_pixel) {
  int k = get_global_id(0);
  if (k >= count) return;
  long g = first + k;

  if (mode == AA_MODE_QUINCUNX) {
    long corners = (long)(width + 1) * (long)(height + 1);
    if (g < corners) {
      xy[2 * k] = (float)(int)(g % (width + 1));
      xy[2 * k + 1] = (float)(int)(g / (width + 1));
      aov_pixel[k] = -1;
    } else {
      int pixel = (int)(g - corners);
      xy[2 * k] = (float)(pixel % width) + 0.5f;
      xy[2 * k + 1] = (float)(pixel / width) + 0.5f;
      aov_pixel[k] = pixel;
    }
    return;
  }

  int pixel = (int)(g / spp);
  int sample = (int)(g % spp);
  float2 s;
  switch (mode) {
    case AA_MODE_GRID: {
      int n = exact_sqrt(spp);
      s = n > 0 ? grid_point(sample, n) : (float2)(0.5f, 0.5f);
      break;
    }
    case AA_MODE_JITTER:
      s = jitter_point(seed, (uint)pixel, sample, spp);
      break;
    case AA_MODE_POISSON: {
      float2 offset = (float2)(rng_uniform(seed, (uint)pixel, POISSON_OFFSET_STREAM, 0u),
                               rng_uniform(seed, (uint)pixel, POISSON_OFFSET_STREAM, 1u));
      s = poisson_point(tile, sample, offset);
      break;
    }
    case AA_MODE_RANDOM:
      /* The same numbers kernels/generate.cl uses for spp > 1. */
      s = (float2)(rng_uniform(seed, (uint)pixel, (uint)sample, 0u), rng_uniform(seed, (uint)pixel, (uint)sample, 1u));
      break;
    default:
      s = (float2)(0.5f, 0.5f);
      break;
  }
  xy[2 * k] = film_coord(pixel % width, s.x);
  xy[2 * k + 1] = film_coord(pixel / width, s.y);
  aov_pixel[k] = sample == 0 ? pixel : -1;
}
