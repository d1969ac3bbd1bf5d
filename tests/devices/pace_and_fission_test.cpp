// Devices of different speeds sharing a frame (issue 13): a device much slower
// than the others leaves them the last units (worthTaking, dealUnits), and a CPU
// device beside a GPU leaves the GPU's driver a core (computeUnitsBeside, a
// Context on a sub-device) without changing a bit of the image.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <thread>

#include "device/frame_contexts.h"
#include "device_fixtures.h"
#include "render/work_dealer.h"

using namespace prism;
using namespace prism_test;

namespace {

DevicePace pace(double samples_per_second, bool busy = false, double left = 0) {
  DevicePace p;
  p.samples_per_second = samples_per_second;
  p.busy = busy;
  p.samples_left = left;
  return p;
}

DeviceDescription described(cl_device_type type, unsigned units) {
  DeviceDescription d;
  d.type = type;
  d.compute_units = units;
  return d;
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

TEST_CASE("dealUnits: a much slower device leaves the last units to a faster one") {
  // Device 0 traces a unit in 1 ms, device 1 in 200 ms; 20 units of 1000
  // samples. Device 1 takes at most the unit it starts with (before anything is
  // known, or while device 0 is not yet busy): after it, device 0 would finish
  // everything left long before device 1 finished one more.
  const std::vector<std::uint64_t> units(20, 1000);
  for (bool known : {false, true}) {
    DYNAMIC_SECTION((known ? "paces known from an earlier frame" : "paces learnt in this frame")) {
      std::vector<DeviceShare> devices(2);
      std::vector<double> paces = known ? std::vector<double>{1e6, 5e3} : std::vector<double>{};
      std::vector<std::atomic<int>> traced(units.size());
      const DealResult r = dealUnits(
          devices, units,
          [&](std::size_t d, std::size_t u) {
            std::this_thread::sleep_for(std::chrono::milliseconds(d == 0 ? 1 : 200));
            ++traced[u];
          },
          nullptr, paces);
      for (const auto& t : traced) CHECK(t == 1);
      CHECK(devices[0].units + devices[1].units == units.size());
      CHECK(devices[1].units <= 1);
      // This frame's paces are kept for the next.
      REQUIRE(paces.size() == 2);
      CHECK(paces[0] > paces[1]);
    }
  }
}

TEST_CASE("computeUnitsBeside: a CPU leaves one compute unit per device of another kind") {
  const DeviceDescription cpu = described(CL_DEVICE_TYPE_CPU, 16), gpu = described(CL_DEVICE_TYPE_GPU, 132);
  CHECK(computeUnitsBeside({cpu}, 0) == 0);                 // alone: all
  CHECK(computeUnitsBeside({cpu, cpu}, 0) == 0);            // PoCL twins share the cores anyway
  CHECK(computeUnitsBeside({gpu, cpu}, 1) == 15);
  CHECK(computeUnitsBeside({gpu, cpu, gpu}, 1) == 14);
  CHECK(computeUnitsBeside({gpu, cpu}, 0) == 0);            // a GPU keeps its units
  CHECK(computeUnitsBeside({gpu, described(CL_DEVICE_TYPE_CPU, 1)}, 1) == 1);  // never none
}

TEST_CASE("a CPU device on fewer compute units (a sub-device) renders the same bits") {
  const std::vector<Context*> all = poclDevices();
  REQUIRE(!all.empty());
  const DeviceDescription& device = all[0]->device();
  if (device.compute_units < 2) {
    WARN("one compute unit: nothing to partition on this machine");
    return;
  }
  Context fewer(device, true, BinaryCache::UnlessDriverCaches, device.compute_units - 1);
  // PoCL partitions its CPU devices (OpenCL 1.2 device fission).
  REQUIRE(fewer.device().compute_units == device.compute_units - 1);
  CHECK(fewer.device().device != device.device);
  const Case& c = kCases[0];
  const Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR "/scenes/") + c.scene);
  const RenderOptions o = optionsFor(scene, c);
  Renderer whole(*all[0]);
  Renderer part(fewer);
  Renderer shared({&fewer, all[1]});
  const RenderResult reference = whole.render(scene, o);
  requireSameFrame(reference, part.render(scene, o));
  requireSameFrame(reference, shared.render(scene, o));
}
