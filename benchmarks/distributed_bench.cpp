#include "distributed_bench.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "device/device_list.h"
#include "kernels/shared/ray_gpu.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"

namespace prism::bench {
namespace {

const char* kUsage =
    "usage: prism-bench distributed [--device D] [--size WxH] [--spp N] [--repeat N] [--scenes DIR]\n"
    "\n"
    "Renders scenes/penumbra, glossy, dof, motion and cook at 1 and N (default 16)\n"
    "samples per pixel (default size 160x120): samples/s, rays per sample, the\n"
    "cost of N spp over 1 spp (time ratio), and the motion scene against itself\n"
    "held still. Times are the median of --repeat runs (default 3) after one\n"
    "untimed run, render time only (no kernel compilation).\n";

struct Run {
  double seconds = 0;
  double rays_per_sample = 0;
  double samples = 0;
};

Run timeRender(Renderer& renderer, const Scene& scene, const RenderOptions& options, int repeats) {
  renderer.render(scene, options);  // kernels compiled, caches warm
  std::vector<double> times;
  Run run;
  for (int i = 0; i < repeats; ++i) {
    RenderResult r = renderer.render(scene, options);
    times.push_back(r.stats.seconds);
    run.samples = static_cast<double>(r.stats.rays_by_kind[RAY_KIND_PRIMARY]);
    run.rays_per_sample = static_cast<double>(r.stats.totalRays()) / run.samples;
  }
  std::sort(times.begin(), times.end());
  run.seconds = times[times.size() / 2];
  return run;
}

}  // namespace

int distributedMain(const std::vector<std::string>& args) {
  std::string device_name, scenes_dir = PRISM_SOURCE_DIR "/scenes";
  int width = 160, height = 120, spp = 16, repeats = 3;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) {
        std::cerr << "prism-bench distributed: " << a << " needs a value\n\n" << kUsage;
        std::exit(2);
      }
      return args[++i];
    };
    try {
      if (a == "--help" || a == "-h") {
        std::cout << kUsage;
        return 0;
      } else if (a == "--device") {
        device_name = value();
      } else if (a == "--size") {
        const std::string v = value();
        if (std::sscanf(v.c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1)
          throw std::invalid_argument("--size: expected WxH, got '" + v + "'");
      } else if (a == "--spp") {
        spp = std::stoi(value());
        if (spp < 2) throw std::invalid_argument("--spp: expected at least 2");
      } else if (a == "--repeat") {
        repeats = std::max(1, std::stoi(value()));
      } else if (a == "--scenes") {
        scenes_dir = value();
      } else {
        throw std::invalid_argument("unknown option '" + a + "'");
      }
    } catch (const std::exception& e) {
      std::cerr << "prism-bench distributed: " << e.what() << "\n\n" << kUsage;
      return 2;
    }
  }
  try {
    DeviceDescription device = selectDevice(device_name);
    Context context(device, true);
    Renderer renderer(context);
    std::printf("device: %s (%s, driver %s, %u compute units); %dx%d, median of %d runs\n\n", device.name.c_str(),
                device.platform_name.c_str(), device.driver_version.c_str(), device.compute_units, width, height,
                repeats);
    std::printf("%-10s %12s %12s %12s %12s %14s\n", "scene", "1spp Ms/s", "rays/sample", "Nspp Ms/s", "rays/sample",
                "N spp / 1 spp");
    for (const char* name : {"penumbra", "glossy", "dof", "motion", "cook"}) {
      Scene scene = loadSceneFile(scenes_dir + "/" + name + ".json");
      RenderOptions options = RenderOptions::fromScene(scene);
      options.width = width;
      options.height = height;
      options.first_hit = FirstHitMode::Trace;
      options.spp = 1;
      options.aa.reset();
      const Run one = timeRender(renderer, scene, options, repeats);
      options.spp = spp;
      const Run many = timeRender(renderer, scene, options, repeats);
      std::printf("%-10s %12.3f %12.2f %12.3f %12.2f %13.1fx\n", name, one.samples / one.seconds / 1e6,
                  one.rays_per_sample, many.samples / many.seconds / 1e6, many.rays_per_sample,
                  many.seconds / one.seconds);
      if (std::string(name) == "motion") {
        Scene still = scene;
        still.camera.shutter_open = still.camera.shutter_close = 0;
        const Run held = timeRender(renderer, still, options, repeats);
        std::printf("%-10s %12s %12s %12.3f %12.2f %13.2fx  (moving / held still, %d spp)\n", "  still", "", "",
                    held.samples / held.seconds / 1e6, held.rays_per_sample, many.seconds / held.seconds, spp);
      }
    }
    std::printf("\nN = %d. Ms/s: million primary samples per second of render time.\n", spp);
  } catch (const std::exception& e) {
    std::cerr << "prism-bench distributed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace prism::bench
