// The film entries of the units that devices handed over as they finished
// them: every device of a shared frame but the one that resolves it holds a
// film window of one unit (render/device_tracer.h), so its units wait here, on
// the host, until the resolver's thread writes them into its film between its
// own units, or, at a part other than 0, until their run is resolved
// (Renderer::resolveAcrossParts).
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

#include "render/device_tracer.h"

namespace prism {

// The film entries (rgba) and positions (x, y) of a run of samples, on the host.
struct SampleRun {
  std::vector<float> rgba, xy;
  void resize(std::size_t n) {
    rgba.resize(4 * n);
    xy.resize(2 * n);
  }
  std::size_t size() const { return xy.size() / 2; }
};

class HeldUnits {
 public:
  // Units of unit_size samples (the last may have fewer), `units` of them.
  HeldUnits(std::uint64_t unit_size, std::size_t units) : m_unit_size(unit_size), m_units(units) {}

  // Unit u's entries, read from the film of the tracer that just traced it
  // (on that device's thread; any number of threads at once).
  void take(std::size_t u, std::uint64_t samples, const DeviceTracer& tracer);
  // The units taken since the last call, let go here (any thread). A unit
  // traced again after it was let go comes again.
  std::vector<std::pair<std::size_t, SampleRun>> takeWaiting();
  // Writes such units into the tracer's film, which must hold their samples.
  void write(const std::vector<std::pair<std::size_t, SampleRun>>& units, DeviceTracer& tracer) const;

  // Once no device thread is left: whether unit u is here, and samples
  // [first, end), all in units here, into rgba (4 a sample) and xy (2).
  bool holds(std::size_t u) const { return m_units[u].size() > 0; }
  void copy(std::uint64_t first, std::uint64_t end, float* rgba, float* xy) const;

 private:
  std::uint64_t m_unit_size;
  std::mutex m_mutex;
  std::vector<SampleRun> m_units;
  std::vector<std::size_t> m_waiting;  // taken, not yet let go
};

}  // namespace prism
