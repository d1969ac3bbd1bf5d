/* Small vector helpers shared by all kernels. */
#ifndef PRISM_COMMON_MATH_H
#define PRISM_COMMON_MATH_H

/* Keep a*b+c as two roundings everywhere, so the host's double reference and two
 * code shapes of one test agree (PERF-NOTES: contraction changed t on 40% of hits). */
#pragma OPENCL FP_CONTRACT OFF

#define PRISM_INF INFINITY

inline float3 load3(const float* p) { return (float3)(p[0], p[1], p[2]); }
inline float3 load3g(__global const float* p) { return (float3)(p[0], p[1], p[2]); }
inline float max3(float3 v) { return fmax(v.x, fmax(v.y, v.z)); }

/* Offset that moves a secondary ray's origin off the surface it leaves; scaled by
 * the point's magnitude because float spacing grows with it. */
inline float surface_epsilon(float3 p) { return 1e-4f * fmax(1.0f, max3(fabs(p))); }

#endif
