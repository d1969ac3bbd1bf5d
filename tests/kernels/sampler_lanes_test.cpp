// ray_sample_2d8 and ray_sample_1d8, the sampler in eight vector lanes
// (kernels/sampling/), against ray_sample_2d and ray_sample_1d one sample at a
// time on the same inputs: the same bits in every
// lane, with each lane's own group, sample, dimension and sample count (so
// lanes whose permutations cycle-walk a different number of times share a
// vector), in both the stratified and the independent (strata <= 0) modes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "support/shared_context.h"

using namespace prism;

namespace {

const char* kProbe = R"(
#include "sampling/dimensions.h"
/* Work-item k: lanes 8k .. 8k + 7 of each input; seed and strata per item. */
__kernel void sampler_lanes_probe(__global const uint* seed, __global const int* strata, __global const int* strata_id,
                                  __global const int* sample, __global const int* dim, __global const int* sub,
                                  __global const int* subs, int items, __global float* one, __global float* lanes) {
  int k = get_global_id(0);
  if (k >= items) return;
  for (int l = 0; l < 8; ++l) {
    int i = 8 * k + l;
    float2 u = ray_sample_2d(seed[k], strata[k], strata_id[i], sample[i], dim[i], sub[i], subs[i]);
    one[3 * i] = u.x;
    one[3 * i + 1] = u.y;
    one[3 * i + 2] = ray_sample_1d(seed[k], strata[k], strata_id[i], sample[i], dim[8 * k]);
  }
  float8 x, y;
  ray_sample_2d8(seed[k], strata[k], vload8(k, strata_id), vload8(k, sample), vload8(k, dim), vload8(k, sub),
                 vload8(k, subs), &x, &y);
  float xs[8], ys[8], vs[8];
  vstore8(x, 0, xs);
  vstore8(y, 0, ys);
  /* The 1-D value's dimension is one per work-item, as generate's are. */
  vstore8(ray_sample_1d8(seed[k], strata[k], vload8(k, strata_id), vload8(k, sample), dim[8 * k]), 0, vs);
  for (int l = 0; l < 8; ++l) {
    lanes[3 * (8 * k + l)] = xs[l];
    lanes[3 * (8 * k + l) + 1] = ys[l];
    lanes[3 * (8 * k + l) + 2] = vs[l];
  }
}
/* sampler_unit against sampler_unit8 on the same eight values. */
__kernel void unit_probe(__global const float* x, int items, __global float* one, __global float* lanes) {
  int k = get_global_id(0);
  if (k >= items) return;
  for (int l = 0; l < 8; ++l) one[8 * k + l] = sampler_unit(x[8 * k + l]);
  vstore8(sampler_unit8(vload8(k, x)), k, lanes);
}
)";

std::uint32_t bits(float f) {
  std::uint32_t b;
  std::memcpy(&b, &f, sizeof b);
  return b;
}

}  // namespace

TEST_CASE("the sampler in eight lanes gives ray_sample_2d's and ray_sample_1d's bits in every lane", "[kernels][sampling]") {
  const int items = 4096;
  std::mt19937 gen(11);
  std::vector<std::uint32_t> seed(items);
  std::vector<std::int32_t> strata(items), strata_id(8 * items), sample(8 * items), dim(8 * items), sub(8 * items),
      subs(8 * items);
  for (int k = 0; k < items; ++k) {
    seed[k] = gen();
    // Every eighth item independent (aa mode random); others sample counts
    // where the grid's side may need its corrections (a square, or one or two
    // less, up to 2^31 - 1, with one sample a lane), counts past 2^24 (not exact in
    // float), and the common case, 1 to 64 strata of 0 to 16 samples.
    const int kind = k % 8;
    bool one_sub = false;
    if (kind == 7) {
      strata[k] = -static_cast<int>(gen() % 2);
    } else if (kind == 3) {
      const std::int64_t side = k == 3 ? 46341 : 3000 + static_cast<std::int64_t>(gen() % 43340);
      strata[k] = static_cast<std::int32_t>(
          std::min<std::int64_t>(side * side - static_cast<std::int64_t>(gen() % 3), 2147483647));
      one_sub = true;
    } else if (kind == 5) {
      strata[k] = (1 << 24) + 1 + static_cast<int>(gen() % 1000);
      one_sub = true;
    } else {
      strata[k] = 1 + static_cast<int>(gen() % 64);
    }
    for (int l = 0; l < 8; ++l) {
      const int i = 8 * k + l;
      strata_id[i] = static_cast<std::int32_t>(gen());
      subs[i] = one_sub ? 1 : static_cast<int>(gen() % 17);  // 0: a point light's (no samples)
      sub[i] = subs[i] > 0 ? static_cast<int>(gen() % subs[i]) : 0;
      sample[i] = one_sub ? static_cast<int>(gen() % 2147483647u) : static_cast<int>(gen() % 1024);
      dim[i] = static_cast<int>(gen() % 40);
    }
  }
  Context& ctx = test::sharedContext();
  cl_kernel kernel = ctx.kernelFromText(kProbe, "sampler_lanes_probe.cl", "sampler_lanes_probe", "");
  Buffer seed_b(ctx, seed.size() * 4), strata_b(ctx, strata.size() * 4), id_b(ctx, strata_id.size() * 4),
      sample_b(ctx, sample.size() * 4), dim_b(ctx, dim.size() * 4), sub_b(ctx, sub.size() * 4),
      subs_b(ctx, subs.size() * 4), one_b(ctx, 24 * items * sizeof(float)), lanes_b(ctx, 24 * items * sizeof(float));
  seed_b.writeVector(seed);
  strata_b.writeVector(strata);
  id_b.writeVector(strata_id);
  sample_b.writeVector(sample);
  dim_b.writeVector(dim);
  sub_b.writeVector(sub);
  subs_b.writeVector(subs);
  ctx.launch(kernel)
      .arg(seed_b)
      .arg(strata_b)
      .arg(id_b)
      .arg(sample_b)
      .arg(dim_b)
      .arg(sub_b)
      .arg(subs_b)
      .arg(static_cast<cl_int>(items))
      .arg(one_b)
      .arg(lanes_b)
      .run(items);
  const std::vector<float> one = one_b.readVector<float>(24 * items);
  const std::vector<float> lanes = lanes_b.readVector<float>(24 * items);
  int mismatches = 0, inside = 0;
  for (int i = 0; i < 8 * items; ++i) {
    for (int c = 0; c < 3; ++c) {  // x, y, then the 1-D value
      const float a = one[3 * i + c], b = lanes[3 * i + c];
      if (bits(a) != bits(b)) {
        if (++mismatches <= 5) UNSCOPED_INFO("lane " << i << " coordinate " << c << ": one " << a << " lanes " << b);
      }
      inside += a >= 0.0f && a < 1.0f;
    }
  }
  CHECK(mismatches == 0);
  // The points are the sampler's, in [0, 1): not all one value.
  CHECK(inside == 24 * items);
  CHECK(one[0] != one[3]);
}

TEST_CASE("sampler_unit8 clamps as sampler_unit does, at 1 and past it, infinities and NaN too", "[kernels][sampling]") {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> x = {0.0f, -0.0f, 0.5f, std::nextafter(1.0f, 0.0f), 1.0f, std::nextafter(1.0f, 2.0f),
                                2.0f, inf, -inf, nan, -nan, -1.0f, 1e-45f, 0.99999f, 3e38f, -3e38f};
  Context& ctx = test::sharedContext();
  cl_kernel kernel = ctx.kernelFromText(kProbe, "sampler_lanes_probe.cl", "unit_probe", "");
  const int items = static_cast<int>(x.size() / 8);
  Buffer xb(ctx, x.size() * sizeof(float)), one_b(ctx, x.size() * sizeof(float)), lanes_b(ctx, x.size() * sizeof(float));
  xb.writeVector(x);
  ctx.launch(kernel).arg(xb).arg(static_cast<cl_int>(items)).arg(one_b).arg(lanes_b).run(items);
  const std::vector<float> one = one_b.readVector<float>(x.size());
  const std::vector<float> lanes = lanes_b.readVector<float>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    INFO("x " << x[i] << " one " << one[i] << " lanes " << lanes[i]);
    CHECK(bits(one[i]) == bits(lanes[i]));
    // Below 1 stays; 1, above it and NaN become the float just below 1.
    if (x[i] < 1.0f)
      CHECK(bits(one[i]) == bits(x[i]));
    else
      CHECK(one[i] == std::nextafter(1.0f, 0.0f));
  }
}
