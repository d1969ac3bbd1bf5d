// The light buffer (render/light_buffer.h): conservative by construction —
// every primitive a feeler could meet is in the list of the cell its direction
// falls in — and the same shadows as the acceleration structure in whole
// renders, opaque and semitransparent, lights inside boxes and beside planes;
// auto's choice and the refusals.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <set>
#include <string>

#include "render/gpu_scene.h"
#include "render/light_buffer.h"
#include "render/renderer.h"
#include "scene_format/scene_loader.h"
#include "support/scene_errors.h"
#include "support/shared_context.h"
#include "support/test_data.h"

using namespace prism;
using namespace prism::test;

namespace {

// kernels/shading/light_buffer.h's light_buffer_cell, in float as the kernel computes it.
int kernelCell(float wx, float wy, float wz, int res, const float* windows) {
  const float ax = std::fabs(wx), ay = std::fabs(wy), az = std::fabs(wz);
  int face;
  float m, s, t;
  if (ax >= ay && ax >= az) {
    face = wx > 0 ? 0 : 1, m = ax, s = wy, t = wz;
  } else if (ay >= az) {
    face = wy > 0 ? 2 : 3, m = ay, s = wx, t = wz;
  } else {
    face = wz > 0 ? 4 : 5, m = az, s = wx, t = wy;
  }
  const float* w = windows + 4 * face;
  const int i = std::clamp(static_cast<int>(std::floor((s / m - w[0]) * w[1])), 0, res - 1);
  const int j = std::clamp(static_cast<int>(std::floor((t / m - w[2]) * w[3])), 0, res - 1);
  return (face * res + j) * res + i;
}

std::string lightsScene(const std::string& objects, const std::string& lights, const std::string& materials = "") {
  return R"({
    "camera": {"position": [0, 2.5, 7], "look_at": [0, 0.6, 0], "fov": 45},
    "film": {"width": 80, "height": 60},
    "render": {"max_depth": 3, "background": [0.2, 0.3, 0.45]},
    "materials": {"clay": {"diffuse": [0.8, 0.7, 0.6]},
                  "glass": {"diffuse": 0.1, "transmit": 0.6, "ior": 1.0},
                  "tint": {"diffuse": 0.3, "transmit": 0.3, "ior": 1.0})" +
         materials + R"(},
    "lights": )" + lights + R"(,
    "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "clay"}, )" +
         objects + "]}";
}

RenderResult renderWith(const Scene& scene, ShadowMode shadows) {
  RenderOptions options = RenderOptions::fromScene(scene);
  options.shadows = shadows;
  return sharedRenderer().render(scene, options);
}

}  // namespace

TEST_CASE("every primitive a feeler could meet is in its cell's list", "[render][lightbuffer]") {
  // Random boxes and spheres round a light, and random points inside each: the
  // direction from the light to the point is the direction of every feeler
  // from beyond it, so the cell it falls in must list the primitive.
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1, 1);
  std::string objects;
  for (int k = 0; k < 300; ++k) {
    const double x = 3 * u(rng), y = 3 * u(rng), z = 3 * u(rng), h = 0.05 + 0.3 * (u(rng) + 1);
    objects += (k ? ", " : "") + std::string(R"({"type": "box", "min": [)") + std::to_string(x - h) + ", " +
               std::to_string(y - h) + ", " + std::to_string(z - h) + "], \"max\": [" + std::to_string(x + h) + ", " +
               std::to_string(y + h) + ", " + std::to_string(z + h) + "]}";
  }
  const Scene scene = parseScene(R"({"lights": [{"position": [0.1, 0.2, -0.3]}, {"position": [2.5, 2.5, 2.5]}],
                                     "objects": [)" + objects + "]}", "boxes");
  const GpuScene gpu = flattenScene(scene, RenderOptions::fromScene(scene));
  for (int res : {1, 4, 16}) {
    const LightBuffer lb = buildLightBuffer(gpu.objects, gpu.lights, res);
    std::size_t checked = 0, missing = 0;
    for (std::size_t l = 0; l < gpu.lights.size(); ++l) {
      const float* L = gpu.lights[l].position;
      for (std::size_t prim = 0; prim < scene.objects.size(); ++prim) {
        const Object& o = scene.objects[prim];
        for (int k = 0; k < 200; ++k) {
          // Points inside the box, and on its faces, edges and corners.
          double p[3];
          for (int a = 0; a < 3; ++a) {
            const double lo = o.box_min[a], hi = o.box_max[a], r = u(rng);
            p[a] = k % 4 == 0 ? (r < 0 ? lo : hi) : lo + (hi - lo) * 0.5 * (r + 1);
          }
          const float w[3] = {float(p[0]) - L[0], float(p[1]) - L[1], float(p[2]) - L[2]};
          if (w[0] == 0 && w[1] == 0 && w[2] == 0) continue;
          const std::size_t entry = 1 + l * 6 * res * res + kernelCell(w[0], w[1], w[2], res, &lb.windows[24 * l]);
          const int first = lb.cells[2 * entry], count = lb.cells[2 * entry + 1];
          bool listed = false;
          for (int c = 0; c < count; ++c) listed = listed || lb.ids[first + c] == static_cast<int>(prim);
          ++checked;
          missing += !listed;
        }
      }
    }
    INFO("resolution " << res << ": " << checked << " directions checked, " << missing << " not listed");
    CHECK(missing == 0);
    // And it is a buffer, not a list of everything: at 16 cells a side a
    // feeler's cell lists far fewer than all 300.
    if (res == 16) CHECK(lb.mean_candidates < 60);
    INFO("mean candidates " << lb.mean_candidates);
  }
}

TEST_CASE("the light buffer casts the structure's shadows", "[render][lightbuffer]") {
  const std::string teapot = prism_test::testDataDir() + "/patches/teapot.bpt";
  const std::string scenes[] = {
      // Opaque and semitransparent spheres and boxes, two lights.
      lightsScene(R"({"type": "sphere", "center": [-1, 0.6, 0], "radius": 0.6, "material": "clay"},
                     {"type": "sphere", "center": [0.6, 0.5, 0.8], "radius": 0.5, "material": "glass"},
                     {"type": "box", "min": [0.2, 0, -1.2], "max": [1.2, 1.4, -0.4], "material": "tint"},
                     {"type": "box", "min": [-0.3, 1.5, -0.3], "max": [0.3, 1.7, 0.3], "material": "glass"})",
                  R"([{"position": [2, 5, 3], "intensity": 0.8}, {"position": [-3, 2, 1], "intensity": 0.5}])"),
      // A light inside a glass box and one level with the floor's plane.
      lightsScene(R"({"type": "box", "min": [-0.5, 0.5, -0.5], "max": [0.5, 1.5, 0.5], "material": "glass"},
                     {"type": "sphere", "center": [1.5, 0.4, 0.5], "radius": 0.4, "material": "clay"})",
                  R"([{"position": [0, 1, 0], "intensity": 0.8}, {"position": [-4, 0, 2], "intensity": 0.5}])"),
      // The teapot's triangles, semitransparent.
      lightsScene(R"({"type": "patches", "file": ")" + teapot + R"(", "material": "tint",
                     "transform": [{"scale": 0.5}, {"rotate": {"axis": [1, 0, 0], "angle": -90}}]})",
                  R"([{"position": [1, 4, 2], "intensity": 0.9}])"),
  };
  for (const std::string& json : scenes) {
    const Scene scene = parseScene(json, "shadows");
    const RenderResult a = renderWith(scene, ShadowMode::Accel), b = renderWith(scene, ShadowMode::LightBuffer);
    REQUIRE(a.stats.shadows == ShadowMode::Accel);
    REQUIRE(b.stats.shadows == ShadowMode::LightBuffer);
    std::size_t differ = 0;
    double worst = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
      const double d = std::fabs(double(a.rgba[i]) - b.rgba[i]);
      differ += d != 0;
      worst = std::max(worst, d);
    }
    // The same primitives attenuate each feeler; only the order in which
    // their k_trans multiply may differ (the last bit of a float).
    INFO(differ << " channels differ, by at most " << worst);
    CHECK(worst <= 1e-6);
  }
}

TEST_CASE("auto takes the light buffer where its cells list few candidates, and refusals", "[render][lightbuffer]") {
  // A few dozen spheres: short lists, and a BVH to beat.
  std::string spheres;
  for (int i = 0; i < 36; ++i)
    spheres += std::string(i ? ", " : "") + R"({"type": "sphere", "center": [)" + std::to_string(i % 6 - 2.5) +
               ", 0.3, " + std::to_string(i / 6 - 2.5) + R"(], "radius": 0.3})";
  const RenderResult dozens = renderWith(parseScene(lightsScene(spheres, R"([{"position": [2, 5, 3]}])"), "few"),
                                         ShadowMode::Auto);
  CHECK(dozens.stats.accel == AccelKind::Bvh);
  CHECK(dozens.stats.shadows == ShadowMode::LightBuffer);
  // A handful, traced by brute force: nothing for a light buffer to save.
  const std::string few = lightsScene(R"({"type": "sphere", "center": [0, 1, 0], "radius": 1})", R"([{"position": [2, 5, 3]}])");
  CHECK(renderWith(parseScene(few, "few"), ShadowMode::Auto).stats.shadows == ShadowMode::Accel);
  // The teapot's thousands of triangles: long lists, the BVH is faster.
  const std::string teapot = lightsScene(R"({"type": "patches", "file": ")" + prism_test::testDataDir() +
                                             R"(/patches/teapot.bpt", "tolerance": 0.01})",
                                         R"([{"position": [2, 5, 3]}])");
  CHECK(renderWith(parseScene(teapot, "teapot"), ShadowMode::Auto).stats.shadows == ShadowMode::Accel);
  // Area lights only: nothing for a light buffer to do.
  const std::string area = lightsScene(R"({"type": "sphere", "center": [0, 1, 0], "radius": 1})",
                                       R"([{"type": "sphere", "center": [2, 5, 3], "radius": 0.5}])");
  CHECK(renderWith(parseScene(area, "area"), ShadowMode::LightBuffer).stats.shadows == ShadowMode::Accel);
  // More point lights than the light buffer holds.
  std::string many = "[";
  for (int i = 0; i < 65; ++i) many += std::string(i ? ", " : "") + "{\"position\": [" + std::to_string(i) + ", 5, 3], \"intensity\": 0.01}";
  many += "]";
  const Scene crowd = parseScene(lightsScene(R"({"type": "sphere", "center": [0, 1, 0], "radius": 1})", many), "many");
  CHECK(renderWith(crowd, ShadowMode::Auto).stats.shadows == ShadowMode::Accel);
  CHECK_THROWS_WITH(renderWith(crowd, ShadowMode::LightBuffer),
                    Catch::Contains("at most 64 point lights") && Catch::Contains("the scene has 65"));
  CHECK_THAT(errorOf(R"({"render": {"shadows": "shadowmap"}})"),
             Catch::Contains("render.shadows: unknown shadow mode 'shadowmap' (expected auto, accel, lightbuffer)"));
}
