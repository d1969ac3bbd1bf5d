// Opens one shared library as a prism plugin and checks it against the ABI:
// loadable (dlopen RTLD_NOW | RTLD_LOCAL, so missing symbols fail here and not
// in the middle of a load), exports prism_plugin_entry_v1, same ABI major
// version, a PrismPluginInfo large enough for the fields this host reads, and
// sane contents. The registry keeps what passes; this file only judges.
#pragma once

#include <string>

#include "mesh/plugin_registry.h"

namespace prism {

struct OpenedPlugin {
  PluginCandidate candidate;             // accepted, or refused with a reason
  const PrismPluginInfo* info = nullptr; // set when accepted
  void* handle = nullptr;                // dlopen handle when accepted (caller owns it)
};

OpenedPlugin openPlugin(const std::string& path);

}  // namespace prism
