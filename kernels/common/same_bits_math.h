/* The math that every kernel uses in place of OpenCL's own geometric, mix and
 * elementary functions, so that a frame is the same bits on every OpenCL
 * device (issue 13: "whatever the mix of devices").
 *
 * OpenCL fixes +, -, * and, with -cl-fp32-correctly-rounded-divide-sqrt
 * (host/device/context.cpp asks for it wherever the device offers it), / and
 * sqrt to IEEE's correctly rounded results; FP_CONTRACT OFF keeps every
 * a * b + c as two roundings. Everything else is left to the implementation:
 * sin, exp, log2, atan2 and the rest may be off by 3 to 16 ulps each way, dot
 * and length may fuse or reorder, normalize may scale or use rsqrt. PoCL,
 * Oclgrind and NVIDIA's driver all choose differently: PoCL's image differed
 * from Oclgrind's in 17% of its values, an H200's from PoCL's in up to 0.5% of
 * its pixels (docs/devices.md). So these are written with the exact
 * operations alone, in a fixed order. Two devices then agree where both round
 * division and sqrt correctly and keep subnormals (DeviceDescription says
 * which do).
 *
 * The elementary functions follow the classic single-precision method of
 * Moshier's Cephes library: reduce the argument exactly (Cody and Waite's
 * split constants), then a short minimax polynomial. Their errors against
 * double precision are held by tests/kernels/same_bits_math_test.cpp.
 *
 * Below the definitions, OpenCL's own versions are made unusable, so that no
 * kernel calls one by habit. */
#ifndef PRISM_COMMON_SAME_BITS_MATH_H
#define PRISM_COMMON_SAME_BITS_MATH_H

#pragma OPENCL FP_CONTRACT OFF

#define SB_PI 3.14159265358979323846f
#define SB_PI_2 1.57079632679489661923f
#define SB_PI_4 0.785398163397448309616f

/* ---- vectors: one fixed order of products and sums ---- */

inline float sb_dot(float3 a, float3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline float sb_dot2(float2 a, float2 b) { return a.x * b.x + a.y * b.y; }
inline float sb_dot4(float4 a, float4 b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

inline float3 sb_cross(float3 a, float3 b) {
  return (float3)(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* a + (b - a) t, which is OpenCL's definition of mix; for floats and vectors alike. */
#define sb_mix(a, b, t) ((a) + ((b) - (a)) * (t))

/* Where the squared length would overflow or lose bits to underflow, the
 * vector is first divided by its largest component. */
inline bool sb_needs_scaling(float squared) { return !(squared > 0x1p-100f && squared < 0x1p100f); }

inline float sb_length(float3 v) {
  float d = sb_dot(v, v);
  if (!sb_needs_scaling(d)) return sqrt(d);
  if (isnan(d)) return d; /* fmax below would drop a NaN component */
  float m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
  if (!(m > 0.0f) || isinf(m)) return m; /* 0, infinity or NaN */
  v = v / m;
  return m * sqrt(sb_dot(v, v));
}

inline float sb_length2(float2 v) {
  float d = sb_dot2(v, v);
  if (!sb_needs_scaling(d)) return sqrt(d);
  if (isnan(d)) return d;
  float m = fmax(fabs(v.x), fabs(v.y));
  if (!(m > 0.0f) || isinf(m)) return m;
  v = v / m;
  return m * sqrt(sb_dot2(v, v));
}

/* The zero vector stays zero (OpenCL 2.0's rule), rather than becoming NaN. */
inline float3 sb_normalize(float3 v) {
  float d = sb_dot(v, v);
  if (sb_needs_scaling(d)) {
    float m = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
    if (!(m > 0.0f) || isinf(m)) return v;
    v = v / m;
    d = sb_dot(v, v);
  }
  return v / sqrt(d);
}

/* For quaternions, whose squared length is near 1. */
inline float4 sb_normalize4(float4 q) {
  float d = sb_dot4(q, q);
  return d > 0.0f ? q / sqrt(d) : q;
}

/* ---- powers of two, exponentials and logarithms ---- */

/* 2^n for n in [-126, 127], built from its bits. */
inline float sb_pow2i(int n) { return as_float((n + 127) << 23); }

/* x 2^n for x in [0.5, 2] and n in [-152, 129]: two exact scalings, the
 * second of which rounds once where the result is subnormal. */
inline float sb_scale(float x, int n) {
  int first = n / 2;
  return x * sb_pow2i(first) * sb_pow2i(n - first);
}

/* 2^x: x = n + f with |f| <= 1/2, then 2^f - 1 = f P(f). */
inline float sb_exp2(float x) {
  if (isnan(x)) return x;
  if (x >= 128.0f) return INFINITY;
  if (x < -150.0f) return 0.0f;
  float n = floor(x + 0.5f);
  float f = x - n;
  float p = ((((1.535336188319500e-4f * f + 1.339887440266574e-3f) * f + 9.618437357674640e-3f) * f +
              5.550332471162809e-2f) * f + 2.402264791363012e-1f) * f + 6.931472028550421e-1f;
  return sb_scale(1.0f + f * p, (int)n);
}

/* e^x: x = n ln 2 + g, ln 2 split in two so that n ln 2 is subtracted exactly,
 * then e^g = 1 + g + g^2 P(g). */
inline float sb_exp(float x) {
  if (isnan(x)) return x;
  if (x > 88.72283905206835f) return INFINITY;
  if (x < -103.97207708f) return 0.0f;
  float n = floor(1.44269504088896341f * x + 0.5f);
  float g = x - n * 0.693359375f;
  g = g - n * -2.12194440e-4f;
  float p = ((((1.9875691500e-4f * g + 1.3981999507e-3f) * g + 8.3334519073e-3f) * g + 4.1665795894e-2f) * g +
             1.6666665459e-1f) * g + 5.0000001201e-1f;
  return sb_scale(p * (g * g) + g + 1.0f, (int)n);
}

/* log2 x: x = 2^e m with m in [sqrt(1/2), sqrt(2)), ln m = ln(1 + t) from a
 * polynomial in t = m - 1, and log2 m = ln m + ln m * (log2(e) - 1), the
 * second product alone rounded. */
inline float sb_log2(float x) {
  if (isnan(x) || x == INFINITY) return x;
  if (x < 0.0f) return NAN;
  if (x == 0.0f) return -INFINITY;
  int e = 0;
  if (x < 0x1p-126f) { /* subnormal: make it normal first */
    x = x * 0x1p23f;
    e = -23;
  }
  int bits = as_int(x);
  e += ((bits >> 23) & 0xff) - 126;
  float m = as_float((bits & 0x007fffff) | 0x3f000000); /* [1/2, 1) */
  float t;
  if (m < 0.70710678118654752f) {
    e -= 1;
    t = m + m - 1.0f;
  } else {
    t = m - 1.0f;
  }
  float z = t * t;
  float y = (((((((7.0376836292e-2f * t - 1.1514610310e-1f) * t + 1.1676998740e-1f) * t - 1.2420140846e-1f) * t +
                1.4249322787e-1f) * t - 1.6668057665e-1f) * t + 2.0000714765e-1f) * t - 2.4999993993e-1f) * t +
            3.3333331174e-1f;
  y = y * t * z - 0.5f * z; /* ln(1 + t) = t + y */
  const float log2e_minus_1 = 0.44269504088896340736f;
  float r = y * log2e_minus_1;
  r = r + t * log2e_minus_1;
  r = r + y;
  r = r + t;
  return r + (float)e;
}

/* ---- circular functions ---- */

/* sin(q pi/2 + r) for |r| <= pi/4, from sin r or cos r by the quadrant q (0 to 3). */
inline float sb_sin_quadrant(float r, int q) {
  float z = r * r;
  float s = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * r + r;
  float c = ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z - 0.5f * z + 1.0f;
  float v = (q & 1) ? c : s;
  return (q & 2) ? -v : v;
}

/* x = n pi/2 + r with |r| <= pi/4: n the nearest multiple, and pi/2 split in
 * three so that n times each part is exact for the arguments the kernels pass
 * (|x| up to a few thousand). Accuracy falls off beyond 2^13. The quadrant, n
 * mod 4, is taken in float, exactly for every finite n: converting n itself
 * to int would be undefined beyond the int range. */
inline float sb_reduce_quadrant(float x, int* q) {
  float n = floor(x * 0.636619772367581343f + 0.5f);
  *q = (int)(n - 4.0f * floor(0.25f * n));
  float r = x - n * 1.5703125f;
  r = r - n * 4.837512969970703125e-4f;
  r = r - n * 7.549789954891886e-8f;
  return r;
}

inline float sb_sin(float x) {
  if (!isfinite(x)) return x - x; /* NaN */
  if (fabs(x) < 0x1p-12f) return x; /* sin x = x to within x^3 / 6, under half an ulp; and -0 stays -0 */
  int q;
  float r = sb_reduce_quadrant(x, &q);
  return sb_sin_quadrant(r, q);
}

inline float sb_cos(float x) {
  if (!isfinite(x)) return x - x;
  int q;
  float r = sb_reduce_quadrant(x, &q);
  return sb_sin_quadrant(r, (q + 1) & 3);
}

/* atan x: |x| brought into [0, tan(pi/8)] by atan x = pi/2 - atan(1/x) and
 * atan x = pi/4 + atan((x - 1) / (x + 1)), then an odd polynomial. */
inline float sb_atan(float x) {
  float a = fabs(x), base = 0.0f;
  if (a > 2.414213562373095f) {
    base = SB_PI_2;
    a = -1.0f / a;
  } else if (a > 0.4142135623730950f) {
    base = SB_PI_4;
    a = (a - 1.0f) / (a + 1.0f);
  }
  float z = a * a;
  float r = base + ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f) * z * a + a);
  return copysign(r, x);
}

/* The angle of (x, y) in [-pi, pi]. */
inline float sb_atan2(float y, float x) {
  if (x == 0.0f) return y > 0.0f ? SB_PI_2 : (y < 0.0f ? -SB_PI_2 : y); /* y: +-0, or NaN */
  float a = sb_atan(y / x);
  if (x < 0.0f) a = y < 0.0f ? a - SB_PI : a + SB_PI;
  return a;
}

/* asin x: an odd polynomial on [0, 1/2]; above, asin x = pi/2 - 2 asin(sqrt((1 - x) / 2)). */
inline float sb_asin(float x) {
  float a = fabs(x);
  if (!(a <= 1.0f)) return NAN;
  bool upper = a > 0.5f;
  float z = upper ? 0.5f * (1.0f - a) : a * a;
  float s = upper ? sqrt(z) : a;
  float r = ((((4.2163199048e-2f * z + 2.4181311049e-2f) * z + 4.5470025998e-2f) * z + 7.4953002686e-2f) * z +
             1.6666752422e-1f) * z * s + s;
  if (upper) r = SB_PI_2 - (r + r);
  return copysign(r, x);
}

inline float sb_acos(float x) {
  if (x < -0.5f) return SB_PI - 2.0f * sb_asin(sqrt(0.5f * (1.0f + x)));
  if (x > 0.5f) return 2.0f * sb_asin(sqrt(0.5f * (1.0f - x)));
  return SB_PI_2 - sb_asin(x);
}

/* ---- OpenCL's own, out of reach ----
 * A call to one of these is an error at compile time that names the
 * replacement (some compilers define OpenCL's as macros: those are undefined
 * first). sqrt, fabs, floor, fmin, fmax, clamp and fma stay: OpenCL fixes
 * their results (sqrt with the option above). */
#undef dot
#define dot(a, b) use_sb_dot_not_dot(a, b)
#undef cross
#define cross(a, b) use_sb_cross_not_cross(a, b)
#undef length
#define length(v) use_sb_length_not_length(v)
#undef fast_length
#define fast_length(v) use_sb_length_not_fast_length(v)
#undef distance
#define distance(a, b) use_sb_length_not_distance(a, b)
#undef normalize
#define normalize(v) use_sb_normalize_not_normalize(v)
#undef fast_normalize
#define fast_normalize(v) use_sb_normalize_not_fast_normalize(v)
#undef mix
#define mix(a, b, t) use_sb_mix_not_mix(a, b, t)
#undef mad
#define mad(a, b, c) use_two_roundings_not_mad(a, b, c)
#undef exp
#define exp(x) use_sb_exp_not_exp(x)
#undef exp2
#define exp2(x) use_sb_exp2_not_exp2(x)
#undef log2
#define log2(x) use_sb_log2_not_log2(x)
#undef log
#define log(x) use_sb_log2_not_log(x)
#undef pow
#define pow(x, y) use_pow_positive_not_pow(x, y)
#undef powr
#define powr(x, y) use_pow_positive_not_powr(x, y)
#undef sin
#define sin(x) use_sb_sin_not_sin(x)
#undef cos
#define cos(x) use_sb_cos_not_cos(x)
#undef tan
#define tan(x) use_sb_sin_and_sb_cos_not_tan(x)
#undef atan
#define atan(x) use_sb_atan_not_atan(x)
#undef atan2
#define atan2(y, x) use_sb_atan2_not_atan2(y, x)
#undef asin
#define asin(x) use_sb_asin_not_asin(x)
#undef acos
#define acos(x) use_sb_acos_not_acos(x)
#undef rsqrt
#define rsqrt(x) use_one_over_sqrt_not_rsqrt(x)
/* And the rest whose results OpenCL leaves open: none has a replacement yet. */
#undef fast_distance
#define fast_distance(a, b) not_fixed_by_opencl_fast_distance(a, b)
#undef hypot
#define hypot(x, y) not_fixed_by_opencl_hypot(x, y)
#undef sincos
#define sincos(x, c) not_fixed_by_opencl_sincos(x, c)
#undef smoothstep
#define smoothstep(a, b, x) not_fixed_by_opencl_smoothstep(a, b, x)
#undef degrees
#define degrees(x) not_fixed_by_opencl_degrees(x)
#undef radians
#define radians(x) not_fixed_by_opencl_radians(x)
#undef sinh
#define sinh(x) not_fixed_by_opencl_sinh(x)
#undef cosh
#define cosh(x) not_fixed_by_opencl_cosh(x)
#undef tanh
#define tanh(x) not_fixed_by_opencl_tanh(x)
#undef asinh
#define asinh(x) not_fixed_by_opencl_asinh(x)
#undef acosh
#define acosh(x) not_fixed_by_opencl_acosh(x)
#undef atanh
#define atanh(x) not_fixed_by_opencl_atanh(x)
#undef cbrt
#define cbrt(x) not_fixed_by_opencl_cbrt(x)
#undef exp10
#define exp10(x) not_fixed_by_opencl_exp10(x)
#undef expm1
#define expm1(x) not_fixed_by_opencl_expm1(x)
#undef log10
#define log10(x) not_fixed_by_opencl_log10(x)
#undef log1p
#define log1p(x) not_fixed_by_opencl_log1p(x)
#undef logb
#define logb(x) not_fixed_by_opencl_logb(x)
#undef pown
#define pown(x, n) not_fixed_by_opencl_pown(x, n)
#undef rootn
#define rootn(x, n) not_fixed_by_opencl_rootn(x, n)
#undef sinpi
#define sinpi(x) not_fixed_by_opencl_sinpi(x)
#undef cospi
#define cospi(x) not_fixed_by_opencl_cospi(x)
#undef tanpi
#define tanpi(x) not_fixed_by_opencl_tanpi(x)
#undef asinpi
#define asinpi(x) not_fixed_by_opencl_asinpi(x)
#undef acospi
#define acospi(x) not_fixed_by_opencl_acospi(x)
#undef atanpi
#define atanpi(x) not_fixed_by_opencl_atanpi(x)
#undef atan2pi
#define atan2pi(y, x) not_fixed_by_opencl_atan2pi(y, x)
#undef erf
#define erf(x) not_fixed_by_opencl_erf(x)
#undef erfc
#define erfc(x) not_fixed_by_opencl_erfc(x)
#undef tgamma
#define tgamma(x) not_fixed_by_opencl_tgamma(x)
#undef lgamma
#define lgamma(x) not_fixed_by_opencl_lgamma(x)
#undef native_sin
#define native_sin(x) not_fixed_by_opencl_native_sin(x)
#undef native_cos
#define native_cos(x) not_fixed_by_opencl_native_cos(x)
#undef native_tan
#define native_tan(x) not_fixed_by_opencl_native_tan(x)
#undef native_exp
#define native_exp(x) not_fixed_by_opencl_native_exp(x)
#undef native_exp2
#define native_exp2(x) not_fixed_by_opencl_native_exp2(x)
#undef native_exp10
#define native_exp10(x) not_fixed_by_opencl_native_exp10(x)
#undef native_log
#define native_log(x) not_fixed_by_opencl_native_log(x)
#undef native_log2
#define native_log2(x) not_fixed_by_opencl_native_log2(x)
#undef native_log10
#define native_log10(x) not_fixed_by_opencl_native_log10(x)
#undef native_powr
#define native_powr(x, y) not_fixed_by_opencl_native_powr(x, y)
#undef native_sqrt
#define native_sqrt(x) not_fixed_by_opencl_native_sqrt(x)
#undef native_rsqrt
#define native_rsqrt(x) not_fixed_by_opencl_native_rsqrt(x)
#undef native_recip
#define native_recip(x) not_fixed_by_opencl_native_recip(x)
#undef native_divide
#define native_divide(x, y) not_fixed_by_opencl_native_divide(x, y)
#undef half_sin
#define half_sin(x) not_fixed_by_opencl_half_sin(x)
#undef half_cos
#define half_cos(x) not_fixed_by_opencl_half_cos(x)
#undef half_tan
#define half_tan(x) not_fixed_by_opencl_half_tan(x)
#undef half_exp
#define half_exp(x) not_fixed_by_opencl_half_exp(x)
#undef half_exp2
#define half_exp2(x) not_fixed_by_opencl_half_exp2(x)
#undef half_exp10
#define half_exp10(x) not_fixed_by_opencl_half_exp10(x)
#undef half_log
#define half_log(x) not_fixed_by_opencl_half_log(x)
#undef half_log2
#define half_log2(x) not_fixed_by_opencl_half_log2(x)
#undef half_log10
#define half_log10(x) not_fixed_by_opencl_half_log10(x)
#undef half_powr
#define half_powr(x, y) not_fixed_by_opencl_half_powr(x, y)
#undef half_sqrt
#define half_sqrt(x) not_fixed_by_opencl_half_sqrt(x)
#undef half_rsqrt
#define half_rsqrt(x) not_fixed_by_opencl_half_rsqrt(x)
#undef half_recip
#define half_recip(x) not_fixed_by_opencl_half_recip(x)
#undef half_divide
#define half_divide(x, y) not_fixed_by_opencl_half_divide(x, y)

#endif
