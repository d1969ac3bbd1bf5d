/* The one sampler behind every stochastic choice after the film position: time,
 * lens, glossy and translucent lobes, points on area lights. Sample `sample` of
 * the `count` samples of a group (a pixel's spp samples in the per-pixel modes)
 * gets, in each dimension, a point of correlated multi-jittered sampling
 * (Kensler, "Correlated Multi-Jittered Sampling", Pixar TM 13-01, 2013): the
 * group's `count` points fall one per cell of an m x n grid (m*n >= count) and
 * one per 1/count stratum of either axis, jittered inside. Each (group,
 * dimension) has its own pseudo-random permutation of the strata, so the pairing
 * of strata between dimensions is shuffled, not the same index everywhere.
 * Every value is a function of (seed, group, sample, count, dimension) alone. */
#ifndef PRISM_SAMPLING_SAMPLER_H
#define PRISM_SAMPLING_SAMPLER_H

#include "common/rng.h"

/* A permutation of [0, len) chosen by `key`: a bijective hash on the next power
 * of two, cycle-walked until it lands inside (Kensler's construction). */
inline uint sampler_permute(uint i, uint len, uint key) {
  uint mask = len - 1u;
  mask |= mask >> 1;
  mask |= mask >> 2;
  mask |= mask >> 4;
  mask |= mask >> 8;
  mask |= mask >> 16;
  do {
    i ^= key;
    i *= 0xe170893du;
    i ^= key >> 16;
    i ^= (i & mask) >> 4;
    i ^= key >> 8;
    i *= 0x0929eb3fu;
    i ^= key >> 23;
    i ^= (i & mask) >> 1;
    i *= 1u | key >> 27;
    i *= 0x6935fa69u;
    i ^= (i & mask) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & mask) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & mask) >> 2;
    i *= 0xc860a3dfu;
    i &= mask;
    i ^= i >> 5;
  } while (i >= len);
  return (i + key) % len;
}

/* Uniform in [0, 1) from 24 bits of a hash of (i, key). */
inline float sampler_jitter(uint i, uint key) { return (float)(pcg_hash(i ^ pcg_hash(key)) >> 8) * (1.0f / 16777216.0f); }

/* The key of one (seed, group, dimension): every permutation and jitter of that
 * dimension derives from it. */
inline uint sampler_key(uint seed, uint group, int dim) {
  return pcg_hash(seed ^ pcg_hash(group ^ pcg_hash((uint)dim ^ 0x9e3779b9u)));
}

/* Keeps a value below 1 after float rounding. */
inline float sampler_unit(float x) { return x < 1.0f ? x : 0x1.fffffep-1f; }

/* A point in [0, 1)^2: sample `sample` of `count`, in dimension `dim` of group
 * `group`. */
inline float2 sample_2d(uint seed, uint group, int sample, int count, int dim) {
  uint key = sampler_key(seed, group, dim);
  uint n_total = (uint)max(count, 1);
  uint m = (uint)sqrt((float)n_total);
  if (m * m > n_total) m -= 1u;
  if ((m + 1u) * (m + 1u) <= n_total) m += 1u;
  uint n = (n_total + m - 1u) / m;
  uint s = sampler_permute((uint)sample % n_total, n_total, key * 0x51633e2du);
  uint sx = sampler_permute(s % m, m, key * 0x68bc21ebu);
  uint sy = sampler_permute(s / m, n, key * 0x02e5be93u);
  float jx = sampler_jitter(s, key * 0x967a889bu);
  float jy = sampler_jitter(s, key * 0x368cc8b7u);
  float x = ((float)sx + ((float)sy + jx) / (float)n) / (float)m;
  float y = ((float)s + jy) / (float)n_total;
  return (float2)(sampler_unit(x), sampler_unit(y));
}

/* A value in [0, 1): one jittered point per 1/count stratum, strata permuted per
 * (group, dimension). */
inline float sample_1d(uint seed, uint group, int sample, int count, int dim) {
  uint key = sampler_key(seed, group, dim);
  uint n_total = (uint)max(count, 1);
  uint s = sampler_permute((uint)sample % n_total, n_total, key * 0x51633e2du);
  return sampler_unit(((float)s + sampler_jitter(s, key * 0x967a889bu)) / (float)n_total);
}

#endif
