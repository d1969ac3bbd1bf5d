// How prism's own plugins report failure internally: throw PluginFailure
// anywhere in a reader, and guardLoad() at the ABI boundary turns it (and any
// other exception) into a PrismPluginStatus plus a filled PrismPluginError.
// Nothing thrown ever crosses into the host.
#pragma once

#include <cstdint>
#include <cstdio>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>

#include "prism_plugin.h"

namespace prism_plugins {

class PluginFailure : public std::runtime_error {
 public:
  PluginFailure(int status, const std::string& message, std::uint64_t line = 0, std::uint64_t offset = 0)
      : std::runtime_error(message), m_status(status), m_line(line), m_offset(offset) {}
  int status() const { return m_status; }
  std::uint64_t line() const { return m_line; }
  std::uint64_t offset() const { return m_offset; }

 private:
  int m_status;
  std::uint64_t m_line;
  std::uint64_t m_offset;
};

// A malformed file: the most common failure, so it gets a short name.
[[noreturn]] inline void parseError(const std::string& message, std::uint64_t line = 0, std::uint64_t offset = 0) {
  throw PluginFailure(PRISM_PLUGIN_ERROR_PARSE, message, line, offset);
}

// Thrown by SinkWriter when the host asks to stop; the host has the reason.
struct SinkStopped {};

inline void fillError(PrismPluginError* err, const char* message, std::uint64_t line, std::uint64_t offset) {
  if (err == nullptr) return;
  std::snprintf(err->message, sizeof err->message, "%s", message);
  err->line = line;
  err->offset = offset;
}

// Runs a reader and converts every way it can fail into a status.
template <typename Fn>
int guardLoad(PrismPluginError* err, Fn&& fn) {
  try {
    fn();
    return PRISM_PLUGIN_OK;
  } catch (const PluginFailure& f) {
    fillError(err, f.what(), f.line(), f.offset());
    return f.status();
  } catch (const SinkStopped&) {
    fillError(err, "stopped by the host", 0, 0);
    return PRISM_PLUGIN_ERROR_SINK;
  } catch (const std::bad_alloc&) {
    fillError(err, "out of memory", 0, 0);
    return PRISM_PLUGIN_ERROR_OUT_OF_MEMORY;
  } catch (const std::exception& e) {
    fillError(err, (std::string("internal error: ") + e.what()).c_str(), 0, 0);
    return PRISM_PLUGIN_ERROR_INTERNAL;
  } catch (...) {
    fillError(err, "internal error: unknown exception", 0, 0);
    return PRISM_PLUGIN_ERROR_INTERNAL;
  }
}

}  // namespace prism_plugins
