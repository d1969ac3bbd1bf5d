#include "distributed_bench.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "bench_options.h"
#include "accel_workloads.h"
#include "device/device_list.h"
#include "kernels/shared/ray_gpu.h"
#include "render/renderer.h"
#include "scene_format/scene_loader.h"

namespace prism::bench {
namespace {

const char* kUsage =
    "usage: prism-bench distributed [--device D] [--size WxH] [--spp N] [--repeat N] [--scenes DIR]\n"
    "\n"
    "Renders scenes/penumbra, glossy, dof, motion and cook at 1 and N (default 16)\n"
    "samples per pixel (default size 160x120): samples/s, rays per sample, the\n"
    "cost of N spp over 1 spp (time ratio), and the motion scene against itself\n"
    "held still; then moving primitives in each structure (4000 spheres moving\n"
    "their own ways, a 100k-triangle torus sliding, at a quarter of the pixels).\n"
    "Times are the median of --repeat runs (default 3) after one\n"
    "untimed run, render time only (no kernel compilation).\n";

struct Run {
  double seconds = 0;        // the render
  double build_seconds = 0;  // of which building the acceleration structure
  double rays_per_sample = 0;
  double samples = 0;
  double traceSeconds() const { return seconds - build_seconds; }
};

// Many small spheres, each moving its own way during the shutter: where the
// structures' bounds for moving primitives matter.
Scene movingSpheres(int count, bool moving) {
  Scene scene;
  scene.camera.position = {0, 0, 12};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.fov = 40;
  scene.camera.shutter_open = 0;
  scene.camera.shutter_close = 1;
  Light light;
  light.position = {4, 8, 10};
  scene.lights.push_back(light);
  scene.materials.push_back(defaultMaterial());
  std::uint32_t state = 12345;
  auto next = [&state] {  // a fixed LCG: the same scene on every run
    state = state * 1664525u + 1013904223u;
    return (state >> 8) * (1.0 / 16777216.0);
  };
  for (int i = 0; i < count; ++i) {
    Object o;
    o.type = ObjectType::Sphere;
    o.center = {8 * next() - 4, 6 * next() - 3, 4 * next() - 2};
    o.radius = 0.06;
    o.moving = moving;
    o.transform_end = Transform::translate({next() - 0.5, next() - 0.5, next() - 0.5});
    scene.objects.push_back(o);
  }
  return scene;
}

// A bumpy torus of about 100k triangles sliding by its own width during the
// shutter: coherent motion, where swept boxes of the triangles overlap badly and
// linear bounds stay tight.
Scene slidingTorus(bool moving) {
  Scene scene;
  scene.camera.position = {0, 0.5, 4};
  scene.camera.look_at = {0, 0, 0};
  scene.camera.fov = 40;
  scene.camera.shutter_close = 1;
  Light light;
  light.position = {2, 4, 4};
  scene.lights.push_back(light);
  Object o;
  o.type = ObjectType::Mesh;
  o.mesh = std::make_shared<TriangleMesh>(bumpyTorus(100000));
  o.moving = moving;
  o.transform = Transform::translate({-0.5, 0, 0});
  o.transform_end = Transform::translate({0.5, 0, 0});
  scene.objects.push_back(o);
  return scene;
}

Run timeRender(Renderer& renderer, const Scene& scene, const RenderOptions& options, int repeats) {
  renderer.render(scene, options);  // kernels compiled, caches warm
  std::vector<double> times, builds;
  Run run;
  for (int i = 0; i < repeats; ++i) {
    RenderResult r = renderer.render(scene, options);
    times.push_back(r.stats.seconds);
    builds.push_back(r.stats.accel_stats.build_seconds);
    run.samples = static_cast<double>(r.stats.rays_by_kind[RAY_KIND_PRIMARY]);
    run.rays_per_sample = static_cast<double>(r.stats.totalRays()) / run.samples;
  }
  std::sort(times.begin(), times.end());
  std::sort(builds.begin(), builds.end());
  run.seconds = times[times.size() / 2];
  run.build_seconds = builds[builds.size() / 2];
  return run;
}

}  // namespace

int distributedMain(const std::vector<std::string>& args) {
  std::string device_name, scenes_dir = PRISM_SOURCE_DIR "/scenes";
  int width = 160, height = 120, spp = 16, repeats = 3;
  const int status = parseBenchOptions(args, "distributed", kUsage, [&](const std::string& a, const OptionValue& value) {
    if (a == "--device") {
      device_name = value();
    } else if (a == "--size") {
      parseSize(a, value(), &width, &height);
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
  });
  if (status >= 0) return status;
  try {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a line at a time: the runs are long
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
    // Moving primitives in each structure: 4000 spheres, each moving by up to
    // 0.87 units (15 radii) during the shutter; a sliding 100k-triangle torus.
    for (int workload = 0; workload < 2; ++workload) {
      const Scene still = workload == 0 ? movingSpheres(4000, false) : slidingTorus(false);
      const Scene moving = workload == 0 ? movingSpheres(4000, true) : slidingTorus(true);
      std::printf("\n%-26s %d spp %5s %12s %14s %10s %10s\n",
                  workload == 0 ? "4000 moving spheres," : "sliding torus 100k tris,", spp,
                  workload == 0 ? "" : "(1/4)", "Ms/s", "time / still", "build s", "still");
      RenderOptions options = RenderOptions::fromScene(moving);
      // The torus at a quarter of the pixels: the octree takes tens of times
      // longer on it than on the still torus.
      options.width = workload == 0 ? width : std::max(1, width / 2);
      options.height = workload == 0 ? height : std::max(1, height / 2);
      const int runs = repeats;
      options.spp = spp;
      options.first_hit = FirstHitMode::Trace;
      struct Contender {
        const char* name;
        AccelKind kind;
        bool linear;
      };
      for (const Contender& c : {Contender{"bvh, linear bounds", AccelKind::Bvh, true},
                                 Contender{"bvh, swept boxes", AccelKind::Bvh, false},
                                 Contender{"octree, swept boxes", AccelKind::Octree, true},
                                 Contender{"bsp, swept boxes", AccelKind::Bsp, true}}) {
        AccelBuildOptions build;
        build.bvh_linear_bounds = c.linear;
        renderer.setAccelBuildOptions(build);
        options.accel = c.kind;
        const Run held = timeRender(renderer, still, options, runs);
        const Run run = timeRender(renderer, moving, options, runs);
        std::printf("%-34s %12.3f %13.2fx %10.3f %10.3f\n", c.name, run.samples / run.traceSeconds() / 1e6,
                    run.traceSeconds() / held.traceSeconds(), run.build_seconds, held.build_seconds);
      }
      renderer.setAccelBuildOptions({});
    }
    std::printf("\nN = %d. Ms/s: million primary samples per second of render time (of tracing alone, its\n"
                "acceleration structure's build taken out, for the moving primitives; their builds are\n"
                "in the last two columns, moving and still).\n", spp);
  } catch (const std::exception& e) {
    std::cerr << "prism-bench distributed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace prism::bench
