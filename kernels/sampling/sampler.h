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

/* The pieces of the sampler, for one value (S empty: U uint, I int, F float)
 * or for eight in vector lanes (S 8: uint8, int8, float8), with the same
 * operations lane by lane, so the same bits: integer operations are exact; the
 * float ones are conversions of integers to float (rounded to nearest, as
 * OpenCL fixes them), one square root whose result only seeds an integer that
 * exact integer tests then correct, divisions (correctly rounded, as prism asks
 * of every device that offers it) and one compare.
 *   sampler_mask: all bits below len's highest set;
 *   sampler_round: one round of Kensler's bijective hash on [0, mask];
 *   sampler_jitter: uniform in [0, 1) from 24 bits of a hash of (i, key);
 *   sampler_key: the key of one (seed, group, dimension), from which every
 *     permutation and jitter of that dimension derives;
 *   sampler_unit: keeps a value below 1 after float rounding;
 * (SAMPLER_POINTS, after the permutations, makes the points of them.) */
#define SAMPLER_PIECES(S, U, I, F)                                                                             \
  inline U sampler_mask##S(U len) {                                                                            \
    U mask = len - 1u;                                                                                         \
    mask |= mask >> 1;                                                                                         \
    mask |= mask >> 2;                                                                                         \
    mask |= mask >> 4;                                                                                         \
    mask |= mask >> 8;                                                                                         \
    return mask | mask >> 16;                                                                                  \
  }                                                                                                            \
  inline U sampler_round##S(U i, U key, U mask) {                                                              \
    i ^= key;                                                                                                  \
    i *= 0xe170893du;                                                                                          \
    i ^= key >> 16;                                                                                            \
    i ^= (i & mask) >> 4;                                                                                      \
    i ^= key >> 8;                                                                                             \
    i *= 0x0929eb3fu;                                                                                          \
    i ^= key >> 23;                                                                                            \
    i ^= (i & mask) >> 1;                                                                                      \
    i *= 1u | key >> 27;                                                                                       \
    i *= 0x6935fa69u;                                                                                          \
    i ^= (i & mask) >> 11;                                                                                     \
    i *= 0x74dcb303u;                                                                                          \
    i ^= (i & mask) >> 2;                                                                                      \
    i *= 0x9e501cc3u;                                                                                          \
    i ^= (i & mask) >> 2;                                                                                      \
    i *= 0xc860a3dfu;                                                                                          \
    i &= mask;                                                                                                 \
    return i ^ i >> 5;                                                                                         \
  }                                                                                                            \
  inline F sampler_jitter##S(U i, U key) {                                                                     \
    return convert_##F(pcg_hash##S(i ^ pcg_hash##S(key)) >> 8) * (1.0f / 16777216.0f);                         \
  }                                                                                                            \
  inline U sampler_key##S(uint seed, U group, I dim) {                                                         \
    return pcg_hash##S(seed ^ pcg_hash##S(group ^ pcg_hash##S(as_##U(dim) ^ 0x9e3779b9u)));                    \
  }                                                                                                            \
  inline F sampler_unit##S(F x) { return select((F)(0x1.fffffep-1f), x, x < 1.0f); }

SAMPLER_PIECES(, uint, int, float)
SAMPLER_PIECES(8, uint8, int8, float8)

/* A permutation of [0, len) chosen by `key`: a bijective hash on the next power
 * of two, cycle-walked until it lands inside (Kensler's construction). */
inline uint sampler_permute(uint i, uint len, uint key) {
  uint mask = sampler_mask(len);
  do {
    i = sampler_round(i, key, mask);
  } while (i >= len);
  return (i + key) % len;
}

/* Eight permutations at once, lane by lane as sampler_permute: a lane that
 * has landed inside its range keeps its value while others walk on. */
inline uint8 sampler_permute8(uint8 i, uint8 len, uint8 key) {
  uint8 mask = sampler_mask8(len);
  int8 walking = (int8)(-1);
  do {
    i = select(i, sampler_round8(i, key, mask), walking);
    walking &= i >= len;
  } while (any(walking));
  return (i + key) % len;
}

/* The sampler's points, for one value or eight lanes as SAMPLER_PIECES: sample
 * `sample` of `count`, in dimension `dim` of group `group`, as a point of
 * [0, 1)^2 (sampler_point, for sample_2d) or a value in [0, 1) (sampler_value,
 * for sample_1d). max's 1 is of count's type: Oclgrind 21.10 gets max(int8,
 * int) wrong, which OpenCL C allows and PoCL gets right. */
#define SAMPLER_POINTS(S, U, I, F)                                                                             \
  inline void sampler_point##S(uint seed, U group, I sample, I count, I dim, F* x_out, F* y_out) {             \
    U key = sampler_key##S(seed, group, dim);                                                                  \
    U n_total = as_##U(max(count, (I)(1)));                                                                    \
    U m = convert_##U(sqrt(convert_##F(n_total)));                                                             \
    m = select(m, m - 1u, m * m > n_total);                                                                    \
    m = select(m, m + 1u, (m + 1u) * (m + 1u) <= n_total);                                                     \
    U n = (n_total + m - 1u) / m;                                                                              \
    U s = sampler_permute##S(as_##U(sample) % n_total, n_total, key * 0x51633e2du);                            \
    U sx = sampler_permute##S(s % m, m, key * 0x68bc21ebu);                                                    \
    U sy = sampler_permute##S(s / m, n, key * 0x02e5be93u);                                                    \
    F jx = sampler_jitter##S(s, key * 0x967a889bu);                                                            \
    F jy = sampler_jitter##S(s, key * 0x368cc8b7u);                                                            \
    *x_out = sampler_unit##S((convert_##F(sx) + (convert_##F(sy) + jx) / convert_##F(n)) / convert_##F(m));    \
    *y_out = sampler_unit##S((convert_##F(s) + jy) / convert_##F(n_total));                                    \
  }                                                                                                            \
  inline F sampler_value##S(uint seed, U group, I sample, I count, I dim) {                                    \
    U key = sampler_key##S(seed, group, dim);                                                                  \
    U n_total = as_##U(max(count, (I)(1)));                                                                    \
    U s = sampler_permute##S(as_##U(sample) % n_total, n_total, key * 0x51633e2du);                            \
    return sampler_unit##S((convert_##F(s) + sampler_jitter##S(s, key * 0x967a889bu)) / convert_##F(n_total)); \
  }

SAMPLER_POINTS(, uint, int, float)
SAMPLER_POINTS(8, uint8, int8, float8)

/* A point in [0, 1)^2: sample `sample` of `count`, in dimension `dim` of group
 * `group`. The sampler's hashes are long chains of dependent multiplies, and
 * PoCL runs a work-group's items one after another without vectorising across
 * them, so one point at a time waits on every link of every chain; a work-item
 * with several points to draw draws eight at once in vector lanes
 * (sampler_point8), the same bits as eight calls here (docs/architecture.md,
 * step 4, has what that saved). */
inline float2 sample_2d(uint seed, uint group, int sample, int count, int dim) {
  float x, y;
  sampler_point(seed, group, sample, count, dim, &x, &y);
  return (float2)(x, y);
}

/* A value in [0, 1): one jittered point per 1/count stratum, strata permuted per
 * (group, dimension). */
inline float sample_1d(uint seed, uint group, int sample, int count, int dim) {
  return sampler_value(seed, group, sample, count, dim);
}

#endif
