// What each fuzz target shares: run one reader over the input through the
// host's real MeshBuilder, then validate the result as loadMeshFile would.
// Errors are expected outcomes; only crashes, sanitizer findings, leaks and
// timeouts are failures.
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>

#include "common/plugin_failure.h"
#include "common/sink_writer.h"
#include "mesh/mesh_builder.h"
#include "mesh/mesh_error.h"
#include "mesh/mesh_validation.h"

template <typename Reader>
int fuzzOneInput(const std::uint8_t* data, std::size_t size, Reader read) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  prism::MeshBuilder builder;
  PrismPluginError err;
  std::memset(&err, 0, sizeof err);
  int status = prism_plugins::guardLoad(&err, [&] {
    prism_plugins::SinkWriter sink(builder.sink());
    read(text, sink);
  });
  // The plugin contract: a NUL-terminated message, and a failure status on failure.
  if (std::memchr(err.message, '\0', sizeof err.message) == nullptr) __builtin_trap();
  if (status == PRISM_PLUGIN_OK) {
    try {
      prism::validateMesh(builder.mesh(), "fuzz input");
    } catch (const prism::MeshError&) {
    }
  }
  return 0;
}
