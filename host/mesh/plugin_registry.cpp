// Plugin discovery; see plugin_registry.h for the search order.
#include "mesh/plugin_registry.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstddef>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "mesh/plugin_library.h"

namespace fs = std::filesystem;

namespace prism {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The folder of the shared object (libprism.so, or the executable when the
// library is linked statically) that holds this function.
std::string folderOfThisLibrary() {
  Dl_info dl{};
  if (dladdr(reinterpret_cast<void*>(&folderOfThisLibrary), &dl) == 0 || dl.dli_fname == nullptr) return {};
  std::error_code ec;
  fs::path p = fs::canonical(dl.dli_fname, ec);
  if (ec) {
    // The main program may be reported by a bare name; /proc knows its path.
    p = fs::canonical("/proc/self/exe", ec);
    if (ec) return {};
  }
  return p.parent_path().string();
}

}  // namespace

std::vector<std::string> PluginRegistry::defaultSearchPath() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("PRISM_PLUGIN_PATH")) {
    std::string all = env;
    std::size_t start = 0;
    while (start <= all.size()) {
      std::size_t end = all.find(':', start);
      if (end == std::string::npos) end = all.size();
      if (end > start) dirs.push_back(all.substr(start, end - start));
      start = end + 1;
    }
  }
  // Installed, the plugins sit in <libdir>/prism/plugins; in the build tree, in
  // build/plugins beside build/libprism.so.
  std::string lib = folderOfThisLibrary();
  if (!lib.empty()) {
    dirs.push_back((fs::path(lib) / "prism" / "plugins").string());
    dirs.push_back((fs::path(lib) / "plugins").string());
  }
  return dirs;
}

const PluginRegistry& PluginRegistry::global() {
  static const PluginRegistry registry(defaultSearchPath());
  return registry;
}

PluginRegistry::PluginRegistry(std::vector<std::string> search_dirs) : m_search_dirs(std::move(search_dirs)) {
  std::vector<fs::path> seen;  // the same folder named twice is scanned once
  for (const std::string& dir : m_search_dirs) {
    std::error_code ec;
    fs::path canonical = fs::canonical(dir, ec);
    if (ec || !fs::is_directory(canonical, ec)) continue;
    if (std::find(seen.begin(), seen.end(), canonical) != seen.end()) continue;
    seen.push_back(canonical);
    scanFolder(dir);
  }
}

// Accepted plugins are never dlclose'd: their code may have registered exit
// handlers or thread-local destructors (C++ runtimes do), and unloading it
// before those run is a classic crash at exit. The registry lives as long as
// the process in practice (global()), so this costs nothing.
PluginRegistry::~PluginRegistry() = default;

void PluginRegistry::scanFolder(const std::string& dir) {
  std::vector<std::string> libraries;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path& p = it->path();
    if (p.extension() != ".so") continue;
    std::error_code type_ec;
    if (!fs::is_regular_file(p, type_ec)) continue;  // follows symlinks
    libraries.push_back(p.string());
  }
  std::sort(libraries.begin(), libraries.end());  // a stable order, whatever the file system's
  for (const std::string& path : libraries) consider(path);
}

void PluginRegistry::consider(const std::string& path) {
  OpenedPlugin opened = openPlugin(path);
  if (opened.candidate.accepted) {
    if (const LoadedPlugin* earlier = findByName(opened.candidate.name)) {
      opened.candidate.accepted = false;
      opened.candidate.reason = "plugin '" + opened.candidate.name + "' was already loaded from " + earlier->path;
      dlclose(opened.handle);
    } else {
      m_plugins.push_back({path, opened.info});
      m_handles.push_back(opened.handle);
    }
  }
  m_candidates.push_back(std::move(opened.candidate));
}

const LoadedPlugin* PluginRegistry::findByExtension(const std::string& extension) const {
  std::string e = lower(!extension.empty() && extension[0] == '.' ? extension.substr(1) : extension);
  for (const LoadedPlugin& p : m_plugins)
    for (std::size_t i = 0; p.info->extensions[i] != nullptr; ++i) {
      const char* x = p.info->extensions[i];
      if (x[0] == '.') ++x;
      if (lower(x) == e) return &p;
    }
  return nullptr;
}

const LoadedPlugin* PluginRegistry::findByContent(const unsigned char* head, std::size_t size) const {
  constexpr std::size_t kProbeEnd = offsetof(PrismPluginInfo, probe) + sizeof(PrismPluginInfo::probe);
  for (const LoadedPlugin& p : m_plugins)
    if (p.info->struct_size >= kProbeEnd && p.info->probe != nullptr && p.info->probe(head, size) != 0) return &p;
  return nullptr;
}

const LoadedPlugin* PluginRegistry::findByName(const std::string& name) const {
  for (const LoadedPlugin& p : m_plugins)
    if (name == p.info->name) return &p;
  return nullptr;
}

std::vector<std::string> PluginRegistry::knownExtensions() const {
  std::vector<std::string> all;
  for (const PluginCandidate& c : m_candidates)
    if (c.accepted) all.insert(all.end(), c.extensions.begin(), c.extensions.end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

}  // namespace prism
