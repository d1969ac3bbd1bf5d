// Finds mesh-format plugins (shared libraries behind include/prism_plugin.h),
// loads the acceptable ones, and remembers why the others were refused, so
// `prism plugins` can list both. The mesh loader asks it for the plugin that
// reads a file extension.
//
// Search order (first plugin of a given name wins):
//   1. each folder in $PRISM_PLUGIN_PATH (colon-separated), in order;
//   2. plugins/ next to the library (or executable) that holds this code, found
//      with dladdr: <prefix>/lib/plugins once installed, build/plugins in the
//      build tree, where plugins/CMakeLists.txt puts them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "prism_plugin.h"

namespace prism {

// One shared library the registry looked at.
struct PluginCandidate {
  std::string path;                     // as found in the search folder
  std::string name;                     // the plugin's own name; "" if it could not be read
  std::string description;              // its one-line description
  std::vector<std::string> extensions;  // lower case, without the dot
  bool accepted = false;
  std::string reason;                   // why it was refused; "" when accepted
};

// A plugin that passed every check, ready to call. Valid while its registry lives.
struct LoadedPlugin {
  std::string path;
  const PrismPluginInfo* info = nullptr;
};

class PluginRegistry {
 public:
  // Scans the folders in order. Missing folders are skipped silently (the
  // default path always names a few that may not exist).
  explicit PluginRegistry(std::vector<std::string> search_dirs);
  ~PluginRegistry();
  PluginRegistry(const PluginRegistry&) = delete;
  PluginRegistry& operator=(const PluginRegistry&) = delete;

  // $PRISM_PLUGIN_PATH's folders, then <dir of libprism>/plugins.
  static std::vector<std::string> defaultSearchPath();
  // The process-wide registry over defaultSearchPath(), scanned on first use
  // (so set PRISM_PLUGIN_PATH before the first mesh is loaded).
  static const PluginRegistry& global();

  const std::vector<std::string>& searchPath() const { return m_search_dirs; }
  // Every library looked at, accepted or not, in search order.
  const std::vector<PluginCandidate>& candidates() const { return m_candidates; }
  const std::vector<LoadedPlugin>& plugins() const { return m_plugins; }

  // The first accepted plugin that reads `extension` (with or without the dot,
  // any case), or nullptr.
  const LoadedPlugin* findByExtension(const std::string& extension) const;
  // For files without an extension: the first accepted plugin whose probe
  // recognises the file's first bytes, or nullptr.
  const LoadedPlugin* findByContent(const unsigned char* head, std::size_t size) const;
  // The first accepted plugin with this name, or nullptr.
  const LoadedPlugin* findByName(const std::string& name) const;
  // Every extension some accepted plugin reads, sorted, without duplicates.
  std::vector<std::string> knownExtensions() const;

 private:
  void scanFolder(const std::string& dir);
  void consider(const std::string& path);

  std::vector<std::string> m_search_dirs;
  std::vector<PluginCandidate> m_candidates;
  std::vector<LoadedPlugin> m_plugins;
  std::vector<void*> m_handles;  // dlopen handles of accepted plugins
};

}  // namespace prism
