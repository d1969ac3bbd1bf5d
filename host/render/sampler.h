// Anti-aliasing on the device side (the settings, their names and validation are
// scene/sampling_options.h): the filter radii, the Poisson tile generator, launch wrappers for kernels/supersample.cl and kernels/resolve.cl,
// and the adaptive (three-step) sampler, which drives tracing through a callback so
// it can run without the renderer. docs/sampling.md describes the modes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "device/context.h"
#include "scene/sampling_options.h"

namespace prism {

// The program that holds the render loop's small kernels, supersample and
// resolve among them (kernels/render_loop.cl): one build instead of six.
constexpr const char* kRenderLoopProgram = "render_loop.cl";
// Samples a work-item of its generate kernel takes (GENERATE_LANES): launch
// (count + kGenerateLanes - 1) / kGenerateLanes work-items for count samples.
constexpr std::size_t kGenerateLanes = 8;

// Support radius in pixels: box 0.5, tent 1, gaussian 1.5, mitchell 2.
double filterRadius(FilterKind kind);
// The rows and columns of pixels either side of a pixel whose samples its
// resolve reads (kernels/resolve.cl): ceil(radius - 1/2), in float as there.
int filterReach(FilterKind kind);

// N points on the unit torus [0,1)^2 at least `min_distance` apart (toroidal
// distance, computed on the stored float coordinates, which are multiples of
// 2^-24). Made by relaxation dart throwing (McCool and Fiume 1992: the radius
// starts at the packing bound and shrinks by 2% after every 200 consecutive
// misses), then maximin hill climbing (each point tries small moves away from its
// nearest neighbour, which never lowers the minimum distance); best of 4 runs. The
// work is bounded (well under a second at kMaxPoissonSpp) and the result is a
// function of (n, seed) alone: about 0.94 of the packing bound at n = 4, 0.85 at
// 256, 0.78 at 4096.
struct PoissonTile {
  std::vector<float> xy;     // 2 per point
  double min_distance = 0;   // 1 (the period) when n == 1
  double packing_bound = 0;  // sqrt(2 / (sqrt(3) n)): no n points can be farther apart
};
PoissonTile poissonTile(int n, std::uint64_t seed);

// The 32-bit seed the kernels mix into sample positions (as flattenScene does).
std::uint32_t kernelSeed(std::uint64_t seed);

// Sample positions (2 floats a sample, film coordinates) of a whole width x height
// image for a kernel-generated mode (not adaptive), and in `aov_pixel` (if given)
// the pixel whose AOVs each sample writes, or -1.
std::vector<float> samplePositions(Context& context, const SamplingOptions& options, int width, int height,
                                   std::uint64_t seed, std::vector<std::int32_t>* aov_pixel = nullptr);

// Pixels (rgba) from per-sample rgba radiance, numbered as samplePositions
// numbers the samples, through options.effectiveFilter().
std::vector<float> resolveSamples(Context& context, const SamplingOptions& options, int width, int height,
                                  const std::vector<float>& sample_xy, const std::vector<float>& radiance);

// Adaptive sampling. `trace` gets film positions (x, y pairs) and returns their
// colours, the same number of channels (>= 1) for each point, points in order.
using TraceFn = std::function<std::vector<float>(const std::vector<float>& xy)>;

struct AdaptiveResult {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;                    // width*height*channels
  std::vector<std::uint8_t> levels;             // per pixel: the deepest subdivision (0 = corners only)
  std::uint64_t samples = 0;                    // points traced, each once however many pixels share it
  std::vector<std::uint64_t> samples_per_pass;  // pass 0: the corners; pass l: the points level l added
};

// Three steps: trace every pixel corner (shared by neighbours); subdivide each
// square whose four corners differ by more than `threshold` in some channel, level
// by level down to `max_level`, tracing the new points of a level in one call (a
// dyadic grid, so a point shared by squares or pixels is traced once); then each
// pixel is the area-weighted mean of its leaf squares' corner averages.
AdaptiveResult adaptiveSample(int width, int height, double threshold, int max_level, const TraceFn& trace);

}  // namespace prism
