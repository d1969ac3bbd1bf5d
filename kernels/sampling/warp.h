/* Maps of the unit square onto other domains that keep strata compact. */
#ifndef PRISM_SAMPLING_WARP_H
#define PRISM_SAMPLING_WARP_H

#include "common/math.h"

/* A point of the unit disk for u in [0, 1)^2, by Shirley and Chiu's concentric
 * map: squares go to rings, so a stratified square stays stratified. */
inline float2 concentric_disk(float2 u) {
  float2 s = 2.0f * u - (float2)(1.0f, 1.0f);
  if (s.x == 0.0f && s.y == 0.0f) return (float2)(0.0f, 0.0f);
  float r, theta;
  if (fabs(s.x) > fabs(s.y)) {
    r = s.x;
    theta = (PRISM_PI / 4.0f) * (s.y / s.x);
  } else {
    r = s.y;
    theta = (PRISM_PI / 2.0f) - (PRISM_PI / 4.0f) * (s.x / s.y);
  }
  return (float2)(r * sb_cos(theta), r * sb_sin(theta));
}

#endif
