// Anti-aliasing settings as a scene or a caller states them: the sampling modes
// and reconstruction filters by name, their validation, and how many primary
// samples an image takes. No device here: the scene loader uses it as well as
// the renderer (render/sampler.h has the kernels' side). docs/sampling.md
// describes the modes.
#pragma once

#include <cstdint>
#include <string>

namespace prism {

// Values match AA_MODE_* and FILTER_* in kernels/sampling/sample_modes.h.
enum class AaMode { None, Grid, Quincunx, Adaptive, Jitter, Poisson, Random };
enum class FilterKind { Box, Tent, Gaussian, Mitchell };

// Parse a user's name ("jitter", "mitchell"); unknown names throw
// std::invalid_argument listing the valid ones.
AaMode parseAaMode(const std::string& name);
FilterKind parseFilterKind(const std::string& name);
const char* aaModeName(AaMode mode);
const char* filterName(FilterKind kind);
// "none, grid, quincunx, adaptive, jitter, poisson, random" and "box, tent, gaussian, mitchell".
std::string aaModeNames();
std::string filterNames();

struct SamplingOptions {
  AaMode mode = AaMode::None;
  FilterKind filter = FilterKind::Box;  // quincunx always uses the tent; adaptive uses none
  int spp = 1;                          // samples per pixel of the per-pixel modes
  double adaptive_threshold = 0.1;      // max channel difference between a square's corners
  int adaptive_max_level = 2;           // subdivisions of a pixel's side: up to 2^level squares per side

  // Throws std::invalid_argument naming the option and the reason: spp out of
  // 1..65536, a non-square spp for grid, spp other than 1 for none, quincunx and
  // adaptive (they fix their own samples), poisson above kMaxPoissonSpp, a negative
  // or non-finite threshold, a level outside 0..kMaxAdaptiveLevel.
  void validate() const;
  // The filter the resolve step applies (tent for quincunx).
  FilterKind effectiveFilter() const { return mode == AaMode::Quincunx ? FilterKind::Tent : filter; }
};

constexpr int kMaxPoissonSpp = 4096;
constexpr int kMaxAdaptiveLevel = 8;

// Primary samples (rays) a width x height image takes: W*H for none, W*H*spp for
// grid, jitter, poisson and random, (W+1)(H+1) + W*H for quincunx. Adaptive
// sampling depends on the image: this returns its first pass, the (W+1)(H+1)
// corners; AdaptiveResult::samples has the total.
std::uint64_t sampleCount(AaMode mode, int width, int height, int spp);

}  // namespace prism
