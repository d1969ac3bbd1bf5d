// The mesh plugins the benchmarks load files with: the usual search path, then
// the plugins of this build tree, so prism-bench runs without installing.
#pragma once

#include "mesh/plugin_registry.h"

namespace prism::bench {

const PluginRegistry& benchPlugins();

}  // namespace prism::bench
