// Test main: the test binaries link the library statically, so the plugin
// search's "plugins/ next to libprism" would look beside the test executable;
// point it at the build tree's plugins unless the caller chose a folder.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdlib>

int main(int argc, char* argv[]) {
  setenv("PRISM_PLUGIN_PATH", PRISM_BINARY_DIR "/plugins", /*overwrite=*/0);
  return Catch::Session().run(argc, argv);
}
