// Test main: the test binaries link the library statically, so the plugin
// search's "plugins/ next to libprism" would look beside the test executable;
// point it at the build tree's plugins unless the caller chose a folder. The
// kernel caches (PoCL's and prism's) live in the build tree, so a test run
// neither reads nor fills the user's.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdlib>

int main(int argc, char* argv[]) {
  setenv("PRISM_PLUGIN_PATH", PRISM_BINARY_DIR "/plugins", /*overwrite=*/0);
  setenv("POCL_CACHE_DIR", PRISM_BINARY_DIR "/pocl-cache", /*overwrite=*/1);
  setenv("XDG_CACHE_HOME", PRISM_BINARY_DIR "/test-cache", /*overwrite=*/1);
  return Catch::Session().run(argc, argv);
}
