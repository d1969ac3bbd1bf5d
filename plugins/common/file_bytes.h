// Reads a whole mesh file into memory, refusing what is not a regular file (a
// FIFO or /dev/zero would never end) and files beyond a size cap, so that
// every later bound can be checked against the real byte count.
#pragma once

#include <cstdint>
#include <string>

namespace prism_plugins {

// 8 GiB: far beyond any mesh prism renders, small enough to fail cleanly.
constexpr std::uint64_t kMaxMeshFileBytes = 8ull << 30;

// Throws PluginFailure (PRISM_PLUGIN_ERROR_IO or _LIMIT).
std::string readFileBytes(const std::string& path, std::uint64_t max_bytes = kMaxMeshFileBytes);

}  // namespace prism_plugins
