#include "device/program_cache.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "device/device_list.h"
#include "prism_config.h"

namespace prism {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'S', 'M', 'B', 'I', 'N', '1'};

std::string defaultFolder() {
  if (const char* own = std::getenv("PRISM_CACHE_DIR"); own && *own) return own;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/prism/kernels";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/prism/kernels";
  return "";
}

std::uint64_t checksum(const std::vector<unsigned char>& data) {
  return fnv1a64(std::string(data.begin(), data.end()));
}

}  // namespace

std::uint64_t fnv1a64(const std::string& data, std::uint64_t seed) {
  std::uint64_t h = seed;
  for (unsigned char c : data) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

ProgramCache::ProgramCache(std::string folder) : m_folder(folder.empty() ? defaultFolder() : std::move(folder)) {}

std::string ProgramCache::keyFor(const DeviceDescription& device, const std::string& options,
                                 const std::string& source) const {
  std::string identity = device.platform_name + '\n' + device.platform_version + '\n' + device.name + '\n' +
                         device.driver_version + '\n' + PRISM_VERSION_STRING + '\n' + options + '\n' + source;
  std::ostringstream os;
  os << std::hex << std::setfill('0') << std::setw(16) << fnv1a64(identity) << std::setw(16)
     << fnv1a64(identity, 0x9e3779b97f4a7c15ull);
  return os.str();
}

std::optional<std::vector<unsigned char>> ProgramCache::load(const std::string& key) const {
  if (m_folder.empty()) return std::nullopt;
  std::ifstream in(m_folder + "/" + key + ".bin", std::ios::binary);
  if (!in) return std::nullopt;
  char magic[8];
  std::uint64_t sum = 0, size = 0;
  if (!in.read(magic, 8) || std::memcmp(magic, kMagic, 8) != 0) return std::nullopt;
  if (!in.read(reinterpret_cast<char*>(&sum), 8) || !in.read(reinterpret_cast<char*>(&size), 8)) return std::nullopt;
  if (size == 0 || size > (1ull << 30)) return std::nullopt;
  std::vector<unsigned char> data(size);
  if (!in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(size))) return std::nullopt;
  if (checksum(data) != sum) return std::nullopt;
  return data;
}

void ProgramCache::store(const std::string& key, const std::vector<unsigned char>& binary) const {
  if (m_folder.empty() || binary.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(m_folder, ec);
  if (ec) return;
  // Write then rename, so a concurrent reader never sees half a file.
  std::string final_path = m_folder + "/" + key + ".bin";
  // Unique per process and call: contexts in several threads may store at once.
  static std::atomic<unsigned long> stores{0};
  std::string tmp_path = final_path + ".tmp" + std::to_string(getpid()) + "." + std::to_string(stores++);
  {
    std::ofstream out(tmp_path, std::ios::binary);
    std::uint64_t sum = checksum(binary), size = binary.size();
    out.write(kMagic, 8);
    out.write(reinterpret_cast<const char*>(&sum), 8);
    out.write(reinterpret_cast<const char*>(&size), 8);
    out.write(reinterpret_cast<const char*>(binary.data()), static_cast<std::streamsize>(size));
    if (!out) {
      std::filesystem::remove(tmp_path, ec);
      return;
    }
  }
  std::filesystem::rename(tmp_path, final_path, ec);
  if (ec) std::filesystem::remove(tmp_path, ec);
}

}  // namespace prism
