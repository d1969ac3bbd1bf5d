// pow_positive (kernels/common/math.h) on the device against double-precision
// pow of the same float inputs: within the error bound its comment derives from
// OpenCL's accuracy of log2 and exp2, exact where the result is 1, and 0 (not
// NaN) where the result is below every float. any4_t and any8_t against
// OpenCL's any() on every pattern of set lanes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "support/shared_context.h"

using namespace prism;

namespace {

const char* kProbe = R"(
#include "common/math.h"
__kernel void pow_probe(__global const float* x, __global const float* y, __global float* out, int count) {
  int k = get_global_id(0);
  if (k < count) out[k] = pow_positive(x[k], y[k]);
}
)";

std::vector<float> devicePow(const std::vector<float>& x, const std::vector<float>& y) {
  Context& ctx = test::sharedContext();
  cl_kernel kernel = ctx.kernelFromText(kProbe, "pow_probe.cl", "pow_probe", "");
  Buffer xb(ctx, x.size() * sizeof(float)), yb(ctx, y.size() * sizeof(float)), out(ctx, x.size() * sizeof(float));
  xb.writeVector(x);
  yb.writeVector(y);
  ctx.launch(kernel).arg(xb).arg(yb).arg(out).arg(static_cast<cl_int>(x.size())).run(x.size());
  return out.readVector<float>(x.size());
}

}  // namespace

TEST_CASE("pow_positive is within its error bound of double pow", "[kernels][math]") {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<float> x, y;
  // The uses: highlights (cos in (0, 1], shininess 0 to 1e6) and lobe sampling
  // (1 - u in (0, 1], exponent 1 / (n + 1)); then any positive base.
  for (int i = 0; i < 20000; ++i) {
    x.push_back(static_cast<float>(unit(gen)) + std::numeric_limits<float>::min());
    y.push_back(static_cast<float>(std::pow(10.0, 6.5 * unit(gen) - 0.5)));  // 0.3 .. 1e6
  }
  for (int i = 0; i < 20000; ++i) {
    x.push_back(static_cast<float>(std::pow(2.0, 60 * unit(gen) - 30)));
    y.push_back(static_cast<float>(8 * unit(gen) - 4));
  }
  const std::vector<float> got = devicePow(x, y);
  const double ulp = std::ldexp(1.0, -24);
  int checked = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double exact = std::pow(double(x[k]), double(y[k]));
    INFO("x " << x[k] << " y " << y[k] << " exact " << exact << " got " << got[k]);
    REQUIRE(std::isfinite(got[k]));
    if (exact < std::numeric_limits<float>::min()) {  // below the normal floats: only "tiny" is promised
      REQUIRE(got[k] <= 2 * std::numeric_limits<float>::min());
      continue;
    }
    const double z = std::fabs(double(y[k]) * std::log2(double(x[k])));
    const double bound = (3.5 * z * std::log(2.0) + 3) * ulp;
    REQUIRE(std::fabs(got[k] - exact) <= bound * exact);
    ++checked;
  }
  CHECK(checked > 20000);  // most cases land in the normal range
}

TEST_CASE("pow_positive gives exactly 1 at exponent 0 and at base 1, and 0 when the result underflows",
          "[kernels][math]") {
  const std::vector<float> x = {1e-30f, 0.5f, 1.0f, 3e30f, 1.0f, 1.0f, 0.999f, 1e-6f};
  const std::vector<float> y = {0.0f, 0.0f, 0.0f, 0.0f, 7.0f, 1e6f, 1e6f, 1e6f};
  const std::vector<float> got = devicePow(x, y);
  for (int k = 0; k < 6; ++k) CHECK(got[k] == 1.0f);
  CHECK(got[6] == 0.0f);  // 0.999^1e6 = e^-1000
  CHECK(got[7] == 0.0f);
}

namespace {

// any4_t and any8_t against OpenCL's any() on the same lanes: any() looks at
// each lane's sign bit alone, whatever the other bits.
const char* kAnyProbe = R"(
#include "common/math.h"
__kernel void any_probe(__global const int* lanes, __global int* out, int count) {
  int k = get_global_id(0);
  if (k >= count) return;
  int8 m = vload8(k, lanes);
  out[4 * k] = any8_t(m);
  out[4 * k + 1] = any(m);
  out[4 * k + 2] = any4_t(m.lo);
  out[4 * k + 3] = any(m.lo);
}
)";

}  // namespace

TEST_CASE("any4_t and any8_t agree with any() on every pattern of set lanes", "[kernels][math]") {
  // Every pattern of eight set (negative) and clear (non-negative) lanes, each
  // lane's value drawn from both kinds' extremes and ordinary values.
  const std::int32_t set[] = {-1, std::numeric_limits<std::int32_t>::min(), -5, -123456};
  const std::int32_t clear[] = {0, 1, std::numeric_limits<std::int32_t>::max(), 77};
  std::mt19937 gen(3);
  std::vector<std::int32_t> lanes;
  std::vector<int> expected, expected_low;
  for (int round = 0; round < 8; ++round)
    for (int pattern = 0; pattern < 256; ++pattern) {
      for (int l = 0; l < 8; ++l)
        lanes.push_back(((pattern >> l) & 1) ? set[gen() % 4] : clear[gen() % 4]);
      expected.push_back(pattern != 0);
      expected_low.push_back((pattern & 15) != 0);
    }
  const size_t count = expected.size();
  Context& ctx = test::sharedContext();
  cl_kernel kernel = ctx.kernelFromText(kAnyProbe, "any_probe.cl", "any_probe", "");
  Buffer in(ctx, lanes.size() * sizeof(std::int32_t)), out(ctx, 4 * count * sizeof(std::int32_t));
  in.writeVector(lanes);
  ctx.launch(kernel).arg(in).arg(out).arg(static_cast<cl_int>(count)).run(count);
  std::vector<std::int32_t> got = out.readVector<std::int32_t>(4 * count);
  size_t wrong8 = 0, wrong4 = 0, wrong_any = 0;
  for (size_t k = 0; k < count; ++k) {
    wrong_any += (got[4 * k + 1] != 0) != (expected[k] != 0);
    wrong_any += (got[4 * k + 3] != 0) != (expected_low[k] != 0);
    wrong8 += (got[4 * k] != 0) != (got[4 * k + 1] != 0);
    wrong4 += (got[4 * k + 2] != 0) != (got[4 * k + 3] != 0);
  }
  CHECK(wrong_any == 0);  // the references themselves
  CHECK(wrong8 == 0);
  CHECK(wrong4 == 0);
}
