/* A moving object's world-to-object matrix at an instant: translation and
 * stretch interpolated linearly, rotation by slerp between the decomposed
 * transforms at shutter open and close, then inverted. */
#ifndef PRISM_GEOMETRY_MOTION_H
#define PRISM_GEOMETRY_MOTION_H

#include "common/math.h"
#include "shared/motion_gpu.h"
#include "shared/object_gpu.h"

inline float4 motion_slerp(float4 a, float4 b, float s) {
  float c = sb_dot4(a, b);
  if (c < 0.0f) {
    b = -b;
    c = -c;
  }
  if (c > 0.9995f) return sb_normalize4(sb_mix(a, b, s)); /* nearly parallel: lerp is exact enough */
  float theta = sb_acos(c);
  float sin_theta = sb_sin(theta);
  return (sb_sin((1.0f - s) * theta) / sin_theta) * a + (sb_sin(s * theta) / sin_theta) * b;
}

/* The 3x4 world-to-object matrix (rows) of `motion` at `time`, into m. */
inline void motion_world_to_object(__global const MotionGpu* motion, float time, float* m) {
  float open = motion->shutter_open, close = motion->shutter_close;
  float s = close > open ? clamp((time - open) / (close - open), 0.0f, 1.0f) : 0.0f;
  float3 t = sb_mix(vload3(0, motion->translate0), vload3(0, motion->translate1), s);
  if (motion->kind == MOTION_TRANSLATE) {
    __global const float* linear = motion->shape0; /* 9 floats, row by row */
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[4 * i + j] = linear[3 * i + j];
      m[4 * i + 3] = -(m[4 * i] * t.x + m[4 * i + 1] * t.y + m[4 * i + 2] * t.z);
    }
    return;
  }
  float3 a0 = vload3(0, motion->shape0 + MOTION_ROTATION), a1 = vload3(0, motion->shape1 + MOTION_ROTATION);
  float4 q0 = (float4)(a0, sqrt(fmax(0.0f, 1.0f - sb_dot(a0, a0))));
  float4 q1 = (float4)(a1, sqrt(fmax(0.0f, 1.0f - sb_dot(a1, a1))));
  float4 q = motion_slerp(q0, q1, s);
  float st[6];
  for (int i = 0; i < 6; ++i) st[i] = sb_mix(motion->shape0[MOTION_STRETCH + i], motion->shape1[MOTION_STRETCH + i], s);
  /* The stretch's inverse (symmetric), by cofactors. */
  float a = st[0], b = st[1], c = st[2], d = st[3], e = st[4], f = st[5];
  float c00 = d * f - e * e, c01 = c * e - b * f, c02 = b * e - c * d;
  float c11 = a * f - c * c, c12 = b * c - a * e, c22 = a * d - b * b;
  float inv_det = 1.0f / (a * c00 + b * c01 + c * c02);
  float si[9] = {c00 * inv_det, c01 * inv_det, c02 * inv_det, c01 * inv_det, c11 * inv_det,
                 c12 * inv_det, c02 * inv_det, c12 * inv_det, c22 * inv_det};
  /* R of the unit quaternion (x, y, z, w), row by row. */
  float x = q.x, y = q.y, z = q.z, w = q.w;
  float r[9] = {1.0f - 2.0f * (y * y + z * z), 2.0f * (x * y - z * w),        2.0f * (x * z + y * w),
                2.0f * (x * y + z * w),        1.0f - 2.0f * (x * x + z * z), 2.0f * (y * z - x * w),
                2.0f * (x * z - y * w),        2.0f * (y * z + x * w),        1.0f - 2.0f * (x * x + y * y)};
  /* world-to-object = S^-1 R^T (p - t) */
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      m[4 * i + j] = si[3 * i] * r[3 * j] + si[3 * i + 1] * r[3 * j + 1] + si[3 * i + 2] * r[3 * j + 2];
    m[4 * i + 3] = -(m[4 * i] * t.x + m[4 * i + 1] * t.y + m[4 * i + 2] * t.z);
  }
}

#endif
