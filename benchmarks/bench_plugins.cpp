#include "bench_plugins.h"

#include <string>
#include <vector>

namespace prism::bench {

const PluginRegistry& benchPlugins() {
  static PluginRegistry r = [] {
    std::vector<std::string> dirs = PluginRegistry::defaultSearchPath();
    dirs.push_back(PRISM_BINARY_DIR "/plugins");
    return PluginRegistry(dirs);
  }();
  return r;
}

}  // namespace prism::bench
