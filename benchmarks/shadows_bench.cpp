#include "shadows_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "bench_data.h"
#include "bench_options.h"
#include "bench_plugins.h"
#include "device/context.h"
#include "device/device_list.h"
#include "mesh/mesh_loader.h"
#include "render/gpu_scene.h"
#include "render/light_buffer.h"
#include "render/renderer.h"
#include "scene/mesh_objects.h"
#include "scene_format/scene_loader.h"

namespace prism::bench {
namespace {

const char* kUsage =
    "usage: prism-bench shadows [--device D] [--size WxH] [--repeat N] [--data DIR] [--no-large]\n"
    "\n"
    "Renders scenes of 4 to about a million primitives (scenes/whitted.json, spheres\n"
    "on a floor, the teapot's triangles, the Stanford bunny at 69k and 1.1M\n"
    "triangles), with two point lights, with --shadows accel (the structure auto\n"
    "picks: brute force up to 4 primitives, else the BVH) and --shadows lightbuffer, at\n"
    "--size (default 320x240), and reports the shade kernel's device time (it traces\n"
    "the point lights' feelers) as the median of --repeat renders (default 3), the\n"
    "ratio accel / lightbuffer (above 1: the light buffer is faster), the light\n"
    "buffer's resolution, mean candidates per feeler and build time, whether the\n"
    "images agree, and what auto chose. --no-large leaves out the 1.1M bunny.\n";

struct Case {
  std::string name;
  Scene scene;
};

const char* kLights = R"("lights": [{"position": [4, 9, 6], "intensity": 0.7}, {"position": [-6, 5, 2], "intensity": 0.5}])";

Scene spheres(int per_side) {
  std::ostringstream json;
  json << R"({"camera": {"position": [0, 6, 12], "look_at": [0, 0, 0], "fov": 50}, )" << kLights
       << R"(, "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]})";
  for (int i = 0; i < per_side; ++i)
    for (int j = 0; j < per_side; ++j)
      json << R"(, {"type": "sphere", "center": [)" << -4 + 8.0 * (i + 0.5) / per_side << ", "
           << 2.0 / per_side << ", " << -4 + 8.0 * (j + 0.5) / per_side << R"(], "radius": )" << 3.0 / per_side << "}";
  json << "]}";
  return parseScene(json.str(), "spheres");
}

Scene teapot(double tolerance) {
  std::ostringstream json;
  json << R"({"camera": {"position": [0, 4, 9], "look_at": [0, 1.2, 0], "fov": 45}, )" << kLights
       << R"(, "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]},
         {"type": "patches", "file": ")" PRISM_SOURCE_DIR R"(/tests/data/patches/teapot.bpt", "tolerance": )"
       << tolerance << R"(, "transform": {"rotate": {"axis": [1, 0, 0], "angle": -90}}}]})";
  return parseScene(json.str(), "teapot");
}

Scene meshScene(const std::string& path) {
  Scene scene = sceneForMesh(loadMeshFile(path, benchPlugins()));
  // Two point lights above, in front and to the side, instead of the headlight
  // (whose feelers all run back along the camera rays).
  const Vec3 c = scene.camera.look_at, e = scene.camera.position;
  const double r = length(e - c);
  scene.lights.clear();
  for (const Vec3& offset : {Vec3{0.4, 0.9, 0.6}, Vec3{-0.6, 0.5, 0.2}}) {
    Light l;
    l.position = c + offset * r;
    l.intensity = 0.6;
    scene.lights.push_back(l);
  }
  return scene;
}

struct Timing {
  double shade = 0;  // median device seconds of the shade kernel
  RenderResult result;
};

Timing timeRender(Renderer& renderer, const Scene& scene, RenderOptions options, int repeats) {
  options.profile = true;
  std::vector<double> shade;
  Timing out;
  renderer.render(scene, options);  // builds the kernels, untimed
  for (int i = 0; i < repeats; ++i) {
    out.result = renderer.render(scene, options);
    for (const KernelTime& k : out.result.stats.kernels)
      if (k.name == "shade") shade.push_back(k.seconds);
  }
  std::sort(shade.begin(), shade.end());
  out.shade = shade.empty() ? 0 : shade[shade.size() / 2];
  return out;
}

}  // namespace

int shadowsMain(const std::vector<std::string>& args) {
  std::string device_name, data_dir;
  int width = 320, height = 240, repeats = 3;
  bool large = true;
  const int status = parseBenchOptions(args, "shadows", kUsage, [&](const std::string& a, const OptionValue& value) {
    if (a == "--device") {
      device_name = value();
    } else if (a == "--size") {
      parseSize(a, value(), &width, &height);
    } else if (a == "--repeat") {
      repeats = std::max(1, std::stoi(value()));
    } else if (a == "--data") {
      data_dir = value();
    } else if (a == "--no-large") {
      large = false;
    } else {
      throw std::invalid_argument("unknown option '" + a + "'");
    }
  });
  if (status >= 0) return status;
  try {
    std::vector<Case> cases = {{"whitted", loadSceneFile(PRISM_SOURCE_DIR "/scenes/whitted.json")},
                               {"spheres 4", spheres(2)},     {"spheres 64", spheres(8)},
                               {"spheres 1k", spheres(32)},   {"teapot 3.5k", teapot(0.033)},
                               {"teapot 14k", teapot(0.0083)}};
    for (const char* mesh : {"bunny/bun_zipper.ply", "bunny/bunny_loop2_1.1M.ply"}) {
      if (!large && std::string(mesh).find("1.1M") != std::string::npos) continue;
      try {
        cases.push_back({std::string("bunny ") + (std::string(mesh).find("1.1M") != std::string::npos ? "1.1M" : "69k"),
                         meshScene(findBenchMesh(mesh, data_dir))});
      } catch (const std::exception& e) {
        std::printf("(skipped %s: %s)\n", mesh, e.what());
      }
    }
    Context context(selectDevice(device_name), true);
    Renderer renderer(context);
    std::printf("device: %s\nimage: %dx%d, 1 spp, two point lights; shade kernel time, median of %d renders\n\n",
                context.device().name.c_str(), width, height, repeats);
    std::printf("%-12s %9s %6s %5s %11s %9s %10s %10s %9s %8s %12s\n", "scene", "prims", "accel", "res", "candidates",
                "build s", "accel ms", "lbuf ms", "speed-up", "agree", "auto");
    for (Case& c : cases) {
      RenderOptions options = RenderOptions::fromScene(c.scene);
      options.width = width, options.height = height, options.spp = 1;
      options.accel = AccelKind::Auto;  // as a render chooses: brute force up to 4 primitives
      const GpuScene gpu = flattenScene(c.scene, options);
      const auto start = std::chrono::steady_clock::now();
      const LightBuffer lb = buildLightBuffer(gpu.objects, gpu.lights, lightBufferResolution(gpu.primitive_count, gpu.lights.size()));
      const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      options.shadows = ShadowMode::Accel;
      const Timing a = timeRender(renderer, c.scene, options, repeats);
      options.shadows = ShadowMode::LightBuffer;
      const Timing b = timeRender(renderer, c.scene, options, repeats);
      options.shadows = ShadowMode::Auto;
      options.profile = false;
      const ShadowMode chosen = renderer.render(c.scene, options).stats.shadows;
      double worst = 0;
      for (std::size_t i = 0; i < a.result.rgba.size(); ++i)
        worst = std::max(worst, std::fabs(double(a.result.rgba[i]) - b.result.rgba[i]));
      std::printf("%-12s %9zu %6s %5d %11.1f %9.3f %10.2f %10.2f %9.2f %8s %12s\n", c.name.c_str(), gpu.primitive_count,
                  accelName(a.result.stats.accel), lb.resolution, lb.mean_candidates, build, a.shade * 1e3, b.shade * 1e3,
                  b.shade > 0 ? a.shade / b.shade : 0.0, worst <= 1e-6 ? "yes" : "NO", shadowModeName(chosen));
    }
    std::printf("\n(candidates: the mean length of the list a feeler tests, each cell counted as often as it\n"
                "holds primitives; speed-up: accel ms / lbuf ms; agree: every channel within 1e-6)\n");
  } catch (const std::exception& e) {
    std::cerr << "prism-bench shadows: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace prism::bench
