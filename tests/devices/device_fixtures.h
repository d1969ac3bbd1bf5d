// What the tests of a frame shared over several devices (multi_device_test)
// and over several processes (frame_parts_test) have in common: three PoCL
// devices of one kind, the cases whose sample sequences span several units, and
// "the same frame, bit for bit".
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "device/context.h"
#include "device/device_list.h"
#include "render/renderer.h"
#include "scene_format/scene_loader.h"

namespace prism_test {

using namespace prism;

// Static initialisation comes before main, so before the OpenCL ICD loader
// reads PoCL's settings at the first platform query.
inline const bool kThreePoclDevices = setenv("POCL_DEVICES", "pthread pthread pthread", /*overwrite=*/1) == 0;

// The PoCL devices, each with its own context, made once for the binary.
inline std::vector<Context*> poclDevices() {
  static std::vector<std::unique_ptr<Context>> contexts;
  static bool made = false;
  if (!made) {
    made = true;
    for (const DeviceDescription& d : listDevices())
      if (d.platform_name.find("Portable Computing Language") != std::string::npos)
        contexts.push_back(std::make_unique<Context>(d, true));
  }
  std::vector<Context*> out;
  for (auto& c : contexts) out.push_back(c.get());
  return out;
}

inline std::vector<Context*> pick(const std::vector<Context*>& all, std::initializer_list<size_t> which) {
  std::vector<Context*> out;
  for (size_t i : which) out.push_back(all.at(i));
  return out;
}

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline void requireSameFrame(const RenderResult& a, const RenderResult& b) {
  CHECK(sameBits(a.rgba, b.rgba));
  CHECK(sameBits(a.depth, b.depth));
  CHECK(sameBits(a.normal, b.normal));
  CHECK(sameBits(a.primid, b.primid));
  CHECK(sameBits(a.albedo, b.albedo));
  CHECK(a.stats.rays_by_kind == b.stats.rays_by_kind);
  CHECK(a.stats.rays_per_depth == b.stats.rays_per_depth);
}

struct Case {
  const char* name;
  const char* scene;
  int width, height;
  AaMode aa;
  int spp;
  FirstHitMode first_hit;
};

// Scenes and modes whose sample sequences span several units (a unit is a
// slice of 65536 samples; the Z-buffer's is its batch, 64 slices, so that case
// is one unit on one device while the others write no AOV pixel).
inline const Case kCases[] = {
    {"whitted, jitter 4 spp (5 units)", "whitted.json", 320, 240, AaMode::Jitter, 4, FirstHitMode::Trace},
    {"penumbra: area lights' feelers (2 units)", "penumbra.json", 200, 150, AaMode::Grid, 4, FirstHitMode::Trace},
    {"depth of field, 3 spp (4 units)", "dof.json", 256, 192, AaMode::Random, 3, FirstHitMode::Trace},
    {"adaptive (several passes)", "whitted.json", 320, 240, AaMode::Adaptive, 1, FirstHitMode::Trace},
    {"teapot through the Z-buffer", "teapot.json", 160, 120, AaMode::Jitter, 2, FirstHitMode::ZBuffer},
};

inline RenderOptions optionsFor(const Scene& scene, const Case& c) {
  RenderOptions o = RenderOptions::fromScene(scene);
  o.width = c.width;
  o.height = c.height;
  o.aa = c.aa;
  o.spp = c.spp;
  o.first_hit = c.first_hit;
  return o;
}

inline std::uint64_t sharedSamples(const RenderStats& s) {
  std::uint64_t n = 0;
  for (const DeviceShare& d : s.devices) n += d.failed ? 0 : d.samples;
  return n;
}


}  // namespace prism_test
