// A thin C++ face on the host's PrismMeshSink: each call forwards to the
// callback and throws SinkStopped when the host answers non-zero, so readers
// need no return-code plumbing. Callbacks the host left NULL are skipped.
#pragma once

#include <cstdint>
#include <string>

#include "common/plugin_failure.h"
#include "prism_plugin.h"

namespace prism_plugins {

class SinkWriter {
 public:
  explicit SinkWriter(const PrismMeshSink* sink) : m_sink(sink) {
    if (sink == nullptr) throw PluginFailure(PRISM_PLUGIN_ERROR_INTERNAL, "no sink given");
  }

  void begin(std::uint64_t vertices, std::uint64_t faces) { check(call(m_sink->begin, vertices, faces)); }
  void position(float x, float y, float z) { check(call(m_sink->add_position, x, y, z)); }
  void normal(float x, float y, float z) { check(call(m_sink->add_normal, x, y, z)); }
  void texcoord(float u, float v) { check(call(m_sink->add_texcoord, u, v)); }
  void color(float r, float g, float b) { check(call(m_sink->add_color, r, g, b)); }
  void face(const std::uint32_t* indices, std::uint32_t corners, std::int32_t material) {
    check(call(m_sink->add_face, indices, corners, material));
  }
  void material(const PrismMaterialDesc& m) { check(call(m_sink->add_material, &m)); }
  void warning(const std::string& message, std::uint64_t line = 0) {
    check(call(m_sink->warning, message.c_str(), line));
  }

 private:
  template <typename Fn, typename... Args>
  int call(Fn fn, Args... args) {
    return fn != nullptr ? fn(m_sink->host, args...) : 0;
  }
  static void check(int status) {
    if (status != 0) throw SinkStopped{};
  }

  const PrismMeshSink* m_sink;
};

}  // namespace prism_plugins
