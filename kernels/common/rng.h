/* Counter-based random numbers: a value depends only on (seed, pixel, sample,
 * dimension), never on scheduling, so images are identical run to run. */
#ifndef PRISM_COMMON_RNG_H
#define PRISM_COMMON_RNG_H

/* PCG-style integer hash (Jarzynski and Olano, "Hash Functions for GPU
 * Rendering", 2020): pcg_hash on one value, pcg_hash8 on eight in vector lanes
 * (the same operations lane by lane; integer, so the same bits). */
#define PCG_HASH_FUNCTION(name, U)                                    \
  inline U name(U v) {                                                \
    U state = v * 747796405u + 2891336453u;                           \
    U word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u; \
    return (word >> 22u) ^ word;                                      \
  }
PCG_HASH_FUNCTION(pcg_hash, uint)
PCG_HASH_FUNCTION(pcg_hash8, uint8)

/* Uniform float in [0, 1) from 24 random bits. */
inline float rng_uniform(uint seed, uint pixel, uint sample, uint dimension) {
  uint h = pcg_hash(seed ^ pcg_hash(pixel ^ pcg_hash(sample ^ pcg_hash(dimension))));
  return (float)(h >> 8) * (1.0f / 16777216.0f);
}

#endif
