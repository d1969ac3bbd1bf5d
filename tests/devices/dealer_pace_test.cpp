// Devices of different speeds sharing a frame (issue 13): a device much slower
// than the others leaves them the last units (worthTaking, dealUnits), so the
// frame does not wait for it.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "render/work_dealer.h"

using namespace prism;

namespace {

DevicePace pace(double samples_per_second, bool busy = false, double left = 0) {
  DevicePace p;
  p.samples_per_second = samples_per_second;
  p.busy = busy;
  p.samples_left = left;
  return p;
}

}  // namespace

TEST_CASE("worthTaking: a free device takes a unit unless the others would finish all the work first") {
  // Device 1 is ten times slower than device 0, which is busy; each unit holds
  // 100 samples. Device 1 would need 1 s for a unit.
  std::vector<DevicePace> paces = {pace(1000, true, 50), pace(100)};
  // 7 units wait: device 0 needs (700 + 50) / 1000 = 0.75 s for all. Not worth it.
  CHECK_FALSE(worthTaking(1, 100, 700, paces));
  // 20 units wait: device 0 alone needs 2.05 s; device 1 finishes one in 1 s.
  CHECK(worthTaking(1, 100, 2000, paces));
  // The fast device always takes: 0.1 s against device 1's 1 s for the unit.
  paces = {pace(1000), pace(100, true, 50)};
  CHECK(worthTaking(0, 100, 100, paces));

  SECTION("a unit is not split: the others' time is at least the soonest one of them could finish it") {
    // Three devices of one pace; one unit left; the two others busy with half a
    // unit each. Pooled they would need (100 + 100) / 200 = 1 s, but one unit
    // goes to one device: 1.5 s. The free device's 1 s wins.
    CHECK(worthTaking(0, 100, 100, {pace(100), pace(100, true, 50), pace(100, true, 50)}));
  }
  SECTION("what is not known, or nobody else busy, means taking it") {
    CHECK(worthTaking(1, 100, 100, {pace(1000, true, 0), pace(0)}));    // its own pace unknown
    CHECK(worthTaking(1, 100, 100, {pace(0, true, 0), pace(100)}));     // a busy other's unknown
    CHECK(worthTaking(1, 100, 100, {pace(1000, false, 0), pace(100)})); // no other busy
    std::vector<DevicePace> dead = {pace(1000, true, 0), pace(100)};
    dead[0].live = false;
    CHECK(worthTaking(1, 100, 100, dead));                              // the others have failed
  }
}

namespace {

using Clock = std::chrono::steady_clock;

// Deals `units` units over a fast device (0) and a slow one (1) whose units
// take fast_ms and slow_ms; returns when each device finished its last unit.
struct Dealt {
  std::vector<DeviceShare> devices = std::vector<DeviceShare>(2);
  double fast_end = 0, slow_end = 0;  // seconds from the start
};
Dealt dealTwo(std::size_t units, int fast_ms, int slow_ms, std::vector<double>& paces) {
  Dealt d;
  const std::vector<std::uint64_t> samples(units, 1000);
  std::vector<std::atomic<int>> traced(units);
  const auto start = Clock::now();
  std::mutex m;
  dealUnits(
      d.devices, samples,
      [&](std::size_t device, std::size_t u) {
        std::this_thread::sleep_for(std::chrono::milliseconds(device == 0 ? fast_ms : slow_ms));
        ++traced[u];
        const double t = std::chrono::duration<double>(Clock::now() - start).count();
        std::lock_guard<std::mutex> lock(m);
        (device == 0 ? d.fast_end : d.slow_end) = t;
      },
      nullptr, paces);
  for (const auto& t : traced) CHECK(t == 1);
  CHECK(d.devices[0].units + d.devices[1].units == units);
  return d;
}

}  // namespace

TEST_CASE("dealUnits: a much slower device leaves the last units to a faster one") {
  SECTION("the frame does not wait for the slow device's last unit") {
    // 400 units of 1 ms on device 0 against 300 ms on device 1. Taking turns as
    // they come free, device 1 would start a second unit at 300 ms with about
    // 100 ms of work left, and end 200 ms after device 0.
    std::vector<double> paces;
    const Dealt d = dealTwo(400, 1, 300, paces);
    CHECK(d.slow_end <= d.fast_end + 0.1);
    // This frame's paces are kept for the next.
    REQUIRE(paces.size() == 2);
    CHECK(paces[0] > paces[1]);
  }
  SECTION("with paces known from earlier frames, the slow device takes only its first unit") {
    // 20 units of 1 ms against 50 ms: after its first unit, device 0 always
    // finishes what is left before device 1 would finish one more, including
    // the moments when device 0 is between two units.
    std::vector<double> paces = {1e6, 2e4};
    for (int frame = 0; frame < 8; ++frame) {
      const Dealt d = dealTwo(20, 1, 50, paces);
      CHECK(d.devices[1].units <= 1);
    }
  }
}
