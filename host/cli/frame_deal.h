// How `prism render` deals an animation's frames over MPI ranks (mpi_ranks.h).
// Header-only: the command links the C API alone, and the tests include it.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace prism_cli {

// An animation's frames over `parts` processes. While every part can have a
// frame of its own, the frames go whole, in turns: of the first
// frames - frames % parts, the k-th to part k mod parts. Each of the
// frames % parts frames left over is then shared, as a still is, by a group of
// the parts (group g: the parts p with p mod (frames % parts) == g, in order),
// so that no part stands idle while the last frames are rendered.
struct FrameDeal {
  std::vector<std::uint32_t> whole;  // the frames (from 0) this part renders alone, in order
  bool shares = false;               // whether it then shares one of the frames left over
  std::uint32_t shared_frame = 0;    // which
  std::uint32_t group = 0;           // the group sharing it (g above)
  std::uint32_t group_part = 0;      // this part's place in that group
  std::uint32_t group_parts = 1;     // the group's size
};
// Throws std::invalid_argument unless part < parts.
inline FrameDeal dealFrames(std::uint32_t frames, std::uint32_t part, std::uint32_t parts) {
  if (parts == 0 || part >= parts) throw std::invalid_argument("dealFrames: part must be below parts");
  FrameDeal deal;
  const std::uint32_t left_over = frames % parts, whole = frames - left_over;
  for (std::uint32_t frame = part; frame < whole; frame += parts) deal.whole.push_back(frame);
  if (left_over > 0) {
    deal.shares = true;
    deal.group = part % left_over;
    deal.shared_frame = whole + deal.group;
    deal.group_part = part / left_over;
    deal.group_parts = (parts - deal.group + left_over - 1) / left_over;
  }
  return deal;
}

}  // namespace prism_cli
