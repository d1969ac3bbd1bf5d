// Anti-aliasing: sample positions (kernels/supersample.cl), reconstruction
// (kernels/resolve.cl) and the adaptive sampler (host/render/sampler.cpp), against
// counts, geometry and convergence rates that fix the right answer independently.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "render/sampler.h"
#include "support/square_coverage.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

SamplingOptions opts(AaMode mode, int spp = 1, FilterKind filter = FilterKind::Box) {
  SamplingOptions o;
  o.mode = mode;
  o.spp = spp;
  o.filter = filter;
  return o;
}

// A host generator for test inputs (edges, images), independent of the kernels' RNG.
struct TestRng {
  std::uint64_t s;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) * (1.0 / 9007199254740992.0);
  }
};

// Area of the unit square [0,1]^2 on the side n.(p - q) >= 0 of a line, by
// clipping the square (Sutherland-Hodgman) and the shoelace formula.
double halfPlaneArea(double qx, double qy, double nx, double ny) {
  return prism::test::squareCoverage(0, 0, qx, qy, nx, ny);
}

struct Edge {
  double qx, qy, nx, ny, coverage;
};

// One straight edge through each pixel of a size x size image: a random point
// inside the pixel and a random direction.
std::vector<Edge> randomEdges(int size, std::uint64_t seed) {
  TestRng rng{seed * 7919 + 17};
  std::vector<Edge> edges;
  for (int p = 0; p < size * size; ++p) {
    double qx = rng.next(), qy = rng.next(), a = 2 * M_PI * rng.next();
    Edge e{qx, qy, std::cos(a), std::sin(a), 0};
    e.coverage = halfPlaneArea(qx, qy, e.nx, e.ny);
    edges.push_back(e);
  }
  return edges;
}

// RMS error of the box-filtered estimate of each pixel's edge coverage: the step
// function evaluated at the kernel's sample positions, resolved by the kernel.
double edgeRmsError(AaMode mode, int spp, int size, int seeds) {
  double sum2 = 0;
  int n = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    SamplingOptions o = opts(mode, spp);
    std::vector<float> xy = samplePositions(sharedContext(), o, size, size, 1000 + seed);
    std::vector<Edge> edges = randomEdges(size, seed);
    std::vector<float> radiance(2 * xy.size());
    for (size_t k = 0; k < xy.size() / 2; ++k) {
      int pixel = static_cast<int>(k) / spp;
      double x = xy[2 * k] - pixel % size, y = xy[2 * k + 1] - pixel / size;
      const Edge& e = edges[pixel];
      float v = e.nx * (x - e.qx) + e.ny * (y - e.qy) >= 0 ? 1.0f : 0.0f;
      for (int c = 0; c < 4; ++c) radiance[4 * k + c] = v;
    }
    std::vector<float> film = resolveSamples(sharedContext(), o, size, size, xy, radiance);
    for (int p = 0; p < size * size; ++p) {
      double d = film[4 * p] - edges[p].coverage;
      sum2 += d * d;
      ++n;
    }
  }
  return std::sqrt(sum2 / n);
}

// Least-squares slope of log(error) against log(spp).
double logLogSlope(const std::vector<int>& spp, const std::vector<double>& err) {
  double mx = 0, my = 0;
  for (size_t k = 0; k < spp.size(); ++k) {
    mx += std::log(spp[k]);
    my += std::log(err[k]);
  }
  mx /= spp.size();
  my /= spp.size();
  double sxy = 0, sxx = 0;
  for (size_t k = 0; k < spp.size(); ++k) {
    double dx = std::log(spp[k]) - mx;
    sxy += dx * (std::log(err[k]) - my);
    sxx += dx * dx;
  }
  return sxy / sxx;
}

// Inverse of the kernel's Hilbert mapping (Wikipedia's xy2d), written separately.
std::uint64_t hilbertIndex(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    std::uint32_t rx = (x & s) > 0, ry = (y & s) > 0;
    d += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = 65535u - x;
        y = 65535u - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

// The filters from their textbook definitions, in double.
double filter1d(FilterKind f, double d) {
  double a = std::fabs(d);
  switch (f) {
    case FilterKind::Box:
      return d >= -0.5 && d < 0.5 ? 1 : 0;
    case FilterKind::Tent:
      return std::max(0.0, 1 - a);
    case FilterKind::Gaussian:
      return std::max(0.0, std::exp(-2 * d * d) - std::exp(-2 * 1.5 * 1.5));
    case FilterKind::Mitchell: {
      const double B = 1.0 / 3, C = 1.0 / 3;
      if (a < 1) return ((12 - 9 * B - 6 * C) * a * a * a + (-18 + 12 * B + 6 * C) * a * a + (6 - 2 * B)) / 6;
      if (a < 2)
        return ((-B - 6 * C) * a * a * a + (6 * B + 30 * C) * a * a + (-12 * B - 48 * C) * a + (8 * B + 24 * C)) / 6;
      return 0;
    }
  }
  return 0;
}

}  // namespace

TEST_CASE("sampling mode and filter names parse, and a bad name lists the valid ones", "[sampling]") {
  CHECK(parseAaMode("quincunx") == AaMode::Quincunx);
  CHECK(parseAaMode("poisson") == AaMode::Poisson);
  CHECK(parseFilterKind("mitchell") == FilterKind::Mitchell);
  for (AaMode m : {AaMode::None, AaMode::Grid, AaMode::Quincunx, AaMode::Adaptive, AaMode::Jitter, AaMode::Poisson,
                   AaMode::Random})
    CHECK(parseAaMode(aaModeName(m)) == m);
  try {
    parseAaMode("supersample");
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("'supersample'") != std::string::npos);
    CHECK(std::string(e.what()).find("none, grid, quincunx, adaptive, jitter, poisson, random") != std::string::npos);
  }
  CHECK_THROWS_WITH(parseFilterKind("lanczos"), Catch::Contains("box, tent, gaussian, mitchell"));
  CHECK(filterRadius(FilterKind::Box) == 0.5);
  CHECK(filterRadius(FilterKind::Tent) == 1.0);
  CHECK(filterRadius(FilterKind::Gaussian) == 1.5);
  CHECK(filterRadius(FilterKind::Mitchell) == 2.0);
}

TEST_CASE("sampling options are validated with the reason", "[sampling]") {
  CHECK_THROWS_WITH(opts(AaMode::Grid, 8).validate(), Catch::Contains("square") && Catch::Contains("4 or 9"));
  CHECK_NOTHROW(opts(AaMode::Grid, 16).validate());
  CHECK_THROWS_WITH(opts(AaMode::None, 4).validate(), Catch::Contains("spp must be 1"));
  CHECK_THROWS_WITH(opts(AaMode::Quincunx, 4).validate(), Catch::Contains("quincunx"));
  CHECK_THROWS_WITH(opts(AaMode::Adaptive, 2).validate(), Catch::Contains("adaptive"));
  CHECK_THROWS_WITH(opts(AaMode::Poisson, kMaxPoissonSpp + 1).validate(), Catch::Contains("poisson"));
  CHECK_THROWS_WITH(opts(AaMode::Jitter, 0).validate(), Catch::Contains("spp must be in 1..65536"));
  CHECK_NOTHROW(opts(AaMode::Jitter, 7).validate());
  SamplingOptions a = opts(AaMode::Adaptive);
  a.adaptive_max_level = kMaxAdaptiveLevel + 1;
  CHECK_THROWS_WITH(a.validate(), Catch::Contains("level"));
  a.adaptive_max_level = 2;
  a.adaptive_threshold = -1;
  CHECK_THROWS_WITH(a.validate(), Catch::Contains("threshold"));
  CHECK(opts(AaMode::Quincunx, 1, FilterKind::Mitchell).effectiveFilter() == FilterKind::Tent);
}

TEST_CASE("quincunx traces (W+1)(H+1) + W*H samples: each corner once, shared, and each centre", "[sampling]") {
  const int w = 7, h = 5;
  CHECK(sampleCount(AaMode::Quincunx, w, h, 1) == static_cast<std::uint64_t>((w + 1) * (h + 1) + w * h));
  CHECK(sampleCount(AaMode::Quincunx, 640, 480, 1) == 641ull * 481 + 640ull * 480);
  CHECK(sampleCount(AaMode::Jitter, 640, 480, 16) == 640ull * 480 * 16);
  CHECK(sampleCount(AaMode::None, 640, 480, 1) == 640ull * 480);
  std::vector<std::int32_t> aov;
  std::vector<float> xy = samplePositions(sharedContext(), opts(AaMode::Quincunx), w, h, 1, &aov);
  REQUIRE(xy.size() / 2 == static_cast<size_t>((w + 1) * (h + 1) + w * h));
  std::set<std::pair<float, float>> corners, centres;
  for (size_t k = 0; k < xy.size() / 2; ++k) {
    float x = xy[2 * k], y = xy[2 * k + 1];
    if (x == std::floor(x) && y == std::floor(y)) {
      corners.insert({x, y});
      CHECK(aov[k] == -1);
    } else {
      REQUIRE(x - std::floor(x) == 0.5f);
      REQUIRE(y - std::floor(y) == 0.5f);
      centres.insert({x, y});
      CHECK(aov[k] == static_cast<int>(y) * w + static_cast<int>(x));
    }
  }
  CHECK(corners.size() == static_cast<size_t>((w + 1) * (h + 1)));  // no corner twice
  CHECK(centres.size() == static_cast<size_t>(w * h));
  CHECK(*corners.rbegin() == std::make_pair(static_cast<float>(w), static_cast<float>(h)));
}

TEST_CASE("per-pixel modes keep every sample inside its pixel, are deterministic and mark one AOV sample",
          "[sampling]") {
  const int w = 13, h = 9;
  for (auto [mode, spp] : std::vector<std::pair<AaMode, int>>{{AaMode::None, 1},
                                                              {AaMode::Grid, 9},
                                                              {AaMode::Jitter, 16},
                                                              {AaMode::Jitter, 6},
                                                              {AaMode::Poisson, 8},
                                                              {AaMode::Random, 5}}) {
    INFO(aaModeName(mode) << " spp " << spp);
    std::vector<std::int32_t> aov;
    std::vector<float> xy = samplePositions(sharedContext(), opts(mode, spp), w, h, 42, &aov);
    REQUIRE(xy.size() == 2u * w * h * spp);
    int outside = 0, aov_ok = 0;
    for (size_t k = 0; k < xy.size() / 2; ++k) {
      int pixel = static_cast<int>(k) / spp, i = pixel % w, j = pixel / w;
      if (!(xy[2 * k] >= i && xy[2 * k] < i + 1 && xy[2 * k + 1] >= j && xy[2 * k + 1] < j + 1)) ++outside;
      if (aov[k] == (static_cast<int>(k) % spp == 0 ? pixel : -1)) ++aov_ok;
    }
    CHECK(outside == 0);
    CHECK(aov_ok == w * h * spp);
    CHECK(samplePositions(sharedContext(), opts(mode, spp), w, h, 42) == xy);
    if (mode != AaMode::None && mode != AaMode::Grid)
      CHECK(samplePositions(sharedContext(), opts(mode, spp), w, h, 43) != xy);
  }
  // Grid: the centres of the n x n cells; none: the pixel centre.
  std::vector<float> grid = samplePositions(sharedContext(), opts(AaMode::Grid, 4), w, h, 0);
  CHECK(grid[0] == 0.25f);
  CHECK(grid[1] == 0.25f);
  CHECK(grid[2 * 3] == 0.75f);
  CHECK(grid[2 * 3 + 1] == 0.75f);
  std::vector<float> none = samplePositions(sharedContext(), opts(AaMode::None), w, h, 0);
  CHECK(none[2 * 20] == 20 % w + 0.5f);
  CHECK(none[2 * 20 + 1] == 20 / w + 0.5f);
}

TEST_CASE("jitter puts exactly one sample in each stratum, square or not", "[sampling]") {
  const int w = 8, h = 8;
  for (int spp : {16, 7, 12, 50}) {
    INFO("spp " << spp);
    std::vector<float> xy = samplePositions(sharedContext(), opts(AaMode::Jitter, spp), w, h, 5);
    int n = static_cast<int>(std::lround(std::sqrt(spp)));
    int wrong = 0;
    for (size_t k = 0; k < xy.size() / 2; ++k) {
      int pixel = static_cast<int>(k) / spp, s = static_cast<int>(k) % spp;
      double x = xy[2 * k] - pixel % w, y = xy[2 * k + 1] - pixel / w;
      int stratum;
      if (n * n == spp) {
        stratum = static_cast<int>(y * n) * n + static_cast<int>(x * n);
      } else {
        // Strata are equal intervals of the order-16 Hilbert curve's index.
        std::uint64_t d = hilbertIndex(static_cast<std::uint32_t>(x * 65536), static_cast<std::uint32_t>(y * 65536));
        stratum = static_cast<int>(d * spp >> 32);
      }
      if (stratum != s) ++wrong;
    }
    CHECK(wrong == 0);
  }
}

TEST_CASE("a Poisson tile keeps its stated minimum distance inside every pixel", "[sampling][poisson]") {
  for (int n : {1, 4, 16, 64, 256}) {
    INFO("n " << n);
    PoissonTile tile = poissonTile(n, 99);
    REQUIRE(tile.xy.size() == 2u * n);
    CHECK(poissonTile(n, 99).xy == tile.xy);  // a function of (n, seed)
    if (n == 1) continue;
    CHECK(poissonTile(n, 100).xy != tile.xy);
    CHECK(tile.min_distance <= tile.packing_bound);
    CHECK(tile.min_distance >= 0.75 * tile.packing_bound);  // what the generator reaches, with a margin
    // Plain distances within each pixel, from the kernel's film positions. Adding
    // the pixel index rounds x to the float spacing at the film's width.
    const int w = 16, h = 16;
    const double tolerance = 4 * std::ldexp(1.0, -24) * w;
    std::vector<float> xy = samplePositions(sharedContext(), opts(AaMode::Poisson, n), w, h, 99);
    double worst = 1e9;
    for (int p = 0; p < w * h; ++p)
      for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b) {
          const float* pa = &xy[2 * (p * n + a)];
          const float* pb = &xy[2 * (p * n + b)];
          worst = std::min(worst, std::hypot(static_cast<double>(pa[0]) - pb[0], static_cast<double>(pa[1]) - pb[1]));
        }
    CHECK(worst >= tile.min_distance - tolerance);
  }
}

TEST_CASE("the edge-coverage error falls as spp grows, faster for jittered than for random samples",
          "[sampling][convergence]") {
  // A random straight edge crosses each pixel; the exact coverage is its clipped
  // area. Expected RMS error: random ~ N^-1/2, jittered ~ N^-3/4 (Mitchell 1996).
  const int size = 32, seeds = 3;
  const std::vector<int> square = {4, 16, 64, 256}, other = {2, 8, 32, 128};
  std::vector<double> random_err, jitter_err, hilbert_err, poisson_err;
  for (int spp : square) {
    random_err.push_back(edgeRmsError(AaMode::Random, spp, size, seeds));
    jitter_err.push_back(edgeRmsError(AaMode::Jitter, spp, size, seeds));
    poisson_err.push_back(edgeRmsError(AaMode::Poisson, spp, size, seeds));
  }
  for (int spp : other) hilbert_err.push_back(edgeRmsError(AaMode::Jitter, spp, size, seeds));
  double random_slope = logLogSlope(square, random_err), jitter_slope = logLogSlope(square, jitter_err);
  double hilbert_slope = logLogSlope(other, hilbert_err);
  INFO("slopes: random " << random_slope << ", jitter " << jitter_slope << ", jitter (Hilbert strata) "
                         << hilbert_slope);
  std::ostringstream table;
  for (size_t k = 0; k < square.size(); ++k)
    table << "spp " << square[k] << ": random " << random_err[k] << ", jitter " << jitter_err[k] << ", poisson "
          << poisson_err[k] << "; ";
  INFO(table.str());
  for (size_t k = 1; k < square.size(); ++k) {
    CHECK(random_err[k] < random_err[k - 1]);
    CHECK(jitter_err[k] < jitter_err[k - 1]);
    CHECK(hilbert_err[k] < hilbert_err[k - 1]);
    CHECK(jitter_err[k] < random_err[k]);
    CHECK(poisson_err[k] < random_err[k]);
  }
  CHECK(random_slope == Approx(-0.5).margin(0.08));
  CHECK(jitter_slope < random_slope - 0.1);
  CHECK(jitter_slope == Approx(-0.75).margin(0.1));
  CHECK(hilbert_slope < random_slope - 0.1);
}

TEST_CASE("resolve: weights normalise, box at one sample is the identity, filters match their formulas",
          "[sampling][resolve]") {
  const int w = 9, h = 7;
  TestRng rng{3};
  // A constant image resolves to the constant under every filter and mode.
  for (FilterKind f : {FilterKind::Box, FilterKind::Tent, FilterKind::Gaussian, FilterKind::Mitchell})
    for (auto [mode, spp] : std::vector<std::pair<AaMode, int>>{
             {AaMode::None, 1}, {AaMode::Jitter, 4}, {AaMode::Poisson, 5}, {AaMode::Quincunx, 1}}) {
      INFO(filterName(f) << " " << aaModeName(mode));
      SamplingOptions o = opts(mode, spp, f);
      std::vector<float> xy = samplePositions(sharedContext(), o, w, h, 8);
      std::vector<float> radiance(2 * xy.size());
      for (size_t k = 0; k < radiance.size(); k += 4) {
        radiance[k] = 0.3f;
        radiance[k + 1] = 0.7f;
        radiance[k + 2] = 1.9f;
        radiance[k + 3] = 1.0f;
      }
      std::vector<float> film = resolveSamples(sharedContext(), o, w, h, xy, radiance);
      double worst = 0;
      for (size_t k = 0; k < film.size(); ++k)
        worst = std::max(worst, std::fabs(static_cast<double>(film[k]) - radiance[k % 4]) / radiance[k % 4]);
      CHECK(worst < 1e-6);
    }
  // Random images against a double-precision gather written from the definitions.
  for (FilterKind f : {FilterKind::Box, FilterKind::Tent, FilterKind::Gaussian, FilterKind::Mitchell})
    for (int spp : {1, 6}) {
      INFO(filterName(f) << " spp " << spp);
      SamplingOptions o = opts(spp == 1 ? AaMode::None : AaMode::Random, spp, f);
      std::vector<float> xy = samplePositions(sharedContext(), o, w, h, 4);
      std::vector<float> radiance(2 * xy.size());
      for (float& v : radiance) v = static_cast<float>(rng.next());
      std::vector<float> film = resolveSamples(sharedContext(), o, w, h, xy, radiance);
      if (f == FilterKind::Box && spp == 1) CHECK(film == radiance);  // bit for bit
      double worst = 0;
      for (int p = 0; p < w * h; ++p) {
        double cx = p % w + 0.5, cy = p / w + 0.5, sum[4] = {0, 0, 0, 0}, wsum = 0;
        for (size_t k = 0; k < xy.size() / 2; ++k) {
          double wt = filter1d(f, xy[2 * k] - cx) * filter1d(f, xy[2 * k + 1] - cy);
          wsum += wt;
          for (int c = 0; c < 4; ++c) sum[c] += wt * radiance[4 * k + c];
        }
        for (int c = 0; c < 4; ++c) worst = std::max(worst, std::fabs(film[4 * p + c] - sum[c] / wsum));
      }
      CHECK(worst < 2e-5);
    }
  // Quincunx: centre 1/2, corners 1/8 each.
  std::vector<float> xy = samplePositions(sharedContext(), opts(AaMode::Quincunx), w, h, 0);
  std::vector<float> radiance(2 * xy.size());
  for (float& v : radiance) v = static_cast<float>(rng.next());
  std::vector<float> film = resolveSamples(sharedContext(), opts(AaMode::Quincunx), w, h, xy, radiance);
  const int i = 4, j = 3, p = j * w + i, centre = (w + 1) * (h + 1) + p;
  const int c00 = j * (w + 1) + i, c10 = c00 + 1, c01 = c00 + w + 1, c11 = c01 + 1;
  for (int c = 0; c < 4; ++c) {
    double expected = 0.5 * radiance[4 * centre + c] + 0.125 * (radiance[4 * c00 + c] + radiance[4 * c10 + c] +
                                                                radiance[4 * c01 + c] + radiance[4 * c11 + c]);
    CHECK(film[4 * p + c] == Approx(expected).epsilon(1e-6));
  }
}

TEST_CASE("adaptive sampling traces only the corners of a flat image", "[sampling][adaptive]") {
  const int w = 20, h = 14;
  int calls = 0;
  AdaptiveResult r = adaptiveSample(w, h, 0.05, 3, [&](const std::vector<float>& xy) {
    ++calls;
    return std::vector<float>(3 * xy.size() / 2, 0.25f);
  });
  CHECK(calls == 1);
  CHECK(r.samples == static_cast<std::uint64_t>((w + 1) * (h + 1)));
  CHECK(r.samples == sampleCount(AaMode::Adaptive, w, h, 1));
  CHECK(r.channels == 3);
  CHECK(std::all_of(r.levels.begin(), r.levels.end(), [](std::uint8_t l) { return l == 0; }));
  CHECK(std::all_of(r.pixels.begin(), r.pixels.end(), [](float v) { return v == 0.25f; }));
}

TEST_CASE("adaptive sampling refines a checkerboard only at its edges and traces each point once",
          "[sampling][adaptive]") {
  // Squares of 3.7 pixels, offset so edges cross pixel interiors.
  const int w = 24, h = 18, max_level = 3;
  const double cell = 3.7, offset = 0.31;
  auto checker = [&](double x, double y) {
    return (static_cast<long>(std::floor((x - offset) / cell)) + static_cast<long>(std::floor((y - offset) / cell))) &
           1;
  };
  std::set<std::pair<float, float>> traced;
  int duplicates = 0;
  auto trace = [&](const std::vector<float>& xy) {
    std::vector<float> c;
    for (size_t k = 0; k < xy.size(); k += 2) {
      if (!traced.insert({xy[k], xy[k + 1]}).second) ++duplicates;
      c.push_back(static_cast<float>(checker(xy[k], xy[k + 1])));
    }
    return c;
  };
  AdaptiveResult r = adaptiveSample(w, h, 0.5, max_level, trace);
  CHECK(duplicates == 0);
  CHECK(r.samples == traced.size());
  CHECK(r.samples_per_pass.size() == static_cast<size_t>(max_level + 1));
  const int full = (w * 8 + 1) * (h * 8 + 1);
  CHECK(r.samples < static_cast<std::uint64_t>(full) / 3);
  // Edge lines of the board: x = offset + k * cell, and the same in y (cell > 1,
  // so at most one per pixel and axis; the offset keeps them off the 1/8 grid).
  auto touches = [&](double lo, double hi) { return offset + std::ceil((lo - offset) / cell) * cell <= hi; };
  auto crosses = [&](double lo, double hi) { return offset + (std::floor((lo - offset) / cell) + 1) * cell < hi; };
  int refined = 0, crossed = 0, bad = 0;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      bool touched = touches(i, i + 1) || touches(j, j + 1);
      bool crossed_here = crosses(i, i + 1) || crosses(j, j + 1);
      int level = r.levels[j * w + i];
      if (level > 0) {
        ++refined;
        if (!touched) ++bad;
        if (level != max_level) ++bad;  // an edge stays under every subdivision
      }
      if (crossed_here) {
        ++crossed;
        if (level == 0) ++bad;
      }
    }
  INFO(refined << " refined pixels, " << crossed << " crossed by an edge");
  CHECK(bad == 0);
  CHECK(refined < w * h);
  CHECK(refined >= crossed);
  // Refinement pays: the pixel values approach the exact coverage.
  auto coverageError = [&](int level) {
    AdaptiveResult a = adaptiveSample(w, h, 0.5, level, trace);
    double err = 0;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        double exact = 0;  // by 64 x 64 midpoint sampling
        for (int b = 0; b < 64; ++b)
          for (int a2 = 0; a2 < 64; ++a2) exact += checker(i + (a2 + 0.5) / 64, j + (b + 0.5) / 64);
        err += std::fabs(a.pixels[j * w + i] - exact / 4096);
      }
    return err / (w * h);
  };
  traced.clear();
  double e1 = coverageError(1);
  traced.clear();
  double e3 = coverageError(3);
  INFO("mean error: level 1 " << e1 << ", level 3 " << e3);
  CHECK(e3 < 0.6 * e1);
}
