/* Reconstruction filter weights for the resolve kernel. Every filter is separable,
 * w(dx, dy) = f(dx) f(dy), with (dx, dy) the sample's offset from the pixel centre
 * in pixels, and zero where |dx| or |dy| reaches the radius. */
#ifndef PRISM_SAMPLING_FILTERS_H
#define PRISM_SAMPLING_FILTERS_H

#include "common/math.h"
#include "sampling/sample_modes.h"

inline float filter_radius(int kind) {
  switch (kind) {
    case FILTER_TENT: return 1.0f;
    case FILTER_GAUSSIAN: return GAUSSIAN_RADIUS;
    case FILTER_MITCHELL: return 2.0f;
  }
  return 0.5f;
}

/* Mitchell and Netravali (1988) cubic with B = C = 1/3, support [-2, 2]. */
inline float mitchell_1d(float x) {
  const float b = 1.0f / 3.0f, c = 1.0f / 3.0f;
  x = fabs(x);
  if (x < 1.0f)
    return ((12.0f - 9.0f * b - 6.0f * c) * x * x * x + (-18.0f + 12.0f * b + 6.0f * c) * x * x + (6.0f - 2.0f * b)) /
           6.0f;
  if (x < 2.0f)
    return ((-b - 6.0f * c) * x * x * x + (6.0f * b + 30.0f * c) * x * x + (-12.0f * b - 48.0f * c) * x +
            (8.0f * b + 24.0f * c)) /
           6.0f;
  return 0.0f;
}

inline float filter_1d(int kind, float d) {
  switch (kind) {
    case FILTER_TENT: return fmax(0.0f, 1.0f - fabs(d));
    case FILTER_GAUSSIAN:
      /* Shifted down so it reaches zero at the radius instead of being cut there. */
      return fmax(0.0f, sb_exp(-GAUSSIAN_ALPHA * d * d) - sb_exp(-GAUSSIAN_ALPHA * GAUSSIAN_RADIUS * GAUSSIAN_RADIUS));
    case FILTER_MITCHELL: return mitchell_1d(d);
  }
  /* Box: half-open [-0.5, 0.5), so a sample on a pixel border counts in one pixel. */
  return d >= -0.5f && d < 0.5f ? 1.0f : 0.0f;
}

inline float filter_weight(int kind, float dx, float dy) { return filter_1d(kind, dx) * filter_1d(kind, dy); }

#endif
