#include "polygon_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>
#include <sstream>

#include "bench_options.h"
#include "device/context.h"
#include "device/device_list.h"
#include "render/gpu_scene.h"
#include "render/ray_queries.h"
#include "scene_format/scene_loader.h"

namespace prism::bench {
namespace {

const char* kUsage =
    "usage: prism-bench polygons [--device D] [--sides N,...] [--rays N] [--repeat N]\n"
    "\n"
    "Traces the same rays (straight down onto a 12 x 12 field of polygons, a\n"
    "third of them missing) through the same BVH with each point-in-polygon test:\n"
    "crossing (Jordan curve), radial (angle sum) and, on convex polygons,\n"
    "left-right. Fields of regular (convex) polygons and of stars (non-convex)\n"
    "of each --sides count (default 4,16,64); --rays rays (default 262144);\n"
    "times are the median of --repeat runs (default 3), the tests taking turns,\n"
    "kernel time only. Speed is given as Mrays/s and as a ratio to crossing.\n";

// A field of n-gons in the plane z = 0: regular ones, or stars whose inner
// vertices sit at half the radius.
Scene polygonField(int sides, bool star) {
  std::ostringstream json;
  json.precision(17);
  json << R"({"objects": [)";
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      json << (i || j ? ", " : "") << R"({"type": "polygon", "vertices": [)";
      for (int k = 0; k < sides; ++k) {
        const double a = 2 * M_PI * k / sides, r = star && k % 2 ? 0.5 : 1.0;
        json << (k ? ", [" : "[") << 2.2 * i + r * std::cos(a) << ", " << 2.2 * j + r * std::sin(a) << ", 0]";
      }
      json << "]}";
    }
  json << "]}";
  return parseScene(json.str(), star ? "stars" : "regular");
}

std::vector<RayGpu> downwardRays(std::size_t count) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u(-1.1f, 2.2f * 11 + 1.1f);
  std::vector<RayGpu> rays(count);
  for (RayGpu& r : rays) {
    r.ox = u(rng), r.oy = u(rng), r.oz = 1;
    r.dz = -1;
    r.tmax = INFINITY;
    r.kind = RAY_KIND_PRIMARY;
  }
  return rays;
}

}  // namespace

int polygonMain(const std::vector<std::string>& args) {
  std::string device_name;
  std::vector<int> sides = {4, 16, 64};
  std::size_t ray_count = 1 << 18;
  int repeats = 3;
  const int status = parseBenchOptions(args, "polygons", kUsage, [&](const std::string& a, const OptionValue& value) {
    if (a == "--device") {
      device_name = value();
    } else if (a == "--sides") {
      sides.clear();
      std::stringstream ss(value());
      for (std::string s; std::getline(ss, s, ',');) sides.push_back(std::stoi(s));
      for (int n : sides)
        if (n < 3 || n > 4096) throw std::invalid_argument("--sides: each count must be in 3..4096");
    } else if (a == "--rays") {
      ray_count = std::stoul(value());
    } else if (a == "--repeat") {
      repeats = std::max(1, std::stoi(value()));
    } else {
      throw std::invalid_argument("unknown option '" + a + "'");
    }
  });
  if (status >= 0) return status;
  try {
    Context context(selectDevice(device_name), true);
    std::printf("device: %s\nrays: %zu straight down onto 144 polygons; median of %d runs, the tests taking turns\n\n",
                context.device().name.c_str(), ray_count, repeats);
    std::printf("%-8s %6s %-11s %9s %11s %8s\n", "field", "sides", "test", "Mrays/s", "x crossing", "agree%");
    const std::vector<RayGpu> rays = downwardRays(ray_count);
    for (int n : sides)
      for (bool star : {false, true}) {
        if (star && n % 2) continue;  // a star alternates outer and inner vertices
        const Scene scene = polygonField(n, star);
        std::vector<InsideTest> tests = {InsideTest::Crossing, InsideTest::Radial};
        if (!star) tests.push_back(InsideTest::LeftRight);
        std::vector<std::unique_ptr<RayQueryEngine>> engines;
        for (InsideTest t : tests) {
          RenderOptions options = RenderOptions::fromScene(scene);
          options.inside_test = t;
          engines.push_back(std::make_unique<RayQueryEngine>(context, SceneGeometry(flattenScene(scene, options)), AccelKind::Bvh));
          engines.back()->intersect(rays);  // compiles and warms up, untimed
        }
        std::vector<std::vector<double>> times(tests.size());
        std::vector<std::vector<HitGpu>> hits(tests.size());
        for (int rep = 0; rep < repeats; ++rep)
          for (std::size_t k = 0; k < tests.size(); ++k) {
            double seconds = 0;
            hits[k] = engines[k]->intersect(rays, &seconds);
            times[k].push_back(seconds);
          }
        std::vector<double> mrays;
        for (auto& t : times) {
          std::sort(t.begin(), t.end());
          mrays.push_back(ray_count / t[t.size() / 2] * 1e-6);
        }
        for (std::size_t k = 0; k < tests.size(); ++k) {
          std::size_t same = 0;
          for (std::size_t r = 0; r < rays.size(); ++r) same += hits[k][r].prim == hits[0][r].prim;
          std::printf("%-8s %6d %-11s %9.2f %11.2f %8.3f\n", star ? "stars" : "regular", n, insideTestName(tests[k]),
                      mrays[k], mrays[k] / mrays[0], 100.0 * same / rays.size());
        }
      }
  } catch (const std::exception& e) {
    std::cerr << "prism-bench polygons: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace prism::bench
