// The builders' inline float neighbours and outward rounding (scene/primitives/bounds.h)
// against the C library's std::nextafter and exact double comparisons.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "scene/primitives/bounds.h"

using namespace prism;

namespace {

bool sameBits(float a, float b) {
  std::uint32_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

float fromBits(std::uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

}  // namespace

TEST_CASE("nextFloatUp and nextFloatDown are std::nextafter towards the infinities", "[host][bounds]") {
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> values = {0.0f,
                               -0.0f,
                               std::numeric_limits<float>::denorm_min(),
                               -std::numeric_limits<float>::denorm_min(),
                               std::numeric_limits<float>::min(),
                               -std::numeric_limits<float>::min(),
                               std::numeric_limits<float>::max(),
                               -std::numeric_limits<float>::max(),
                               inf,
                               -inf,
                               1.0f,
                               -1.0f,
                               1e15f,
                               -1e15f};
  // Every exponent and sign, with random significands, NaN patterns left out.
  std::mt19937 rng(7);
  for (int i = 0; i < 200000; ++i) {
    const float f = fromBits(static_cast<std::uint32_t>(rng()));
    if (!std::isnan(f)) values.push_back(f);
  }
  for (float f : values) {
    INFO(f);
    CHECK(sameBits(nextFloatUp(f), std::nextafter(f, inf)));
    CHECK(sameBits(nextFloatDown(f), std::nextafter(f, -inf)));
  }
  CHECK(std::isnan(nextFloatUp(std::numeric_limits<float>::quiet_NaN())));
  CHECK(std::isnan(nextFloatDown(std::numeric_limits<float>::quiet_NaN())));
}

TEST_CASE("roundDown and roundUp give the nearest floats below and above a double", "[host][bounds]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-140, 120);
  for (int i = 0; i < 200000; ++i) {
    const double x = std::ldexp(mantissa(rng), exponent(rng));
    const float down = roundDown(x), up = roundUp(x);
    INFO(x);
    REQUIRE(double(down) <= x);
    REQUIRE(double(up) >= x);
    // Nearest: the next float beyond is on the other side of x.
    CHECK(double(std::nextafter(down, std::numeric_limits<float>::infinity())) > x);
    CHECK(double(std::nextafter(up, -std::numeric_limits<float>::infinity())) < x);
  }
}
