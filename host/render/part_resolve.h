// What a part of a frame shared over processes sends the part that writes the
// image (part 0): the pixels it can resolve from its own samples, and the samples
// part 0 still needs for the pixels nobody can resolve alone. A part holds one
// contiguous stretch of the sample sequence, and in the per-pixel sampling modes
// pixel p's samples are keys [p·spp, (p+1)·spp), so its stretch covers a run of
// whole pixels. The resolve filter of pixel p reads the pixels within `reach`
// rows and columns (reach = ceil(radius − ½)), all within `reach · (width + 1)`
// of p in row-major order: the pixels that far inside the run can be resolved
// by the part itself. Sending them costs 16 bytes a pixel, against 24 bytes a
// sample for the film entries (docs/devices.md, "Pixels, not samples, to rank 0").
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace prism {

struct PartResolve {
  std::uint64_t first_pixel = 0, end_pixel = 0;  // the pixels the part resolves (empty: none)
  // The samples part 0 needs from it, as [first key, end key) ranges in order.
  std::vector<std::pair<std::uint64_t, std::uint64_t>> samples;
};

// For a part with keys [first_key, end_key), spp samples a pixel, and a filter
// reaching `reach_pixels` (reach · (width + 1)) pixels either way.
inline PartResolve partResolve(std::uint64_t first_key, std::uint64_t end_key, std::uint64_t spp,
                               std::uint64_t reach_pixels) {
  PartResolve r;
  if (end_key <= first_key) return r;
  const std::uint64_t whole_first = (first_key + spp - 1) / spp, whole_end = end_key / spp;  // its whole pixels
  if (whole_end < whole_first + 2 * reach_pixels + 1) {  // no pixel far enough inside: all its samples
    r.samples.emplace_back(first_key, end_key);
    return r;
  }
  r.first_pixel = whole_first + reach_pixels;
  r.end_pixel = whole_end - reach_pixels;
  // Part 0 resolves the pixels outside [first_pixel, end_pixel): it needs the
  // samples of every pixel within reach of them, and the split pixels at the ends.
  const std::uint64_t head_end = std::min(end_key, (r.first_pixel + reach_pixels) * spp);
  const std::uint64_t tail_first = std::max(first_key, (r.end_pixel - reach_pixels) * spp);
  if (head_end >= tail_first) {
    r.samples.emplace_back(first_key, end_key);
    return r;
  }
  // Either may be empty: with a box filter (reach 0), a stretch that starts or ends
  // on a pixel's edge leaves part 0 nothing to read there.
  if (head_end > first_key) r.samples.emplace_back(first_key, head_end);
  if (end_key > tail_first) r.samples.emplace_back(tail_first, end_key);
  return r;
}

}  // namespace prism
