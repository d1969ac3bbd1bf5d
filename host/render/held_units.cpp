#include "render/held_units.h"

#include <algorithm>
#include <stdexcept>

namespace prism {

void HeldUnits::take(std::size_t u, std::uint64_t samples, const DeviceTracer& tracer) {
  SampleRun run;  // read outside the lock: other devices hand theirs over meanwhile
  run.resize(static_cast<std::size_t>(samples));
  tracer.readSamples(u * m_unit_size, run.size(), run.rgba.data(), run.xy.data());
  std::lock_guard<std::mutex> lock(m_mutex);
  m_units.at(u) = std::move(run);
  m_waiting.push_back(u);
}

std::vector<std::pair<std::size_t, SampleRun>> HeldUnits::takeWaiting() {
  std::vector<std::pair<std::size_t, SampleRun>> out;
  std::lock_guard<std::mutex> lock(m_mutex);
  for (std::size_t u : m_waiting)
    if (m_units[u].size() > 0) out.emplace_back(u, std::move(m_units[u]));
  m_waiting.clear();
  for (auto& unit : out) m_units[unit.first] = SampleRun();
  return out;
}

void HeldUnits::write(const std::vector<std::pair<std::size_t, SampleRun>>& units, DeviceTracer& tracer) const {
  for (const auto& [u, run] : units) tracer.writeSamples(u * m_unit_size, run.size(), run.rgba.data(), run.xy.data());
}

void HeldUnits::copy(std::uint64_t first, std::uint64_t end, float* rgba, float* xy) const {
  for (std::uint64_t k = first; k < end;) {
    const SampleRun& run = m_units.at(static_cast<std::size_t>(k / m_unit_size));
    const std::uint64_t at = k % m_unit_size;
    if (at >= run.size()) throw std::logic_error("HeldUnits::copy: a sample no unit here holds");
    const std::uint64_t n = std::min<std::uint64_t>(end - k, run.size() - at);
    std::copy_n(run.rgba.begin() + 4 * at, 4 * n, rgba + 4 * (k - first));
    std::copy_n(run.xy.begin() + 2 * at, 2 * n, xy + 2 * (k - first));
    k += n;
  }
}

}  // namespace prism
