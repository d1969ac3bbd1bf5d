// dealUnits over a source that another part takes from at the same time
// (render/shared_stretches.h): with several devices, one of them failing, the
// units this part took are each traced once by a device that did not fail,
// those of the failed device (its own stretch's or another's) again; together
// with the other part's, every unit of the frame once.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "device/cl_error.h"
#include "render/shared_stretches.h"
#include "render/work_dealer.h"

using namespace prism;

TEST_CASE("dealUnits takes from a shared source: every unit once between the parts, a failed device's again") {
  const std::size_t units = 60;
  const std::vector<std::uint64_t> samples(units, 100);
  std::vector<std::atomic<std::uint64_t>> words(2);
  for (auto& w : words) w = 0;
  const CompareSwap swap = [&words](std::uint32_t word, std::uint64_t expected, std::uint64_t desired) {
    words.at(word).compare_exchange_strong(expected, desired);
    return expected;
  };
  for (int trial = 0; trial < 4; ++trial) {
    const auto round = static_cast<std::uint16_t>(trial + 1);
    // Part 1: one device, slower, taking until none is left.
    std::vector<std::size_t> theirs;
    std::thread other([&] {
      SharedStretches source(samples, 1, 2, round, swap);
      while (const auto u = source.take()) {
        theirs.push_back(*u);
        std::this_thread::sleep_for(std::chrono::milliseconds(3));
      }
    });
    // Part 0: three devices; device 2 fails at its third unit.
    SharedStretches source(samples, 0, 2, round, swap);
    std::vector<DeviceShare> devices(3);
    std::vector<double> paces;
    std::vector<std::atomic<int>> traced(units);
    std::vector<int> started(3, 0);
    std::mutex m;
    double most = 0;
    std::size_t last_done = 0, last_whole = 0;
    const DealResult dealt = dealUnits(
        devices, samples, source,
        [&](std::size_t d, std::size_t u) {
          {
            std::lock_guard<std::mutex> lock(m);
            if (d == 2 && ++started[2] == 3) throw DeviceError("injected");
          }
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
          ++traced[u];
        },
        [&](std::size_t done, std::size_t whole) {
          most = std::max(most, static_cast<double>(done) / static_cast<double>(whole));
          last_done = done;
          last_whole = whole;
          return true;
        },
        paces);
    other.join();
    INFO("trial " << trial);
    CHECK(source.exhausted());
    CHECK(devices[2].failed);
    CHECK(devices[2].units == 0);
    REQUIRE(dealt.warnings.size() == 1);
    CHECK(most <= 1.0);
    CHECK(last_done == last_whole);
    std::vector<int> times(units, 0);
    std::size_t here = 0;
    for (std::size_t u = 0; u < units; ++u) {
      if (dealt.owner[u] == kNoDevice) continue;
      ++here;
      ++times[u];
      CHECK(dealt.owner[u] != 2);
      CHECK(traced[u] >= 1);  // the failed device may have traced it before it failed
    }
    CHECK(here == devices[0].units + devices[1].units);
    for (std::size_t u : theirs) ++times[u];
    for (std::size_t u = 0; u < units; ++u) {
      INFO("unit " << u);
      CHECK(times[u] == 1);
    }
    // The faster part took from the other's stretch.
    CHECK(here > units / 2);
  }
}

// Three units, and a fourth counted in this part's stretch until take finds
// none left: another part took it meanwhile, as SharedStretches may tell.
class StretchTakenAtTheEnd : public UnitSource {
 public:
  std::optional<std::size_t> take() override {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_next == 3) {
      m_dry = true;
      return std::nullopt;
    }
    return m_next++;
  }
  bool exhausted() const override {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_dry;
  }
  double nextSamples() const override { return 100; }
  double samplesLeft() const override {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_dry ? 0.0 : 100.0 * static_cast<double>(4 - m_next);
  }
  std::size_t expectedUnits() const override {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_dry ? m_next : 4;
  }

 private:
  mutable std::mutex m_mutex;
  std::size_t m_next = 0;
  bool m_dry = false;
};

// With one device the last unit is reported while the fourth still counts, so
// only a report after the source runs dry ends at the whole; with three the
// order varies from run to run, and every order must end there.
TEST_CASE("progress ends at its whole when another part takes the rest of this part's stretch after its last unit") {
  const std::vector<std::uint64_t> samples(4, 100);
  for (std::size_t device_count : {std::size_t(1), std::size_t(3)}) {
    StretchTakenAtTheEnd source;
    std::vector<DeviceShare> devices(device_count);
    std::vector<double> paces;
    std::size_t last_done = 0, last_whole = 0;
    const DealResult dealt = dealUnits(
        devices, samples, source, [](std::size_t, std::size_t) {},
        [&](std::size_t done, std::size_t whole) {
          last_done = done;
          last_whole = whole;
          return true;
        },
        paces);
    INFO(device_count << " device(s)");
    CHECK_FALSE(dealt.cancelled);
    CHECK(last_done == 3);
    CHECK(last_whole == 3);
  }
}
