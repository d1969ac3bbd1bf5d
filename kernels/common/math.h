/* Small vector helpers shared by all kernels. */
#ifndef PRISM_COMMON_MATH_H
#define PRISM_COMMON_MATH_H

/* Keep a*b+c as two roundings everywhere, so the host's double reference and two
 * code shapes of one test agree (PERF-NOTES: contraction changed t on 40% of hits),
 * and use only math whose results OpenCL fixes (same_bits_math.h). */
#pragma OPENCL FP_CONTRACT OFF
#include "common/same_bits_math.h"

#define PRISM_INF INFINITY
#define PRISM_PI 3.14159265358979f

/* For the small helpers of the traversal loops, which take pointers to a ray's
 * private state. PoCL's compiler left them as calls (perf showed packet_closest
 * and the octree's steps as functions of their own), which keeps that state in
 * memory; clang-based OpenCL compilers honour always_inline, others get the
 * plain inline hint. */
#if defined(__clang__) && !defined(PRISM_NO_FORCED_INLINE) /* the latter: tests/oclgrind/check.sh */
#define PRISM_HOT inline __attribute__((always_inline))
#else
#define PRISM_HOT inline
#endif

/* min and max for the traversal's distances, which are finite or infinite but
 * never NaN (no 0 * inf: accel_safe_rcp keeps reciprocals finite, and no
 * inf - inf: boxes are finite or inverted): one instruction each, where
 * fmin/fmax also pay for NaN handling. A tie returns b, as minss does. */
inline float min_t(float a, float b) { return a < b ? a : b; }
inline float max_t(float a, float b) { return a > b ? a : b; }
inline float3 min3_t(float3 a, float3 b) { return select(b, a, a < b); }
inline float3 max3_t(float3 a, float3 b) { return select(b, a, a > b); }

/* any() of a mask, without branches: PoCL lowers any() to a chain of tests
 * and jumps, a pair of lanes at a time, whose branches mispredict where the
 * lanes that are set vary from call to call (a packet's rays, a leaf's four
 * triangles). The lanes ORed together keep the sign bit of any set one. */
inline bool any4_t(int4 m) {
  int2 h = m.lo | m.hi;
  return (h.x | h.y) < 0;
}
inline bool any8_t(int8 m) { return any4_t(m.lo | m.hi); }

inline float3 load3(const float* p) { return (float3)(p[0], p[1], p[2]); }
inline float3 load3g(__global const float* p) { return (float3)(p[0], p[1], p[2]); }
inline float max3(float3 v) { return fmax(v.x, fmax(v.y, v.z)); }

/* x^y for x > 0 and finite y, as exp2(y log2 x). PoCL's pow takes its slow,
 * exact path on every call: in the Whitted scene the specular highlight's pow
 * was three quarters of spawn_shadows' time (80 ms of 0.33 s at 640x480; 22 ms
 * with this). With log2 and exp2 within 3 ulps (same_bits_math.h; OpenCL's own
 * promise is the same), the relative error is at most (3.5 |y log2 x| ln 2 + 3)
 * float ulps: under 2e-5 wherever the result is a normal float
 * (tests/kernels/math_test.cpp holds it to that against double pow). */
inline float pow_positive(float x, float y) { return sb_exp2(y * sb_log2(x)); }

/* Offset that moves a secondary ray's origin off the surface it leaves; scaled by
 * the point's magnitude because float spacing grows with it. */
inline float surface_epsilon(float3 p) { return 1e-4f * fmax(1.0f, max3(fabs(p))); }

#endif
