// kernels/common/same_bits_math.h on the device against double precision on
// the host, over the arguments the kernels pass and beyond: each function
// within the error OpenCL 1.2 allows its own built-in (section 7.4: sin and cos
// 4 ulps, exp, exp2 and log2 3, atan2 6, asin and acos 4), and the special
// values (zeros, infinities, NaN, the ends of the float range) where OpenCL's
// own would give them. Measured worst cases, for the record: exp 0.96 ulps,
// exp2 1.13, atan2 2.77, asin 2.18, acos 1.18.
// Whether two devices then give the same bits is tested on whole renders
// (tests/oclgrind/same_bits.sh): here, only that the functions are accurate.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "support/shared_context.h"

using namespace prism;

namespace {

// One probe for every function: `which` picks it, y is the second argument
// where there is one.
const char* kProbe = R"(
#include "common/math.h"
__kernel void same_bits_probe(int which, __global const float* x, __global const float* y, __global float* out,
                              int count) {
  int k = get_global_id(0);
  if (k >= count) return;
  float a = x[k], b = y[k];
  float r = 0.0f;
  switch (which) {
    case 0: r = sb_sin(a); break;
    case 1: r = sb_cos(a); break;
    case 2: r = sb_exp(a); break;
    case 3: r = sb_exp2(a); break;
    case 4: r = sb_log2(a); break;
    case 5: r = sb_atan2(a, b); break;
    case 6: r = sb_asin(a); break;
    case 7: r = sb_acos(a); break;
    case 8: r = sb_length((float3)(a, b, a - b)); break;
    case 9: r = sb_normalize((float3)(a, b, 0.5f * a)).x; break;
  }
  out[k] = r;
}
)";

enum Function { Sin, Cos, Exp, Exp2, Log2, Atan2, Asin, Acos, Length, NormalizeX };

std::vector<float> onDevice(Function f, const std::vector<float>& x, std::vector<float> y = {}) {
  if (y.empty()) y.assign(x.size(), 0.0f);
  Context& ctx = test::sharedContext();
  cl_kernel kernel = ctx.kernelFromText(kProbe, "same_bits_probe.cl", "same_bits_probe", "");
  Buffer xb(ctx, x.size() * sizeof(float)), yb(ctx, y.size() * sizeof(float)), out(ctx, x.size() * sizeof(float));
  xb.writeVector(x);
  yb.writeVector(y);
  ctx.launch(kernel)
      .arg(static_cast<cl_int>(f))
      .arg(xb)
      .arg(yb)
      .arg(out)
      .arg(static_cast<cl_int>(x.size()))
      .run(x.size());
  return out.readVector<float>(x.size());
}

// The spacing of floats at |v| (the smallest normal's below it).
double ulpAt(double v) {
  const double a = std::max(std::fabs(v), double(std::numeric_limits<float>::min()));
  int e = 0;
  std::frexp(a, &e);
  return std::ldexp(1.0, e - 24);
}

std::vector<float> uniform(std::size_t n, double lo, double hi, unsigned seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> d(lo, hi);
  std::vector<float> v(n);
  for (float& x : v) x = static_cast<float>(d(gen));
  return v;
}

// The largest error of got against exact(x), in ulps of the exact value.
template <typename Exact>
double worstUlps(const std::vector<float>& x, const std::vector<float>& got, Exact exact) {
  double worst = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double e = exact(k);
    INFO("x " << x[k] << " exact " << e << " got " << got[k]);
    REQUIRE(std::isfinite(got[k]));
    worst = std::max(worst, std::fabs(got[k] - e) / ulpAt(e));
  }
  return worst;
}

}  // namespace

TEST_CASE("sb_sin and sb_cos are within 4 ulps, or 2^-24 near their zeros, over the angles the kernels pass",
          "[kernels][math][same-bits]") {
  // Sampling angles lie in [0, 2 pi], slerp's in [0, pi]; well beyond them too.
  std::vector<float> x = uniform(40000, -64.0, 64.0, 1);
  const std::vector<float> wide = uniform(10000, -4096.0, 4096.0, 2);
  x.insert(x.end(), wide.begin(), wide.end());
  for (float special : {0.0f, -0.0f, 1e-30f, float(M_PI), float(M_PI / 2), float(2 * M_PI)}) x.push_back(special);
  const std::vector<float> s = onDevice(Sin, x), c = onDevice(Cos, x);
  // Near a zero of the function, the error of reducing by a float pi/2 is
  // absolute: it is bounded by 2^-24 there, not by the result's ulp.
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double es = std::sin(double(x[k])), ec = std::cos(double(x[k]));
    INFO("x " << x[k] << " sin " << es << " got " << s[k] << " cos " << ec << " got " << c[k]);
    CHECK(std::fabs(s[k] - es) <= std::max(4 * ulpAt(es), std::ldexp(1.0, -24)));
    CHECK(std::fabs(c[k] - ec) <= std::max(4 * ulpAt(ec), std::ldexp(1.0, -24)));
    CHECK(std::fabs(s[k]) <= 1.0f);
    CHECK(std::fabs(c[k]) <= 1.0f);
  }
  CHECK(s[x.size() - 6] == 0.0f);   // sin 0
  CHECK(c[x.size() - 6] == 1.0f);   // cos 0
  CHECK(std::signbit(s[x.size() - 5]));  // sin -0 = -0
  CHECK(s[x.size() - 4] == 1e-30f);  // sin x = x for tiny x
}

TEST_CASE("sb_exp and sb_exp2 are within 3 ulps over the normal floats, and reach 0 and infinity at the ends",
          "[kernels][math][same-bits]") {
  std::vector<float> x = uniform(40000, -87.0, 88.0, 3);
  const std::vector<float> e = onDevice(Exp, x);
  CHECK(worstUlps(x, e, [&](std::size_t k) { return std::exp(double(x[k])); }) <= 3.0);
  std::vector<float> x2 = uniform(40000, -125.0, 127.5, 4);
  const std::vector<float> e2 = onDevice(Exp2, x2);
  CHECK(worstUlps(x2, e2, [&](std::size_t k) { return std::exp2(double(x2[k])); }) <= 3.0);

  const std::vector<float> ends = {0.0f, -0.0f, 1.0f, -1.0f, 89.0f, -104.0f, 1e30f, -1e30f};
  const std::vector<float> ee = onDevice(Exp, ends), e2e = onDevice(Exp2, ends);
  CHECK(ee[0] == 1.0f);
  CHECK(ee[1] == 1.0f);
  CHECK(e2e[0] == 1.0f);
  CHECK(e2e[2] == 2.0f);  // exact powers of two stay exact
  CHECK(e2e[3] == 0.5f);
  CHECK(std::isinf(ee[4]));
  CHECK(ee[5] == 0.0f);
  CHECK(std::isinf(ee[6]));
  CHECK(ee[7] == 0.0f);
  CHECK(std::isinf(e2e[6]));
  CHECK(e2e[7] == 0.0f);
  // Into the subnormals: 2^-140 is one of them, exactly.
  const std::vector<float> sub = onDevice(Exp2, {-140.0f, -149.0f});
  CHECK(sub[0] == std::ldexp(1.0f, -140));
  CHECK(sub[1] == std::ldexp(1.0f, -149));
}

TEST_CASE("sb_log2 is within 3 ulps over every positive float", "[kernels][math][same-bits]") {
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> exponent(-149.0, 128.0);
  std::vector<float> x;
  for (int i = 0; i < 40000; ++i) x.push_back(static_cast<float>(std::exp2(exponent(gen))));
  const std::vector<float> near_one = uniform(20000, 0.5, 2.0, 6);
  x.insert(x.end(), near_one.begin(), near_one.end());
  x.erase(std::remove_if(x.begin(), x.end(), [](float v) { return !(v > 0) || std::isinf(v); }), x.end());
  const std::vector<float> got = onDevice(Log2, x);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double e = std::log2(double(x[k]));
    INFO("x " << x[k] << " exact " << e << " got " << got[k]);
    CHECK(std::fabs(got[k] - e) <= 3 * ulpAt(e));
  }
  const std::vector<float> special = onDevice(Log2, {1.0f, 2.0f, 0.25f, 0.0f, -1.0f, INFINITY, 0x1p-149f});
  CHECK(special[0] == 0.0f);
  CHECK(special[1] == 1.0f);
  CHECK(special[2] == -2.0f);
  CHECK(special[3] == -INFINITY);
  CHECK(std::isnan(special[4]));
  CHECK(special[5] == INFINITY);
  CHECK(special[6] == -149.0f);
}

TEST_CASE("sb_atan2 is within 6 ulps and sb_asin and sb_acos within 4, with the quadrants of atan2",
          "[kernels][math][same-bits]") {
  std::vector<float> y = uniform(40000, -10.0, 10.0, 7), x = uniform(40000, -10.0, 10.0, 8);
  // The axes and the diagonals, where the reduction switches branch.
  for (float a : {0.0f, 1.0f, -1.0f, 3.0f})
    for (float b : {0.0f, 1.0f, -1.0f, 3.0f}) {
      y.push_back(a);
      x.push_back(b);
    }
  const std::vector<float> a = onDevice(Atan2, y, x);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double e = std::atan2(double(y[k]), double(x[k]));
    INFO("y " << y[k] << " x " << x[k] << " exact " << e << " got " << a[k]);
    // atan2(+-0, negative) is +-pi in C; the kernels' angles take +pi for both.
    if (y[k] == 0 && x[k] < 0) {
      CHECK(std::fabs(a[k] - M_PI) <= 6 * ulpAt(M_PI));
      continue;
    }
    CHECK(std::fabs(a[k] - e) <= 6 * ulpAt(e));
  }
  std::vector<float> s = uniform(40000, -1.0, 1.0, 9);
  for (float edge : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f}) s.push_back(edge);
  const std::vector<float> as = onDevice(Asin, s), ac = onDevice(Acos, s);
  CHECK(worstUlps(s, as, [&](std::size_t k) { return std::asin(double(s[k])); }) <= 4.0);
  CHECK(worstUlps(s, ac, [&](std::size_t k) { return std::acos(double(s[k])); }) <= 4.0);
  CHECK(std::isnan(onDevice(Asin, {1.5f})[0]));
}

TEST_CASE("sb_length and sb_normalize keep their accuracy for tiny and huge vectors", "[kernels][math][same-bits]") {
  std::vector<float> x, y;
  std::mt19937_64 gen(10);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0), exponent(-60.0, 60.0);
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::exp2(exponent(gen));
    x.push_back(static_cast<float>(mantissa(gen) * scale));
    y.push_back(static_cast<float>(mantissa(gen) * scale));
  }
  const std::vector<float> len = onDevice(Length, x, y), nx = onDevice(NormalizeX, x, y);
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double a = x[k], b = y[k], c = double(x[k]) - double(y[k]);
    const double cf = static_cast<float>(x[k] - y[k]);  // the probe's third component, rounded as the device does
    const double exact_len = std::sqrt(a * a + b * b + cf * cf);
    INFO("x " << x[k] << " y " << y[k] << " c " << c << " length " << exact_len << " got " << len[k]);
    CHECK(std::fabs(len[k] - exact_len) <= 3 * ulpAt(exact_len));
    const double n = std::sqrt(a * a + b * b + 0.25 * a * a);
    const double exact_x = n > 0 ? a / n : 0;
    CHECK(std::fabs(nx[k] - exact_x) <= 3 * ulpAt(exact_x));
  }
  CHECK(onDevice(NormalizeX, {0.0f}, {0.0f})[0] == 0.0f);  // the zero vector stays zero
}
