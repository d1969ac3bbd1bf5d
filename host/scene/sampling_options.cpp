#include "scene/sampling_options.h"

#include <cmath>
#include <stdexcept>

namespace prism {
namespace {

// Name tables, in enum order.
const char* const kModeNames[] = {"none", "grid", "quincunx", "adaptive", "jitter", "poisson", "random"};
const char* const kFilterNames[] = {"box", "tent", "gaussian", "mitchell"};

template <size_t N>
std::string joinNames(const char* const (&names)[N]) {
  std::string out;
  for (size_t i = 0; i < N; ++i) out += (i ? ", " : "") + std::string(names[i]);
  return out;
}

template <size_t N>
int findName(const char* const (&names)[N], const std::string& name) {
  for (size_t i = 0; i < N; ++i)
    if (name == names[i]) return static_cast<int>(i);
  return -1;
}

}  // namespace

AaMode parseAaMode(const std::string& name) {
  int i = findName(kModeNames, name);
  if (i < 0) throw std::invalid_argument("unknown anti-aliasing mode '" + name + "' (valid: " + aaModeNames() + ")");
  return static_cast<AaMode>(i);
}

FilterKind parseFilterKind(const std::string& name) {
  int i = findName(kFilterNames, name);
  if (i < 0) throw std::invalid_argument("unknown filter '" + name + "' (valid: " + filterNames() + ")");
  return static_cast<FilterKind>(i);
}

const char* aaModeName(AaMode mode) { return kModeNames[static_cast<int>(mode)]; }
const char* filterName(FilterKind kind) { return kFilterNames[static_cast<int>(kind)]; }
std::string aaModeNames() { return joinNames(kModeNames); }
std::string filterNames() { return joinNames(kFilterNames); }

void SamplingOptions::validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
  const std::string mode_name = aaModeName(mode);
  if (spp < 1 || spp > 65536) fail("spp must be in 1..65536, got " + std::to_string(spp));
  switch (mode) {
    case AaMode::None:
      if (spp != 1)
        fail("aa none traces one ray through each pixel centre, so spp must be 1 (got " + std::to_string(spp) +
             "); use aa grid, jitter, poisson or random for more samples per pixel");
      break;
    case AaMode::Quincunx:
    case AaMode::Adaptive:
      if (spp != 1)
        fail("aa " + mode_name + " places its own samples, so spp must be 1 (got " + std::to_string(spp) + ")");
      break;
    case AaMode::Grid: {
      int n = static_cast<int>(std::floor(std::sqrt(static_cast<double>(spp))));
      if (n * n != spp)
        fail("aa grid needs a square spp (n x n samples), got " + std::to_string(spp) +
             "; nearest: " + std::to_string(n * n) + " or " + std::to_string((n + 1) * (n + 1)));
      break;
    }
    case AaMode::Poisson:
      if (spp > kMaxPoissonSpp)
        fail("aa poisson supports at most " + std::to_string(kMaxPoissonSpp) + " samples per pixel, got " +
             std::to_string(spp));
      break;
    case AaMode::Jitter:
    case AaMode::Random:
      break;
  }
  if (mode == AaMode::Adaptive) {
    if (!(adaptive_threshold >= 0) || !std::isfinite(adaptive_threshold))
      fail("the adaptive threshold must be a finite number >= 0, got " + std::to_string(adaptive_threshold));
    if (adaptive_max_level < 0 || adaptive_max_level > kMaxAdaptiveLevel)
      fail("the adaptive maximum level must be in 0.." + std::to_string(kMaxAdaptiveLevel) + ", got " +
           std::to_string(adaptive_max_level));
  }
}

std::uint64_t sampleCount(AaMode mode, int width, int height, int spp) {
  const std::uint64_t w = static_cast<std::uint64_t>(width), h = static_cast<std::uint64_t>(height);
  switch (mode) {
    case AaMode::None:
      return w * h;
    case AaMode::Quincunx:
      return (w + 1) * (h + 1) + w * h;
    case AaMode::Adaptive:
      return (w + 1) * (h + 1);
    default:
      return w * h * static_cast<std::uint64_t>(spp);
  }
}

}  // namespace prism
