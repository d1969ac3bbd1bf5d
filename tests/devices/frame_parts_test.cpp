// One frame over several processes (issue 13; render/frame_parts.h, which
// `mpirun prism render` uses through prismSetFrameParts): parts on threads here,
// each a Renderer on its own PoCL device, exchanging through memory. Part 0's
// image, AOVs and ray counts are those of one process bit for bit, in every
// sampling mode, with any number of parts and devices per part, also when a part
// has no unit to trace; part 0 reports every part's devices.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <functional>
#include <mutex>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "device_fixtures.h"
#include "render/frame_parts.h"
#include "render/part_resolve.h"
#include "render/shared_stretches.h"

using namespace prism;
using namespace prism_test;

namespace {

// The exchange's contract (every part calls it in the same order) over shared
// memory: a round collects every part's bytes, then each part takes what it
// receives; the next round starts once every part has.
class Loopback {
 public:
  explicit Loopback(std::uint32_t parts) : m_parts(parts), m_bytes(parts), m_words(parts) {
    for (auto& w : m_words) w = 0;
  }

  // FrameParts::compare_swap over words in memory.
  std::uint64_t compareSwap(std::uint32_t word, std::uint64_t expected, std::uint64_t desired) {
    m_words.at(word).compare_exchange_strong(expected, desired);
    return expected;  // the value found
  }
  std::uint64_t word(std::uint32_t w) const { return m_words.at(w).load(); }

  std::vector<Bytes> exchange(std::uint32_t part, bool to_all, const Bytes& mine) {
    std::unique_lock<std::mutex> lock(m_mutex);
    m_changed.wait(lock, [&] { return !m_reading || m_aborted; });
    if (m_aborted) throw std::runtime_error("another part failed");
    m_bytes[part] = mine;
    if (++m_arrived == m_parts) {
      m_reading = true;
      m_changed.notify_all();
    } else {
      m_changed.wait(lock, [&] { return m_reading || m_aborted; });
      // A round every part reached is delivered, whatever happened since.
      if (!m_reading) throw std::runtime_error("another part failed");
    }
    std::vector<Bytes> got;
    if (to_all || part == 0) got = m_bytes;
    ++m_bytes_read_count;
    if (m_bytes_read_count == m_parts) {
      m_arrived = m_bytes_read_count = 0;
      m_reading = false;
      m_changed.notify_all();
    }
    ++rounds_seen;
    return got;
  }

  // A part that fails wakes the others, which fail too instead of waiting.
  void abort() {
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_aborted = true;
    m_changed.notify_all();
  }

  std::uint64_t rounds_seen = 0;

 private:
  const std::uint32_t m_parts;
  std::vector<Bytes> m_bytes;
  std::uint32_t m_arrived = 0, m_bytes_read_count = 0;
  bool m_reading = false;
  bool m_aborted = false;
  std::mutex m_mutex;
  std::condition_variable m_changed;
  std::vector<std::atomic<std::uint64_t>> m_words;
};

// How the parts share the units: each its own stretch, or as their devices
// come free (FrameParts::compare_swap); `before_take(part, loopback)` runs
// before each of a part's compare-and-swaps (to hold a part back).
struct Dealing {
  bool as_devices_come_free = false;
  std::function<void(std::uint32_t part, const Loopback&)> before_take;
};
const Dealing kStretches{false, nullptr}, kAsDevicesComeFree{true, nullptr};

struct PartsOutcome {
  std::vector<RenderResult> results;
  std::vector<std::string> errors;  // per part, empty when it rendered
};

// Renders `scene` split into parts, part p on the devices parts_devices[p]
// with options_of(p).
PartsOutcome tryInParts(const std::vector<std::vector<Context*>>& parts_devices, const Scene& scene,
                        const std::function<RenderOptions(std::uint32_t part)>& options_of,
                        const Dealing& dealing = kStretches, std::uint64_t resolve_piece = 0) {
  const auto parts = static_cast<std::uint32_t>(parts_devices.size());
  Loopback loopback(parts);
  std::vector<RenderResult> results(parts);
  std::vector<std::string> errors(parts);
  std::vector<std::thread> threads;
  for (std::uint32_t p = 0; p < parts; ++p) {
    threads.emplace_back([&, p] {
      try {
        Renderer renderer(parts_devices[p]);
        if (resolve_piece > 0) renderer.setResolvePieceSamples(resolve_piece);
        FrameParts fp;
        fp.part = p;
        fp.parts = parts;
        fp.exchange = [&loopback, p](bool to_all, const Bytes& mine) { return loopback.exchange(p, to_all, mine); };
        if (dealing.as_devices_come_free)
          fp.compare_swap = [&loopback, &dealing, p](std::uint32_t word, std::uint64_t expected, std::uint64_t desired) {
            if (dealing.before_take) dealing.before_take(p, loopback);
            return loopback.compareSwap(word, expected, desired);
          };
        renderer.setFrameParts(fp);
        results[p] = renderer.render(scene, options_of(p));
      } catch (const std::exception& e) {
        errors[p] = e.what();
        loopback.abort();
      }
    });
  }
  for (std::thread& t : threads) t.join();
  return {std::move(results), std::move(errors)};
}

std::vector<RenderResult> renderInParts(const std::vector<std::vector<Context*>>& parts_devices, const Scene& scene,
                                        const RenderOptions& options, const Dealing& dealing = kStretches,
                                        std::uint64_t resolve_piece = 0) {
  PartsOutcome outcome = tryInParts(parts_devices, scene, [&](std::uint32_t) { return options; }, dealing, resolve_piece);
  for (const std::string& e : outcome.errors) REQUIRE(e.empty());
  return std::move(outcome.results);
}

// The scene's own options at width x height.
RenderOptions sized(const Scene& scene, int width, int height) {
  RenderOptions o = RenderOptions::fromScene(scene);
  o.width = width;
  o.height = height;
  return o;
}

bool allZero(const std::vector<float>& v) {
  for (float x : v)
    if (x != 0.f) return false;
  return true;
}

}  // namespace

TEST_CASE("units are split into contiguous stretches, one per part, covering the frame once") {
  for (std::size_t units : {0u, 1u, 2u, 5u, 64u, 1000u}) {
    for (std::uint32_t parts : {1u, 2u, 3u, 7u}) {
      std::size_t next = 0;
      for (std::uint32_t p = 0; p < parts; ++p) {
        const auto [first, last] = partUnits(units, p, parts);
        CHECK(first == next);
        CHECK(last >= first);
        CHECK(last - first <= units / parts + 1);
        next = last;
      }
      CHECK(next == units);
    }
  }
  CHECK_THROWS_AS(partUnits(4, 2, 2), std::invalid_argument);
}

TEST_CASE("a frame split over processes is the same as one process's, bit for bit") {
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 3);
  Renderer one(*all[0]);
  for (const Case& c : kCases) {
    SECTION(c.name) {
      const Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR "/scenes/") + c.scene);
      const RenderOptions o = optionsFor(scene, c);
      const RenderResult reference = one.render(scene, o);
      // Two parts of one device, and three: (0, 1), (2).
      for (const auto& layout : {std::vector<std::vector<Context*>>{{all[0]}, {all[1]}},
                                 std::vector<std::vector<Context*>>{{all[0], all[1]}, {all[2]}},
                                 std::vector<std::vector<Context*>>{{all[2]}, {all[0]}, {all[1]}}}) {
        for (const Dealing& dealing : {kStretches, kAsDevicesComeFree}) {
          INFO((dealing.as_devices_come_free ? "dealt as devices come free" : "fixed stretches"));
          const std::vector<RenderResult> parts = renderInParts(layout, scene, o, dealing);
          requireSameFrame(reference, parts[0]);
          // Part 0 reports every part's devices; they traced every sample once.
          std::size_t devices = 0;
          for (const auto& d : layout) devices += d.size();
          REQUIRE(parts[0].stats.devices.size() == devices);
          CHECK(parts[0].stats.devices.back().device.rfind("part " + std::to_string(layout.size() - 1) + ": ", 0) == 0);
          CHECK(sharedSamples(parts[0].stats) == reference.stats.rays_by_kind[0]);
          for (std::size_t p = 1; p < parts.size(); ++p) {
            CHECK(allZero(parts[p].rgba));
            CHECK(parts[p].rgba.size() == reference.rgba.size());
          }
        }
      }
    }
  }
}

TEST_CASE("partResolve: a part resolves only pixels whose filter reads its own samples, and part 0 gets the rest") {
  // Against the filter's 2D neighbourhood (rows and columns within reach), for
  // stretches cut at random keys.
  std::mt19937 rng(7);
  for (std::uint64_t w : {1, 2, 5, 13})
    for (std::uint64_t h : {1, 3, 8})
      for (std::uint64_t spp : {1, 2, 3, 4})
        for (std::uint64_t reach : {0, 1, 2})
          for (int trial = 0; trial < 6; ++trial) {
            const std::uint64_t keys = w * h * spp;
            const std::uint32_t parts = 1 + rng() % 5;
            std::vector<std::uint64_t> cut = {0, keys};
            for (std::uint32_t p = 1; p < parts; ++p) cut.push_back(rng() % (keys + 1));
            std::sort(cut.begin(), cut.end());
            const auto neighbours = [&](std::uint64_t pixel, auto&& each) {
              const auto i = static_cast<std::int64_t>(pixel % w), j = static_cast<std::int64_t>(pixel / w);
              const auto r = static_cast<std::int64_t>(reach);
              for (std::int64_t y = std::max<std::int64_t>(0, j - r); y <= std::min<std::int64_t>(h - 1, j + r); ++y)
                for (std::int64_t x = std::max<std::int64_t>(0, i - r); x <= std::min<std::int64_t>(w - 1, i + r); ++x)
                  each(static_cast<std::uint64_t>(y) * w + static_cast<std::uint64_t>(x));
            };
            std::vector<bool> at_part0(keys, false), resolved(w * h, false);
            for (std::uint64_t k = cut[0]; k < cut[1]; ++k) at_part0[k] = true;
            for (std::uint32_t p = 1; p < parts; ++p) {
              const PartResolve r = partResolve(cut[p], cut[p + 1], spp, reach * (w + 1));
              INFO("w " << w << " h " << h << " spp " << spp << " reach " << reach << " part [" << cut[p] << ", "
                        << cut[p + 1] << ")");
              for (std::uint64_t px = r.first_pixel; px < r.end_pixel; ++px) {
                resolved[px] = true;
                neighbours(px, [&](std::uint64_t q) {
                  CHECK(q * spp >= cut[p]);
                  CHECK((q + 1) * spp <= cut[p + 1]);
                });
              }
              std::uint64_t last = cut[p];
              for (const auto& [first, end] : r.samples) {
                CHECK(first >= last);  // in order, apart
                CHECK(end > first);
                CHECK(end <= cut[p + 1]);
                last = end;
                for (std::uint64_t k = first; k < end; ++k) at_part0[k] = true;
              }
            }
            // Part 0 resolves every other pixel: it has every sample its filter reads.
            for (std::uint64_t px = 0; px < w * h; ++px) {
              if (resolved[px]) continue;
              neighbours(px, [&](std::uint64_t q) {
                for (std::uint64_t k = q * spp; k < (q + 1) * spp; ++k) CHECK(at_part0[k]);
              });
            }
          }
}

TEST_CASE("parts resolve their own pixels: the same bits as one process with every filter and quincunx") {
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 3);
  Renderer one(*all[0]);
  const Scene scene = loadSceneFile(PRISM_SOURCE_DIR "/scenes/whitted.json");
  RenderOptions o = sized(scene, 160, 120);
  o.aa = AaMode::Jitter;
  o.spp = 16;  // 307,200 samples: 5 units, so each part has whole pixels far inside its stretch
  for (FilterKind f : {FilterKind::Box, FilterKind::Tent, FilterKind::Gaussian, FilterKind::Mitchell}) {
    o.filter = f;
    const RenderResult reference = one.render(scene, o);
    const std::vector<RenderResult> two = renderInParts({{all[0]}, {all[1]}}, scene, o);
    requireSameFrame(reference, two[0]);
    // Part 0's device held the frame's film (rgba and x, y: 24 bytes a sample);
    // part 1's put its run of units (2 of the 5) through its window in one piece.
    REQUIRE(two[0].stats.devices.size() == 2);
    CHECK(two[0].stats.devices[0].film_bytes == 24 * reference.stats.rays_by_kind[0]);
    CHECK(two[0].stats.devices[1].film_bytes == 24 * two[0].stats.devices[1].samples);
    CHECK(two[0].stats.devices[1].samples < reference.stats.rays_by_kind[0]);
    requireSameFrame(reference, renderInParts({{all[2]}, {all[0]}, {all[1]}}, scene, o)[0]);
    // Pieces of 5,000 samples (312 pixels and a half at 16 spp): part 1, on two
    // devices, resolves its pixels a piece at a time, and its window holds no more
    // than a piece and the samples within the filter's reach either side.
    const std::uint64_t piece = 5000;
    const std::vector<RenderResult> pieces = renderInParts({{all[0]}, {all[1], all[2]}}, scene, o, kStretches, piece);
    requireSameFrame(reference, pieces[0]);
    const std::uint64_t reach = static_cast<std::uint64_t>(filterReach(f)) * (160 + 1) * 16;  // samples either side
    for (size_t d = 1; d < 3; ++d)
      CHECK(pieces[0].stats.devices[d].film_bytes <= 24 * std::max(DeviceTracer::kSliceRays, piece + 2 * reach));
  }
  o.aa = AaMode::Quincunx;  // corners shared by pixels: parts send samples
  o.spp = 1;
  o.width = 320;
  o.height = 240;
  const RenderResult reference = one.render(scene, o);
  requireSameFrame(reference, renderInParts({{all[0]}, {all[1]}}, scene, o)[0]);
}

TEST_CASE("a part held back leaves its units to the others, and the frame is the same bits") {
  // Dealt as devices come free, part 1 waits before its first take until part
  // 0, done with its own stretch, has taken from the back of part 1's: part 0
  // then holds two runs of units and part 1 one, which the resolve and the
  // adaptive passes' colours must place as one process does.
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 3);
  Renderer one(*all[0]);
  const Scene scene = loadSceneFile(PRISM_SOURCE_DIR "/scenes/whitted.json");
  RenderOptions o = sized(scene, 160, 120);
  struct Case {
    AaMode aa;
    FilterKind filter;
  };
  for (const Case& c : {Case{AaMode::Jitter, FilterKind::Mitchell}, Case{AaMode::Jitter, FilterKind::Box},
                        Case{AaMode::Quincunx, FilterKind::Box}, Case{AaMode::Adaptive, FilterKind::Box}}) {
    o.aa = c.aa;
    o.filter = c.filter;
    o.spp = c.aa == AaMode::Jitter ? 16 : 1;  // jitter: 5 units, stretches [0, 2) and [2, 5)
    // Quincunx: 173,641 corners, 3 units; adaptive: its first pass as many.
    o.width = c.aa == AaMode::Jitter ? 160 : 480;
    o.height = c.aa == AaMode::Jitter ? 120 : 360;
    INFO("aa " << static_cast<int>(c.aa) << ", filter " << static_cast<int>(c.filter));
    const RenderResult reference = one.render(scene, o);
    // In the first deal (round 1): part 1 waits until part 0 has taken from
    // its back; part 0 then waits until part 1 has taken its front, so both
    // hold units of part 1's stretch whatever the threads' speeds.
    std::atomic<bool> held{false};
    Dealing hold_part_1{true, [&held](std::uint32_t part, const Loopback& loopback) {
                          const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(2);
                          const auto wait_while = [&](auto&& still) {
                            while (still(SharedStretches::decode(loopback.word(1)))) {
                              if (std::chrono::steady_clock::now() > until)
                                throw std::runtime_error("the parts never took each other's turn");
                              std::this_thread::sleep_for(std::chrono::milliseconds(1));
                            }
                          };
                          if (part == 1 && !held.exchange(true))
                            wait_while([](const SharedStretches::Word& w) { return w.back == 0; });
                          if (part == 0)
                            wait_while([](const SharedStretches::Word& w) {
                              return w.round == 1 && w.back > 0 && w.front == 0;
                            });
                        }};
    const std::vector<RenderResult> parts = renderInParts({{all[0]}, {all[1]}}, scene, o, hold_part_1);
    requireSameFrame(reference, parts[0]);
    const std::uint64_t units = (reference.stats.rays_by_kind[0] + Renderer::kSliceRays - 1) / Renderer::kSliceRays;
    REQUIRE(parts[0].stats.devices.size() == 2);
    if (c.aa != AaMode::Adaptive) {  // adaptive's passes are several deals; the first alone was held
      CHECK(parts[0].stats.devices[0].units > partUnits(units, 0, 2).second);
      CHECK(parts[0].stats.devices[1].units >= 1);  // part 0's units in two runs, around part 1's
      CHECK(parts[0].stats.devices[0].units + parts[0].stats.devices[1].units == units);
    }
  }
}

TEST_CASE("parts given the same words render frame after frame, each the same bits as one process") {
  // As the C API does, every render sets the parts again (the same FrameParts):
  // the deals go on counting rounds on the same words instead of starting over,
  // where a deal would find the last frame's words and trace nothing.
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 3);
  Renderer one(*all[0]);
  const Scene scene = loadSceneFile(PRISM_SOURCE_DIR "/scenes/whitted.json");
  RenderOptions jitter = optionsFor(scene, kCases[0]), adaptive = optionsFor(scene, kCases[3]);
  const RenderResult jitter_reference = one.render(scene, jitter), adaptive_reference = one.render(scene, adaptive);
  Loopback loopback(2);
  std::vector<std::vector<RenderResult>> results(2);
  std::vector<std::string> errors(2);
  std::vector<std::thread> threads;
  for (std::uint32_t p = 0; p < 2; ++p)
    threads.emplace_back([&, p] {
      try {
        Renderer renderer(*all[p]);
        FrameParts fp;
        fp.part = p;
        fp.parts = 2;
        fp.exchange = [&loopback, p](bool to_all, const Bytes& mine) { return loopback.exchange(p, to_all, mine); };
        fp.compare_swap = [&loopback](std::uint32_t word, std::uint64_t expected, std::uint64_t desired) {
          return loopback.compareSwap(word, expected, desired);
        };
        for (const RenderOptions* o : {&jitter, &adaptive, &jitter}) {
          renderer.setFrameParts(fp);
          results[p].push_back(renderer.render(scene, *o));
        }
      } catch (const std::exception& e) {
        errors[p] = e.what();
        loopback.abort();
      }
    });
  for (std::thread& t : threads) t.join();
  for (const std::string& e : errors) REQUIRE(e.empty());
  requireSameFrame(jitter_reference, results[0][0]);
  requireSameFrame(adaptive_reference, results[0][1]);
  requireSameFrame(jitter_reference, results[0][2]);
}

TEST_CASE("check-nan across parts finds the first non-finite contribution in render order, as one process does") {
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 3);
  // A light of NaN intensity (set after loading: the loader refuses it) poisons
  // every lit hit. The camera looks up, so the top of the image is unlit sky:
  // part 0 finds none and the finding must be part 1's first, not part 2's.
  Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR "/scenes/whitted.json"));
  scene.lights.at(0).intensity = std::nan("");
  scene.camera.look_at.y += 2.5;
  RenderOptions o = optionsFor(scene, kCases[0]);
  o.check_nan = true;
  Renderer one(*all[0]);
  const RenderResult reference = one.render(scene, o);
  REQUIRE(reference.stats.nan.has_value());
  const std::vector<RenderResult> parts = renderInParts({{all[0]}, {all[1]}, {all[2]}}, scene, o);
  REQUIRE(parts[0].stats.nan.has_value());
  CHECK(std::memcmp(&*parts[0].stats.nan, &*reference.stats.nan, sizeof(NanFinding)) == 0);
  const std::uint64_t units = (reference.stats.rays_by_kind[0] + Renderer::kSliceRays - 1) / Renderer::kSliceRays;
  CHECK(reference.stats.nan->sample >= partUnits(units, 1, 3).first * Renderer::kSliceRays);
}

TEST_CASE("parts that would render different frames are refused on every part, before any tracing") {
  const std::vector<Context*> all = poclDevices();
  REQUIRE(all.size() >= 3);
  const Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR "/scenes/whitted.json"));
  const RenderOptions o = optionsFor(scene, kCases[0]);
  // Part 2 asks for twice the samples: its units would be other samples.
  const PartsOutcome outcome = tryInParts({{all[0]}, {all[1]}, {all[2]}}, scene, [&](std::uint32_t part) {
    RenderOptions mine = o;
    if (part == 2) mine.spp = 2 * o.spp;
    return mine;
  });
  for (const std::string& e : outcome.errors) CHECK(e.find("renders a different frame") != std::string::npos);
  CHECK(outcome.errors[0].find("part 2 of 3") != std::string::npos);
}

TEST_CASE("frame parts are checked") {
  const std::vector<Context*> all = poclDevices();
  Renderer r(*all[0]);
  FrameParts fp;
  fp.part = 2;
  fp.parts = 2;
  CHECK_THROWS_AS(r.setFrameParts(fp), std::invalid_argument);
  fp.part = 1;
  CHECK_THROWS_AS(r.setFrameParts(fp), std::invalid_argument);  // no exchange
}
