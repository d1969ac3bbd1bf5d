/* Sample positions inside the unit pixel square for the supersample kernel: grid,
 * jittered strata (n x n for a square count, Hilbert-curve segments otherwise) and
 * Poisson tiles. Randomness comes from kernels/common/rng.h, so every position is a
 * function of (seed, pixel, sample) alone. */
#ifndef PRISM_SAMPLING_STRATA_H
#define PRISM_SAMPLING_STRATA_H

#include "common/rng.h"

/* 32 random bits for (seed, pixel, sample, dimension), the hash behind rng_uniform. */
inline uint rng_bits(uint seed, uint pixel, uint sample, uint dimension) {
  return pcg_hash(seed ^ pcg_hash(pixel ^ pcg_hash(sample ^ pcg_hash(dimension))));
}

/* The integer n with n * n == count, or 0 when count is not a square. */
inline int exact_sqrt(int count) {
  int n = (int)(sqrt((float)count) + 0.5f);
  return n * n == count ? n : 0;
}

/* Centre of cell `sample` of an n x n grid, row by row. */
inline float2 grid_point(int sample, int n) {
  return (float2)(((float)(sample % n) + 0.5f) / (float)n, ((float)(sample / n) + 0.5f) / (float)n);
}

/* Hilbert curve of order 16: index d in [0, 2^32) to a cell (x, y) of the
 * 65536 x 65536 grid (the iterative d2xy of Butz's curve). Consecutive indices are
 * neighbouring cells, so an interval of indices is a compact region. */
inline uint2 hilbert_d2xy(uint d) {
  uint x = 0, y = 0;
  for (uint s = 1; s < 65536u; s <<= 1) {
    uint rx = 1u & (d >> 1);
    uint ry = 1u & (d ^ rx);
    if (ry == 0u) {
      if (rx == 1u) {
        x = s - 1u - x;
        y = s - 1u - y;
      }
      uint t = x;
      x = y;
      y = t;
    }
    x += s * rx;
    y += s * ry;
    d >>= 2;
  }
  return (uint2)(x, y);
}

/* One uniform point in stratum `sample` of `count` strata of the unit square.
 * A square count n^2 uses the n x n cells. Any other count cuts the Hilbert curve,
 * which fills the square with equal measure, into `count` equal intervals: each is
 * a connected region of area 1/count and diameter O(1/sqrt(count)), which is what
 * jittering needs for its O(N^-3/4) error on edges. */
inline float2 jitter_point(uint seed, uint pixel, int sample, int count) {
  float u0 = rng_uniform(seed, pixel, (uint)sample, 0u);
  float u1 = rng_uniform(seed, pixel, (uint)sample, 1u);
  int n = exact_sqrt(count);
  if (n > 0)
    return (float2)(((float)(sample % n) + u0) / (float)n, ((float)(sample / n) + u1) / (float)n);
  /* A uniform index in [sample * 2^32 / count, (sample + 1) * 2^32 / count). */
  ulong wide = ((ulong)(uint)sample << 32) | (ulong)rng_bits(seed, pixel, (uint)sample, 2u);
  uint2 cell = hilbert_d2xy((uint)(wide / (ulong)count));
  return (float2)(((float)cell.x + u0) * (1.0f / 65536.0f), ((float)cell.y + u1) * (1.0f / 65536.0f));
}

/* Point `sample` of a Poisson-disk tile on the unit torus, shifted by `offset`
 * (both in [0, 1)) with wrap-around: a shift keeps toroidal distances, and a plain
 * distance is never shorter than the toroidal one. */
inline float2 poisson_point(__global const float* tile, int sample, float2 offset) {
  float2 p = (float2)(tile[2 * sample], tile[2 * sample + 1]) + offset;
  if (p.x >= 1.0f) p.x -= 1.0f;
  if (p.y >= 1.0f) p.y -= 1.0f;
  return p;
}

/* Film coordinate of offset s in [0, 1] inside pixel column (or row) i, kept below
 * i + 1, so rounding never moves a sample into the next pixel. */
inline float film_coord(int i, float s) {
  float x = (float)i + s;
  float end = (float)(i + 1);
  return x < end ? x : nextafter(end, 0.0f);
}

#endif
