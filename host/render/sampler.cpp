#include "render/sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "kernels/sampling/sample_modes.h"

namespace prism {

static_assert(static_cast<int>(AaMode::None) == AA_MODE_NONE && static_cast<int>(AaMode::Grid) == AA_MODE_GRID &&
                  static_cast<int>(AaMode::Quincunx) == AA_MODE_QUINCUNX &&
                  static_cast<int>(AaMode::Adaptive) == AA_MODE_ADAPTIVE &&
                  static_cast<int>(AaMode::Jitter) == AA_MODE_JITTER &&
                  static_cast<int>(AaMode::Poisson) == AA_MODE_POISSON &&
                  static_cast<int>(AaMode::Random) == AA_MODE_RANDOM,
              "AaMode values are the kernels' AA_MODE_*");
static_assert(static_cast<int>(FilterKind::Box) == FILTER_BOX && static_cast<int>(FilterKind::Tent) == FILTER_TENT &&
                  static_cast<int>(FilterKind::Gaussian) == FILTER_GAUSSIAN &&
                  static_cast<int>(FilterKind::Mitchell) == FILTER_MITCHELL,
              "FilterKind values are the kernels' FILTER_*");

namespace {

// SplitMix64 (Steele, Lea and Flood 2014): a seedable generator whose output is
// fixed by the algorithm, unlike the standard library's distributions.
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // A multiple of 2^-24 in [0, 1): exactly representable as a float.
  double unit24() { return static_cast<double>(next() >> 40) * (1.0 / 16777216.0); }
};

double torusDelta(double a, double b) {
  double d = std::fabs(a - b);
  return std::min(d, 1.0 - d);
}

double torusDistance2(const float* p, const float* q) {
  double dx = torusDelta(p[0], q[0]), dy = torusDelta(p[1], q[1]);
  return dx * dx + dy * dy;
}

double minTorusDistance(const std::vector<float>& xy) {
  const size_t n = xy.size() / 2;
  if (n < 2) return 1.0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) best = std::min(best, torusDistance2(&xy[2 * i], &xy[2 * j]));
  return std::sqrt(best);
}

// Points of the unit torus in a grid of cells at least `reach` wide, so every
// point nearer than `reach` to a query lies in the 3 x 3 cells around it.
class TorusGrid {
 public:
  explicit TorusGrid(double reach) : m_cells(std::max(1, static_cast<int>(std::floor(1.0 / reach)))) {
    m_grid.resize(static_cast<size_t>(m_cells) * m_cells);
  }
  int cellOf(const float* p) const {
    int cx = std::min(m_cells - 1, static_cast<int>(p[0] * m_cells));
    int cy = std::min(m_cells - 1, static_cast<int>(p[1] * m_cells));
    return cy * m_cells + cx;
  }
  void insert(int id, const float* p) { m_grid[cellOf(p)].push_back(id); }
  void remove(int id, const float* p) {
    auto& cell = m_grid[cellOf(p)];
    cell.erase(std::find(cell.begin(), cell.end(), id));
  }
  // Squared distance from p to the nearest stored point other than `skip`,
  // capped at `cap2` (at most reach^2: farther points are not looked at).
  double nearest2(const float* p, const std::vector<float>& xy, int skip, double cap2) const {
    double best = cap2;
    if (m_cells < 3) {
      for (size_t i = 0; i < xy.size() / 2; ++i)
        if (static_cast<int>(i) != skip) best = std::min(best, torusDistance2(p, &xy[2 * i]));
      return best;
    }
    int c = cellOf(p), cx = c % m_cells, cy = c / m_cells;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        for (int i :
             m_grid[static_cast<size_t>((cy + dy + m_cells) % m_cells) * m_cells + (cx + dx + m_cells) % m_cells])
          if (i != skip) best = std::min(best, torusDistance2(p, &xy[2 * i]));
    return best;
  }

 private:
  int m_cells;
  std::vector<std::vector<int>> m_grid;
};

// Relaxation dart throwing: darts at a radius that starts at `start_radius`
// (no larger than the packing bound, so the grid's reach covers it) and shrinks by
// 2% after every 200 consecutive misses.
std::vector<float> dartThrow(int n, double start_radius, SplitMix64& rng, TorusGrid& grid) {
  constexpr int kMissesBeforeShrink = 200;
  constexpr double kShrink = 0.98;
  std::vector<float> xy;
  xy.reserve(2 * static_cast<size_t>(n));
  double r2 = start_radius * start_radius;
  int misses = 0;
  while (static_cast<int>(xy.size() / 2) < n) {
    float c[2] = {static_cast<float>(rng.unit24()), static_cast<float>(rng.unit24())};
    if (grid.nearest2(c, xy, -1, r2) >= r2) {
      grid.insert(static_cast<int>(xy.size() / 2), c);
      xy.push_back(c[0]);
      xy.push_back(c[1]);
      misses = 0;
    } else if (++misses == kMissesBeforeShrink) {
      r2 *= kShrink * kShrink;
      misses = 0;
    }
  }
  return xy;
}

// Maximin hill climbing: each point in turn tries a few moves within half its
// nearest-neighbour distance and keeps the one that takes it farthest from its
// nearest neighbour. Only distances to the moved point change, and its nearest one
// grows, so the minimum distance of the set never falls.
void spreadOut(std::vector<float>& xy, int sweeps, double reach, SplitMix64& rng, TorusGrid& grid) {
  constexpr int kTries = 8;
  const int n = static_cast<int>(xy.size() / 2);
  const double cap2 = reach * reach;
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (int i = 0; i < n; ++i) {
      float* p = &xy[2 * i];
      double best2 = grid.nearest2(p, xy, i, cap2);
      const double step = 0.5 * std::sqrt(best2);
      float best[2] = {p[0], p[1]};
      for (int t = 0; t < kTries; ++t) {
        auto wrap = [](double v) {
          v -= std::floor(v);
          float f = static_cast<float>(std::ldexp(std::floor(std::ldexp(v, 24)), -24));  // keep 24 bits, in [0, 1)
          return f >= 1.0f ? 0.0f : f;
        };
        float c[2] = {wrap(p[0] + step * (2 * rng.unit24() - 1)), wrap(p[1] + step * (2 * rng.unit24() - 1))};
        double d2 = grid.nearest2(c, xy, i, cap2);
        if (d2 > best2) {
          best2 = d2;
          best[0] = c[0];
          best[1] = c[1];
        }
      }
      if (best[0] != p[0] || best[1] != p[1]) {
        grid.remove(i, p);
        p[0] = best[0];
        p[1] = best[1];
        grid.insert(i, p);
      }
    }
}

// Adaptive sampling's point key -> its colour's slot: a dense table over the
// dyadic grid when it is small enough (fast), else a hash map (a high level on a
// large image).
class PointIndex {
 public:
  explicit PointIndex(std::uint64_t grid_points) {
    if (grid_points <= kDenseLimit) m_dense.assign(static_cast<size_t>(grid_points), kAbsent);
  }
  void put(std::uint64_t key, std::uint32_t slot) {
    if (!m_dense.empty())
      m_dense[static_cast<size_t>(key)] = slot;
    else
      m_sparse.emplace(key, slot);
  }
  bool has(std::uint64_t key) const {
    return !m_dense.empty() ? m_dense[static_cast<size_t>(key)] != kAbsent : m_sparse.count(key) != 0;
  }
  std::uint32_t at(std::uint64_t key) const {
    return !m_dense.empty() ? m_dense[static_cast<size_t>(key)] : m_sparse.at(key);
  }

 private:
  static constexpr std::uint64_t kDenseLimit = std::uint64_t{1} << 24;  // 64 MiB of slots
  static constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;
  std::vector<std::uint32_t> m_dense;
  std::unordered_map<std::uint64_t, std::uint32_t> m_sparse;
};

void checkCount(std::uint64_t count, const char* what) {
  if (count > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(count) + " is more than one launch can hold");
}

}  // namespace

int filterReach(FilterKind kind) {
  return static_cast<int>(std::ceil(static_cast<float>(filterRadius(kind)) - 0.5f));
}

double filterRadius(FilterKind kind) {
  switch (kind) {
    case FilterKind::Box:
      return 0.5;
    case FilterKind::Tent:
      return 1.0;
    case FilterKind::Gaussian:
      return GAUSSIAN_RADIUS;
    case FilterKind::Mitchell:
      return 2.0;
  }
  return 0.5;
}

PoissonTile poissonTile(int n, std::uint64_t seed) {
  if (n < 1 || n > kMaxPoissonSpp)
    throw std::invalid_argument("a Poisson tile needs 1.." + std::to_string(kMaxPoissonSpp) + " points, got " +
                                std::to_string(n));
  constexpr int kRuns = 4;
  // About 40 sweeps of 1024 points' work at most: a fraction of a second.
  const int sweeps = std::clamp(40 * 1024 / n, 8, 40);
  PoissonTile tile;
  tile.packing_bound = std::sqrt(2.0 / (std::sqrt(3.0) * n));
  if (n == 1) {
    SplitMix64 rng{seed};
    tile.xy = {static_cast<float>(rng.unit24()), static_cast<float>(rng.unit24())};
    tile.min_distance = 1.0;
    return tile;
  }
  SplitMix64 seeds{seed ^ 0x5A17E5D0C0FFEEull};
  for (int run = 0; run < kRuns; ++run) {
    SplitMix64 rng{seeds.next()};
    TorusGrid grid(tile.packing_bound);
    std::vector<float> xy = dartThrow(n, tile.packing_bound, rng, grid);
    spreadOut(xy, sweeps, tile.packing_bound, rng, grid);
    double d = minTorusDistance(xy);
    if (tile.xy.empty() || d > tile.min_distance) {
      tile.xy = std::move(xy);
      tile.min_distance = d;
    }
  }
  return tile;
}

std::uint32_t kernelSeed(std::uint64_t seed) { return static_cast<std::uint32_t>(seed ^ (seed >> 32)); }

std::vector<float> samplePositions(Context& context, const SamplingOptions& options, int width, int height,
                                   std::uint64_t seed, std::vector<std::int32_t>* aov_pixel) {
  options.validate();
  if (options.mode == AaMode::Adaptive)
    throw std::invalid_argument("adaptive sampling places its samples on the host (adaptiveSample)");
  const std::uint64_t total = sampleCount(options.mode, width, height, options.spp);
  checkCount(total, "samples");
  const int count = static_cast<int>(total);
  std::vector<float> tile_xy(2, 0.0f);  // a buffer may not be empty
  if (options.mode == AaMode::Poisson) tile_xy = poissonTile(options.spp, seed).xy;
  Buffer tile(context, tile_xy.size() * sizeof(float));
  tile.writeVector(tile_xy);
  Buffer xy(context, 2 * total * sizeof(float)), aov(context, total * sizeof(std::int32_t));
  context.launch(context.kernel(kRenderLoopProgram, "supersample"))
      .arg(static_cast<cl_int>(options.mode))
      .arg(static_cast<cl_int>(width))
      .arg(static_cast<cl_int>(height))
      .arg(static_cast<cl_int>(options.spp))
      .arg(static_cast<cl_uint>(kernelSeed(seed)))
      .arg(tile)
      .arg(static_cast<cl_long>(0))
      .arg(static_cast<cl_int>(count))
      .arg(xy)
      .arg(aov)
      .run(total);
  if (aov_pixel) *aov_pixel = aov.readVector<std::int32_t>(total);
  return xy.readVector<float>(2 * total);
}

std::vector<float> resolveSamples(Context& context, const SamplingOptions& options, int width, int height,
                                  const std::vector<float>& sample_xy, const std::vector<float>& radiance) {
  options.validate();
  if (options.mode == AaMode::Adaptive)
    throw std::invalid_argument("adaptive sampling resolves its pixels on the host (adaptiveSample)");
  const std::uint64_t total = sampleCount(options.mode, width, height, options.spp);
  if (sample_xy.size() != 2 * total || radiance.size() != 4 * total)
    throw std::invalid_argument("resolveSamples: expected " + std::to_string(total) + " samples (xy and rgba), got " +
                                std::to_string(sample_xy.size() / 2) + " positions and " +
                                std::to_string(radiance.size() / 4) + " colours");
  checkCount(total, "samples");
  const size_t pixels = static_cast<size_t>(width) * height;
  Buffer xy(context, sample_xy.size() * sizeof(float)), rad(context, radiance.size() * sizeof(float));
  xy.writeVector(sample_xy);
  rad.writeVector(radiance);
  Buffer film(context, 4 * pixels * sizeof(float));
  context.launch(context.kernel(kRenderLoopProgram, "resolve"))
      .arg(static_cast<cl_int>(options.mode))
      .arg(static_cast<cl_int>(options.effectiveFilter()))
      .arg(static_cast<cl_int>(width))
      .arg(static_cast<cl_int>(height))
      .arg(static_cast<cl_int>(options.spp))
      .arg(xy)
      .arg(rad)
      .arg(static_cast<cl_int>(0))  // every sample of the frame
      .arg(static_cast<cl_int>(0))
      .arg(static_cast<cl_int>(pixels))
      .arg(film)
      .run(pixels);
  return film.readVector<float>(4 * pixels);
}

AdaptiveResult adaptiveSample(int width, int height, double threshold, int max_level, const TraceFn& trace) {
  if (width < 1 || height < 1) throw std::invalid_argument("adaptiveSample: empty image");
  if (max_level < 0 || max_level > kMaxAdaptiveLevel)
    throw std::invalid_argument("adaptiveSample: max_level must be in 0.." + std::to_string(kMaxAdaptiveLevel));
  // Points live on the dyadic grid of spacing 1/S pixel, S = 2^max_level, as
  // integer coordinates (X, Y) in [0, W*S] x [0, H*S].
  const std::int64_t S = std::int64_t{1} << max_level;
  const std::int64_t row = static_cast<std::int64_t>(width) * S + 1;
  auto key = [row](std::int64_t X, std::int64_t Y) { return static_cast<std::uint64_t>(Y * row + X); };

  AdaptiveResult result;
  result.width = width;
  result.height = height;
  PointIndex index(static_cast<std::uint64_t>(row) * (static_cast<std::uint64_t>(height) * S + 1));
  std::vector<float> colours;

  // Traces the points of `keys` (sorted, unique, not yet traced) in one call.
  auto traceKeys = [&](const std::vector<std::uint64_t>& keys) {
    result.samples += keys.size();
    result.samples_per_pass.push_back(keys.size());
    if (keys.empty()) return;
    std::vector<float> xy(2 * keys.size());
    for (size_t k = 0; k < keys.size(); ++k) {
      xy[2 * k] = static_cast<float>(static_cast<double>(keys[k] % row) / S);
      xy[2 * k + 1] = static_cast<float>(static_cast<double>(keys[k] / row) / S);
    }
    std::vector<float> c = trace(xy);
    if (c.empty() || c.size() % keys.size() != 0)
      throw std::runtime_error("adaptiveSample: the trace callback returned " + std::to_string(c.size()) +
                               " values for " + std::to_string(keys.size()) + " points");
    const int channels = static_cast<int>(c.size() / keys.size());
    if (result.channels == 0) result.channels = channels;
    if (channels != result.channels)
      throw std::runtime_error("adaptiveSample: the trace callback changed from " + std::to_string(result.channels) +
                               " to " + std::to_string(channels) + " channels");
    const size_t base = colours.size() / channels;
    for (size_t k = 0; k < keys.size(); ++k) index.put(keys[k], static_cast<std::uint32_t>(base + k));
    colours.insert(colours.end(), c.begin(), c.end());
  };
  auto colour = [&](std::int64_t X, std::int64_t Y) {
    return &colours[static_cast<size_t>(index.at(key(X, Y))) * result.channels];
  };

  // Step 1: every pixel corner, row by row.
  {
    std::vector<std::uint64_t> corners;
    corners.reserve(static_cast<size_t>(width + 1) * (height + 1));
    for (std::int64_t j = 0; j <= height; ++j)
      for (std::int64_t i = 0; i <= width; ++i) corners.push_back(key(i * S, j * S));
    traceKeys(corners);
  }

  struct Square {
    std::int32_t pixel;
    std::int64_t x, y;  // top-left corner on the dyadic grid
    std::int64_t size;  // side on the dyadic grid
  };
  const size_t pixels = static_cast<size_t>(width) * height;
  std::vector<double> sums(pixels * result.channels, 0.0);
  result.levels.assign(pixels, 0);
  std::vector<Square> active;
  active.reserve(pixels);
  for (std::int64_t j = 0; j < height; ++j)
    for (std::int64_t i = 0; i < width; ++i)
      active.push_back({static_cast<std::int32_t>(j * width + i), i * S, j * S, S});

  // Steps 2 and 3, level by level: split the squares whose corners differ, trace
  // the new points once, and add every leaf into its pixel.
  const int c = result.channels;
  const double pixel_area = static_cast<double>(S) * S;
  for (int level = 0; !active.empty(); ++level) {
    std::vector<Square> split;
    for (const Square& q : active) {
      const float* corner[4] = {colour(q.x, q.y), colour(q.x + q.size, q.y), colour(q.x, q.y + q.size),
                                colour(q.x + q.size, q.y + q.size)};
      double contrast = 0;
      for (int ch = 0; ch < c; ++ch) {
        float lo = std::min({corner[0][ch], corner[1][ch], corner[2][ch], corner[3][ch]});
        float hi = std::max({corner[0][ch], corner[1][ch], corner[2][ch], corner[3][ch]});
        contrast = std::max(contrast, static_cast<double>(hi) - lo);
      }
      if (level < max_level && contrast > threshold) {
        split.push_back(q);
        continue;
      }
      const double weight = static_cast<double>(q.size) * q.size / pixel_area / 4.0;
      double* sum = &sums[static_cast<size_t>(q.pixel) * c];
      for (int ch = 0; ch < c; ++ch)
        sum[ch] += weight * ((static_cast<double>(corner[0][ch]) + corner[1][ch]) +
                             (static_cast<double>(corner[2][ch]) + corner[3][ch]));
    }
    if (split.empty()) break;
    std::vector<std::uint64_t> fresh;
    std::vector<Square> next;
    next.reserve(4 * split.size());
    for (const Square& q : split) {
      const std::int64_t h = q.size / 2;
      result.levels[q.pixel] = static_cast<std::uint8_t>(level + 1);
      const std::int64_t pts[5][2] = {
          {q.x + h, q.y}, {q.x, q.y + h}, {q.x + h, q.y + h}, {q.x + 2 * h, q.y + h}, {q.x + h, q.y + 2 * h}};
      for (const auto& p : pts)
        if (!index.has(key(p[0], p[1]))) fresh.push_back(key(p[0], p[1]));
      next.push_back({q.pixel, q.x, q.y, h});
      next.push_back({q.pixel, q.x + h, q.y, h});
      next.push_back({q.pixel, q.x, q.y + h, h});
      next.push_back({q.pixel, q.x + h, q.y + h, h});
    }
    std::sort(fresh.begin(), fresh.end());
    fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());
    traceKeys(fresh);
    active = std::move(next);
  }

  result.pixels.resize(pixels * c);
  for (size_t k = 0; k < result.pixels.size(); ++k) result.pixels[k] = static_cast<float>(sums[k]);
  return result;
}

}  // namespace prism
