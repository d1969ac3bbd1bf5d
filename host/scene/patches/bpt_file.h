// Reading Bezier patch files (.bpt, as Newell's teapot is shared): the patch
// count, then for each patch its degrees "n m" and (n + 1)(m + 1) points, xyz
// each, i along u and then j along v. Bicubic patches (3 3) only.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "scene/patches/bezier_patch.h"

namespace prism {

// More patches than this in one file are refused before anything is read into memory.
constexpr std::size_t kMaxPatchesPerFile = 1000000;

// A file that cannot be read as patches: "PATH:LINE: what is wrong".
struct PatchFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<BezierPatch> parseBpt(const std::string& text, const std::string& name);
// Reads a regular file (a FIFO or a device would block or never end).
std::vector<BezierPatch> readBptFile(const std::string& path);

}  // namespace prism
