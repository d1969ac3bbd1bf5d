// On-disk cache of compiled OpenCL program binaries, so a second run starts
// without recompiling. Keyed by platform, device, driver version, prism version,
// build options and the full source text; a corrupt or stale entry is a miss.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace prism {

struct DeviceDescription;

// 64-bit FNV-1a; good enough to key a cache, not for security.
std::uint64_t fnv1a64(const std::string& data, std::uint64_t seed = 1469598103934665603ull);

class ProgramCache {
 public:
  // `folder` empty: $PRISM_CACHE_DIR, else $XDG_CACHE_HOME/prism/kernels, else
  // ~/.cache/prism/kernels.
  explicit ProgramCache(std::string folder = "");

  std::string keyFor(const DeviceDescription& device, const std::string& options, const std::string& source) const;
  std::optional<std::vector<unsigned char>> load(const std::string& key) const;
  // Best effort: a cache that cannot be written only costs time later.
  void store(const std::string& key, const std::vector<unsigned char>& binary) const;
  const std::string& folder() const { return m_folder; }

 private:
  std::string m_folder;
};

}  // namespace prism
