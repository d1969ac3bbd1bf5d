#include "devices_bench.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>

#include "bench_options.h"
#include "bench_process.h"
#include "device/context.h"
#include "device/device_list.h"
#include "render/renderer.h"
#include "scene_format/scene_loader.h"

namespace prism::bench {
namespace {

const char* kUsage =
    "usage: prism-bench devices [--devices SEL] [--scene FILE] [--size WxH] [--spp N] [--repeat N]\n"
    "\n"
    "Renders --scene (default scenes/whitted.json) at --size (default 640x480) with\n"
    "--spp jittered samples (default 4) on each device of --devices alone (default\n"
    "all; a list such as 0,2 as prism render --device takes), then on all of them\n"
    "sharing the frame, the renders taking turns --repeat times (default 3; medians).\n"
    "Throughput is rays over the render's tracing time (set-up left out). Prints each\n"
    "device's solo Mrays/s and share of the shared frame, the shared frame's Mrays/s\n"
    "against the sum of the solos and against the fastest solo, and whether the\n"
    "images are the same bit for bit. Try several PoCL devices of one CPU with\n"
    "POCL_DEVICES=\"pthread pthread\".\n";

double mrays(const RenderResult& r) {
  const double tracing = r.stats.seconds - r.stats.setup_seconds;
  return tracing > 0 ? static_cast<double>(r.stats.totalRays()) / tracing / 1e6 : 0;
}

}  // namespace

int devicesMain(const std::vector<std::string>& args) {
  std::string selector = "all", scene_path = PRISM_SOURCE_DIR "/scenes/whitted.json";
  int width = 640, height = 480, spp = 4, repeats = 3;
  const int status = parseBenchOptions(args, "devices", kUsage, [&](const std::string& a, const OptionValue& value) {
    if (a == "--devices") {
      selector = value();
    } else if (a == "--scene") {
      scene_path = value();
    } else if (a == "--size") {
      parseSize(a, value(), &width, &height);
    } else if (a == "--spp") {
      spp = std::max(1, std::stoi(value()));
    } else if (a == "--repeat") {
      repeats = std::max(1, std::stoi(value()));
    } else {
      throw std::invalid_argument("unknown option '" + a + "'");
    }
  });
  if (status >= 0) return status;
  try {
    const std::vector<DeviceDescription> devices = selectDevices(selector);
    std::vector<std::unique_ptr<Context>> contexts;
    std::vector<Context*> all;
    std::vector<std::unique_ptr<Renderer>> solo;
    for (const DeviceDescription& d : devices) {
      contexts.push_back(std::make_unique<Context>(d, true));
      all.push_back(contexts.back().get());
      solo.push_back(std::make_unique<Renderer>(*contexts.back()));
    }
    Renderer shared(all);
    const Scene scene = loadSceneFile(scene_path);
    RenderOptions options = RenderOptions::fromScene(scene);
    options.width = width;
    options.height = height;
    options.aa = spp > 1 ? AaMode::Jitter : AaMode::None;
    options.spp = spp;

    // Untimed: builds every device's kernels and gives the reference image.
    const RenderResult reference = solo.front()->render(scene, options);
    for (size_t i = 1; i < solo.size(); ++i) solo[i]->render(scene, options);
    shared.render(scene, options);

    std::vector<std::vector<double>> solo_mrays(solo.size());
    std::vector<double> shared_mrays;
    RenderResult last;
    bool same = true;
    for (int r = 0; r < repeats; ++r) {
      for (size_t i = 0; i < solo.size(); ++i) solo_mrays[i].push_back(mrays(solo[i]->render(scene, options)));
      last = shared.render(scene, options);
      shared_mrays.push_back(mrays(last));
      same = same && last.rgba.size() == reference.rgba.size() &&
             std::memcmp(last.rgba.data(), reference.rgba.data(), last.rgba.size() * sizeof(float)) == 0;
    }
    std::printf("scene: %s, %dx%d at %d spp (jitter), %llu rays; median of %d renders, taking turns\n\n",
                scene_path.c_str(), width, height, spp, static_cast<unsigned long long>(reference.stats.totalRays()),
                repeats);
    std::printf("%-4s %-40s %-6s %11s %12s %12s %10s %9s\n", "", "device", "type", "solo Mr/s", "shared units",
                "shared share", "busy ms", "film MiB");
    double sum = 0, best = 0;
    std::uint64_t samples = 0;
    for (const DeviceShare& s : last.stats.devices) samples += s.samples;
    for (size_t i = 0; i < devices.size(); ++i) {
      const double m = median(solo_mrays[i]);
      sum += m;
      best = std::max(best, m);
      const DeviceShare& s = last.stats.devices[i];
      std::printf("[%u]  %-40.40s %-6s %11.2f %12llu %11.1f%% %10.1f %9.1f%s\n", devices[i].index,
                  devices[i].name.c_str(),
                  devices[i].type & CL_DEVICE_TYPE_GPU ? "GPU" : devices[i].type & CL_DEVICE_TYPE_CPU ? "CPU" : "other", m,
                  static_cast<unsigned long long>(s.units), samples ? 100.0 * s.samples / samples : 0.0,
                  1e3 * s.busy_seconds, static_cast<double>(s.film_bytes) / (1024.0 * 1024.0),
                  s.failed ? "  (failed)" : "");
    }
    const double together = median(shared_mrays);
    // Bits are promised among devices of one kind; a GPU and a CPU round some
    // operations differently (docs/devices.md, "NVIDIA's OpenCL").
    bool one_kind = true;
    for (const DeviceDescription& d : devices)
      one_kind = one_kind && d.name == devices.front().name && d.driver_version == devices.front().driver_version;
    std::printf("\nshared frame: %.2f Mrays/s (tracing %.1f ms); / sum of solos %.2f; / fastest solo %.2f; "
                "same image as device [%u] alone: %s\n",
                together, 1e3 * (last.stats.seconds - last.stats.setup_seconds), sum > 0 ? together / sum : 0.0,
                best > 0 ? together / best : 0.0, devices.front().index,
                same ? "yes" : one_kind ? "NO" : "no (devices of different kinds: not promised)");
    std::printf("(the goal: >= 0.9 of the sum where the devices do not share hardware, >= 0.9 of the fastest\n"
                "solo where they do, as several PoCL devices on one CPU)\n");
    return same || !one_kind ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "prism-bench devices: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace prism::bench
