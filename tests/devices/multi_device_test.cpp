// One frame over several devices (issue 13): the image, every AOV and the ray
// counts are the same bit for bit as on one device, whatever the number and
// order of the devices; a device that fails mid-frame (an injected fault) is
// left out with a warning and the others trace its part; every device failing
// is an error; and the selector that names several devices. This binary runs
// with POCL_DEVICES="pthread pthread pthread", set before OpenCL starts
// (device_fixtures.h): three PoCL devices of one kind on the same cores.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "device/cl_error.h"
#include "device_fixtures.h"
#include "render/device_tracer.h"

using namespace prism;

using namespace prism_test;

TEST_CASE("the test runs with three PoCL devices of one kind") {
  // POCL_DEVICES is set for this binary; fewer devices mean the set-up broke.
  REQUIRE(kThreePoclDevices);
  REQUIRE(poclDevices().size() >= 3);
}

TEST_CASE("one frame over several devices is the same as on one, bit for bit, in any order") {
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 3);
  Renderer one(*all[0]);
  Renderer three(pick(all, {0, 1, 2}));
  Renderer two_reversed(pick(all, {2, 0}));
  for (const Case& c : kCases) {
    SECTION(c.name) {
      const Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR "/scenes/") + c.scene);
      const RenderOptions o = optionsFor(scene, c);
      const RenderResult a = one.render(scene, o);
      const RenderResult b = three.render(scene, o);
      const RenderResult d = two_reversed.render(scene, o);
      requireSameFrame(a, b);
      requireSameFrame(a, d);
      REQUIRE(b.stats.devices.size() == 3);
      CHECK(b.stats.warnings.empty());
      // Every unit was traced once: the devices' samples add up to the frame's.
      if (c.aa != AaMode::Adaptive) {
        CHECK(sharedSamples(b.stats) == a.stats.rays_by_kind[0]);
        CHECK(sharedSamples(d.stats) == a.stats.rays_by_kind[0]);
      } else {
        CHECK(sharedSamples(b.stats) == a.stats.rays_by_kind[0]);
      }
    }
  }
}

TEST_CASE("a device that fails mid-frame is left out with a warning and the others trace its part") {
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 2);
  const Case& c = kCases[0];
  const Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR "/scenes/") + c.scene);
  const RenderOptions o = optionsFor(scene, c);
  Renderer one(*all[0]);
  const RenderResult reference = one.render(scene, o);

  Renderer two(pick(all, {0, 1}));
  SECTION("the second device fails on its first unit") {
    two.injectDeviceFault(1, 0);
    const RenderResult r = two.render(scene, o);
    requireSameFrame(reference, r);
    REQUIRE(r.stats.devices.size() == 2);
    CHECK(r.stats.devices[1].failed);
    CHECK(r.stats.devices[1].failure.find("injected fault") != std::string::npos);
    CHECK(r.stats.devices[0].samples == reference.stats.rays_by_kind[0]);
    REQUIRE(r.stats.warnings.size() == 1);
    CHECK(r.stats.warnings[0].find(all[1]->device().name) != std::string::npos);
  }
  SECTION("the first device, which would resolve the frame, fails on its first unit") {
    two.injectDeviceFault(0, 0);
    const RenderResult r = two.render(scene, o);
    requireSameFrame(reference, r);
    CHECK(r.stats.devices[0].failed);
    CHECK(r.stats.devices[1].samples == reference.stats.rays_by_kind[0]);
    CHECK(r.stats.warnings.size() == 1);
  }
  SECTION("a device fails after finishing units: they are traced again by the other") {
    two.injectDeviceFault(0, 1);
    const RenderResult r = two.render(scene, o);
    requireSameFrame(reference, r);
    // Whether device 0 reached a second unit depends on the dealing; when it
    // did, none of its units count and device 1 traced the whole frame.
    if (r.stats.devices[0].failed) {
      CHECK(r.stats.devices[0].units == 0);
      CHECK(r.stats.devices[1].samples == reference.stats.rays_by_kind[0]);
    } else {
      CHECK(sharedSamples(r.stats) == reference.stats.rays_by_kind[0]);
    }
  }
  SECTION("a device that hands its units over fails after finishing some: they are traced again") {
    two.injectDeviceFault(1, 1);
    const RenderResult r = two.render(scene, o);
    requireSameFrame(reference, r);
    if (r.stats.devices[1].failed) CHECK(r.stats.devices[0].samples == reference.stats.rays_by_kind[0]);
  }
  SECTION("the device that resolves fails after gathering the other's units: those are traced again") {
    // 19 units: the first device fails at its fourth, by when it has (as a rule)
    // written units of the second into its film; they go with it.
    RenderOptions many = o;
    many.spp = 16;
    const RenderResult ref = one.render(scene, many);
    two.injectDeviceFault(0, 3);
    const RenderResult r = two.render(scene, many);
    requireSameFrame(ref, r);
    if (r.stats.devices[0].failed) CHECK(r.stats.devices[1].samples == ref.stats.rays_by_kind[0]);
    // The failure's warning, and when it had gathered units, one that says they were traced again.
    REQUIRE(!r.stats.warnings.empty());
    CHECK(r.stats.warnings.size() <= 2);
    if (r.stats.warnings.size() == 2) CHECK(r.stats.warnings[1].find("traced again") != std::string::npos);
  }
  SECTION("adaptive sampling: the failed device's part of every pass goes to the other") {
    const RenderOptions adaptive = optionsFor(scene, kCases[3]);
    const RenderResult ref = one.render(scene, adaptive);
    two.injectDeviceFault(1, 0);
    const RenderResult r = two.render(scene, adaptive);
    requireSameFrame(ref, r);
    CHECK(r.stats.devices[1].failed);
  }
  SECTION("adaptive sampling: a device that fails in a later pass keeps the counts of the passes it finished") {
    // Unit numbers count within a pass: the fault comes at the device's second
    // unit of a pass, after its units of earlier passes went back to the host.
    const RenderOptions adaptive = optionsFor(scene, kCases[3]);
    const RenderResult ref = one.render(scene, adaptive);
    two.injectDeviceFault(1, 1);
    const RenderResult r = two.render(scene, adaptive);
    requireSameFrame(ref, r);  // ray counts included
  }
  SECTION("every device failing is an error") {
    two.injectDeviceFault(0, 0);
    two.injectDeviceFault(1, 0);
    CHECK_THROWS_AS(two.render(scene, o), DeviceError);
  }
  SECTION("one device alone: its failure is the render's") {
    one.injectDeviceFault(0, 2);
    CHECK_THROWS_WITH(one.render(scene, o), Catch::Contains("injected fault"));
  }
}

TEST_CASE("several devices are named by 'all' or by a list of selectors") {
  const std::vector<DeviceDescription> every = listDevices();
  REQUIRE(every.size() >= 2);
  const std::vector<DeviceDescription> all = selectDevices("all");
  REQUIRE(all.size() == every.size());
  for (size_t i = 0; i < all.size(); ++i) CHECK(all[i].index == i);
  const std::vector<DeviceDescription> list = selectDevices("1,0");
  REQUIRE(list.size() == 2);
  CHECK(list[0].index == 1);
  CHECK(list[1].index == 0);
  CHECK(selectDevices("0").size() == 1);
  CHECK_THROWS_WITH(selectDevices("0,0"), Catch::Contains("named twice"));
  CHECK_THROWS_WITH(selectDevices("0,"), Catch::Contains("each comma-separated part"));
  CHECK_THROWS_WITH(selectDevices("all,1"), Catch::Contains("'all' stands alone"));
  CHECK_THROWS_WITH(selectDevices("0,999"), Catch::Contains("no device with that index"));
}

TEST_CASE("a scene names its devices in render.device, checked for its form when it loads") {
  auto load = [](const std::string& device_json) {
    return parseScene(R"({"render": {"device": )" + device_json + "}}", "devices.json");
  };
  CHECK(load(R"("all")").render.device == "all");
  CHECK(load(R"("0,2")").render.device == "0,2");
  CHECK(load(R"("gpu")").render.device == "gpu");
  CHECK(parseScene("{}", "none.json").render.device.empty());
  CHECK_THROWS_WITH(load(R"("0,,1")"), Catch::Contains("render.device: devices '0,,1': each comma-separated part"));
  CHECK_THROWS_WITH(load(R"("all,0")"), Catch::Contains("'all' stands alone"));
  CHECK_THROWS_WITH(load("3"), Catch::Contains("render.device") && Catch::Contains("expected a string"));
}

// A context for device `like` whose description says it has `bytes` of memory:
// the film check (DeviceTracer::checkFilmFits) goes by the description.
static std::unique_ptr<Context> withMemory(const Context& like, std::uint64_t bytes) {
  DeviceDescription d = like.device();
  d.global_memory_bytes = bytes;
  return std::make_unique<Context>(d, true);
}

// The least device memory, to 1 MiB, that `fits` takes, up to 16 GiB.
static std::uint64_t leastMemoryTaken(const std::function<bool(std::uint64_t)>& fits) {
  std::uint64_t refused = 0, taken = std::uint64_t{16} << 30;
  REQUIRE(fits(taken));
  while (taken - refused > (1u << 20)) {
    const std::uint64_t mid = refused + (taken - refused) / 2;
    (fits(mid) ? taken : refused) = mid;
  }
  return taken;
}

TEST_CASE("a device with memory for a unit of the frame but not the whole frame shares it") {
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 2);
  const Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR "/scenes/whitted.json"));
  RenderOptions o = RenderOptions::fromScene(scene);
  o.width = 320;
  o.height = 240;
  o.aa = AaMode::Jitter;
  o.spp = 16;  // 19 units
  o.first_hit = FirstHitMode::Trace;
  const std::uint64_t samples = static_cast<std::uint64_t>(o.width) * o.height * o.spp;
  const std::uint64_t film = 24 * samples, window = 24 * DeviceTracer::kSliceRays;  // rgba and (x, y) a sample
  REQUIRE(film >= 4 * window);

  // The least memory (to 1 MiB) with which the device takes the frame's film
  // alone, found by the device's own refusals; the render stops at its first chunk.
  const auto fits = [&](std::uint64_t bytes) {
    auto context = withMemory(*all[1], bytes);
    Renderer alone(*context);
    try {
      alone.render(scene, o, [](double) { return false; });
    } catch (const FilmTooLarge&) {
      return false;
    } catch (const RenderCancelled&) {
    }
    return true;
  };
  const std::uint64_t taken = leastMemoryTaken(fits);
  // Half the film less: the frame does not fit, a unit of it does, with room to spare.
  const std::uint64_t little_bytes = taken - film / 2;
  REQUIRE(!fits(little_bytes));
  auto little = withMemory(*all[1], little_bytes);

  Renderer one(*all[0]);
  const RenderResult reference = one.render(scene, o);
  Renderer pair({all[0], little.get()});
  const RenderResult shared = pair.render(scene, o);
  requireSameFrame(reference, shared);
  REQUIRE(shared.stats.devices.size() == 2);
  CHECK(!shared.stats.devices[1].failed);
  CHECK(shared.stats.devices[1].samples > 0);
  CHECK(sharedSamples(shared.stats) == samples);
  // The first held the frame's film, the other one unit's.
  CHECK(shared.stats.devices[0].film_bytes == film);
  CHECK(shared.stats.devices[1].film_bytes == window);
  // Named first, it cannot resolve the frame: the device after it does.
  Renderer reversed({little.get(), all[0]});
  const RenderResult other_way = reversed.render(scene, o);
  requireSameFrame(reference, other_way);
  CHECK(other_way.stats.devices[0].samples > 0);
  CHECK(other_way.stats.devices[0].film_bytes == window);
  CHECK(other_way.stats.devices[1].film_bytes == film);
  CHECK(other_way.stats.warnings.empty());
  // Alone, it refuses the frame and says what would fit.
  Renderer alone(*little);
  CHECK_THROWS_WITH(alone.render(scene, o),
                    Catch::Contains(all[1]->device().name) && Catch::Contains("fewer samples per pixel"));

  // A device with memory to spare still cannot take 2^31 samples: the kernels
  // number them with an int. 4096x4096 at 128 spp is 2^31; 127 spp would do.
  DeviceDescription vast = all[1]->device();
  vast.global_memory_bytes = vast.max_alloc_bytes = std::uint64_t{1} << 50;
  Context huge(vast, true);
  Renderer over(huge);
  RenderOptions keys = o;
  keys.width = keys.height = 4096;
  keys.spp = 128;
  CHECK_THROWS_WITH(over.render(scene, keys), Catch::Contains("2147483648 samples") &&
                                                  Catch::Contains("under 2^31") && Catch::Contains("at most 127"));
}

TEST_CASE("a render counts the device memory that an earlier render's Z-buffer pass still holds") {
  // FirstHitPass keeps its buffers from one render to the next, so a traced
  // frame after a Z-buffer one must count them before it takes its film.
  const std::vector<Context*> all = poclDevices();
  REQUIRE(!all.empty());
  const Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR "/scenes/whitted.json"));
  RenderOptions traced = RenderOptions::fromScene(scene);
  traced.width = 320;
  traced.height = 240;
  traced.aa = AaMode::Jitter;
  traced.spp = 16;
  traced.first_hit = FirstHitMode::Trace;
  RenderOptions zbuffer = traced;
  zbuffer.spp = 1;
  zbuffer.first_hit = FirstHitMode::ZBuffer;
  const auto stop = [](double) { return false; };  // the film is checked before the first chunk
  // Whether a renderer on a device of `bytes` takes the traced frame, after the Z-buffer frame or not.
  const auto fits = [&](std::uint64_t bytes, bool after_zbuffer) {
    auto context = withMemory(*all[0], bytes);
    Renderer renderer(*context);
    if (after_zbuffer) {
      const RenderResult z = renderer.render(scene, zbuffer);
      REQUIRE(z.stats.first_hit == FirstHitMode::ZBuffer);
    }
    try {
      renderer.render(scene, traced, stop);
    } catch (const FilmTooLarge&) {
      return false;
    } catch (const RenderCancelled&) {
    }
    return true;
  };
  // The least memory (to 1 MiB) that takes it on a fresh renderer; the pass
  // holds more than that step (its 76,800 samples' entries and directions alone).
  const std::uint64_t taken = leastMemoryTaken([&](std::uint64_t bytes) { return fits(bytes, false); });
  CHECK_FALSE(fits(taken, true));
  CHECK(fits(taken + (std::uint64_t{64} << 20), true));
}

TEST_CASE("the Z-buffer's batches trace in a device's window and reach the film that resolves the frame") {
  // Jitter at 14 spp, 640x480: two batches of the Z-buffer (64 slices, then
  // 106,496 samples). The first device fails at once, so the second, which holds one
  // batch at a time, traces both, then takes the whole film to resolve it.
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 2);
  const Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR "/scenes/whitted.json"));
  RenderOptions o = RenderOptions::fromScene(scene);
  o.width = 640;
  o.height = 480;
  o.aa = AaMode::Jitter;
  o.spp = 14;
  o.first_hit = FirstHitMode::ZBuffer;
  REQUIRE(static_cast<std::uint64_t>(o.width) * o.height * o.spp > DeviceTracer::kZBufferBatch);
  Renderer one(*all[0]);
  const RenderResult reference = one.render(scene, o);
  Renderer two(pick(all, {0, 1}));
  two.injectDeviceFault(0, 0);
  const RenderResult r = two.render(scene, o);
  requireSameFrame(reference, r);
  CHECK(r.stats.devices[0].failed);
  CHECK(r.stats.devices[1].units == 2);
}
