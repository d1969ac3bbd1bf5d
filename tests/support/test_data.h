// Where the test suite's data files live and how tests load them: tests/data/
// in the source tree (its README lists each file's source and licence), read
// through the plugins built beside the tests. The suite reads nothing outside
// the repository, so a fresh clone runs it whole.
#pragma once

#include <string>

#include "mesh/mesh_loader.h"
#include "mesh/plugin_registry.h"

namespace prism_test {

inline std::string testDataDir() { return PRISM_SOURCE_DIR "/tests/data"; }
inline std::string testMeshDir() { return testDataDir() + "/meshes"; }

// The plugins built into build/plugins. (Test binaries link libprism
// statically, so the default path, plugins/ next to the binary, is not it.)
inline const prism::PluginRegistry& testPluginRegistry() {
  static const prism::PluginRegistry registry({PRISM_BINARY_DIR "/plugins"});
  return registry;
}

// A mesh of tests/data/meshes, e.g. "bunny/bun_zipper_res3.ply"; throws if it
// cannot be read, so a missing file fails its test instead of skipping it.
inline prism::SharedMesh loadTestMesh(const std::string& relative) {
  return prism::loadMeshFile(testMeshDir() + "/" + relative, testPluginRegistry());
}

}  // namespace prism_test
