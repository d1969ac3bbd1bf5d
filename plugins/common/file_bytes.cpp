// Bounded whole-file reads; see file_bytes.h.
#include "common/file_bytes.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "common/plugin_failure.h"

namespace prism_plugins {

std::string readFileBytes(const std::string& path, std::uint64_t max_bytes) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw PluginFailure(PRISM_PLUGIN_ERROR_IO, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (fstat(fileno(f.get()), &st) != 0)
    throw PluginFailure(PRISM_PLUGIN_ERROR_IO, std::string("cannot stat: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw PluginFailure(PRISM_PLUGIN_ERROR_IO, "not a regular file");
  auto size = static_cast<std::uint64_t>(st.st_size);
  if (size > max_bytes)
    throw PluginFailure(PRISM_PLUGIN_ERROR_LIMIT,
                        "file is " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) +
                            " this reader accepts");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t got = size > 0 ? std::fread(&bytes[0], 1, bytes.size(), f.get()) : 0;
  if (got != bytes.size()) {
    if (std::ferror(f.get())) throw PluginFailure(PRISM_PLUGIN_ERROR_IO, std::string("read error: ") + std::strerror(errno));
    bytes.resize(got);  // the file shrank while we read it: use what is there
  }
  return bytes;
}

}  // namespace prism_plugins
